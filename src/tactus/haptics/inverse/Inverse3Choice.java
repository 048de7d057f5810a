package tactus.haptics.inverse;

/**
 * Which of the Inverse3s an Inverse Service lists a connection drives: the one with a given {@code device_id},
 * the n-th listed (0: the first), or the first whose configuration says it is {@code "left"} or {@code "right"}
 * handed. Immutable.
 */
public final class Inverse3Choice {
    /** The first Inverse3 the service lists. */
    public static final Inverse3Choice FIRST = new Inverse3Choice(null, 0, null);

    private final String id;
    private final int index;
    private final String handedness;

    private Inverse3Choice(String id, int index, String handedness) {
        this.id = id;
        this.index = index;
        this.handedness = handedness;
    }

    /** The Inverse3 with this {@code device_id} (as the service and the Haply Hub name it, e.g. "049D"). */
    public static Inverse3Choice byId(String deviceId) {
        if (deviceId == null || deviceId.isEmpty()) {
            throw new IllegalArgumentException("Inverse3Choice.byId: need a device id such as \"049D\", got "
                    + (deviceId == null ? "null" : "\"\""));
        }
        return new Inverse3Choice(deviceId, -1, null);
    }

    /** The Inverse3 at this place (>= 0) in the service's list, in the order the service lists them. */
    public static Inverse3Choice byIndex(int index) {
        if (index < 0) {
            throw new IllegalArgumentException("Inverse3Choice.byIndex: need an index >= 0, got " + index);
        }
        return new Inverse3Choice(null, index, null);
    }

    /** The first Inverse3 whose configuration gives this handedness, "left" or "right". */
    public static Inverse3Choice byHandedness(String handedness) {
        if (!"left".equals(handedness) && !"right".equals(handedness)) {
            throw new IllegalArgumentException("Inverse3Choice.byHandedness: need \"left\" or \"right\", got " + handedness);
        }
        return new Inverse3Choice(null, -1, handedness);
    }

    /** The id asked for, or null when chosen by index or handedness. */
    public String id() {
        return id;
    }

    /** The index asked for, or -1 when chosen by id or handedness. */
    public int index() {
        return index;
    }

    /** The handedness asked for, or null when chosen by id or index. */
    public String handedness() {
        return handedness;
    }

    /**
     * The index, in these parallel lists of one snapshot, of the device this choice names, or -1 if none.
     */
    int pick(String[] ids, String[] handednesses, int count) {
        for (int i = 0; i < count; i++) {
            if (id != null ? id.equals(ids[i]) : handedness != null ? handedness.equals(handednesses[i]) : i == index) {
                return i;
            }
        }
        return -1;
    }

    @Override
    public String toString() {
        return id != null ? "the Inverse3 " + id : handedness != null ? "the " + handedness + "-handed Inverse3"
                : index == 0 ? "the first Inverse3" : "Inverse3 number " + index + " (from 0)";
    }
}
