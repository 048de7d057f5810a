package tactus.haptics.passivity;

/**
 * A play (backlash) between the handle's reading and where the avatar goes, one width per axis: the avatar's
 * position, the anchor, stays put while the reading moves within the width of it, and is dragged along, the width
 * behind, when the reading moves further. With the width just above one sensor count at the handle, a reading that
 * flickers by one count (an encoder at a boundary) no longer changes the model's force, so the force does not step
 * by the contact's stiffness times a count at each flicker; a real motion moves the anchor by as much as the
 * handle. The lag is the width, so the play is used only under the {@link EnergyBound}, which charges the energy
 * the lag could give back. Metres; one thread; no allocation.
 */
final class ContactPlay {
    private final double[] anchor = new double[3];
    private boolean anchored;

    /** Forgets the anchor: the next {@link #follow} starts it at the reading. */
    void reset() {
        anchored = false;
    }

    /**
     * Moves the anchor to within {@code widths[i]} (m, &gt;= 0) of {@code reading[i]} on each axis and writes it to
     * out.
     */
    void follow(double[] reading, double[] widths, double[] out) {
        if (!anchored) {
            System.arraycopy(reading, 0, anchor, 0, 3);
            anchored = true;
        }
        for (int i = 0; i < 3; i++) {
            double w = widths[i];
            if (reading[i] - anchor[i] > w) {
                anchor[i] = reading[i] - w;
            } else if (anchor[i] - reading[i] > w) {
                anchor[i] = reading[i] + w;
            }
        }
        System.arraycopy(anchor, 0, out, 0, 3);
    }
}
