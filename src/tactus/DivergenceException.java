package tactus;

/**
 * Raised when a running model diverges: a mass position became non-finite or ran beyond the divergence
 * limit. The model stops stepping at the step where it was detected, until
 * {@link PhysicalModel#clearDivergence()} is called.
 */
public class DivergenceException extends IllegalStateException {
    private static final long serialVersionUID = 1L;
    private final String massName;
    private final long step;
    /** The raw facts of the message, formatted by {@link #getMessage()} on the thread that reads it. */
    private final String massLabel;
    private final double x;
    private final double y;
    private final double z;
    /** The module most likely at fault, with its parameter and the fix, or null. */
    private final String suspect;
    /** The formatted message, made on first read (a race makes the same text twice, harmlessly). */
    private String message;

    /**
     * A divergence whose message is formatted only when it is read: the stepping thread (a PhyUGen's audio thread)
     * records the facts and formats no string.
     */
    DivergenceException(String massLabel, String massName, long step, double x, double y, double z, String suspect) {
        super((String) null);
        this.suspect = suspect;
        this.massName = massName;
        this.step = step;
        this.massLabel = massLabel;
        this.x = x;
        this.y = y;
        this.z = z;
    }

    /**
     * {@return "Mass3D \"name\" diverged at step N: position (x, y, z); most likely cause: ...; the model is
     *     frozen until clearDivergence()", formatted on the first call}
     */
    @Override
    public String getMessage() {
        String m = message;
        if (m == null) {
            m = massLabel + " \"" + massName + "\" diverged at step " + step + ": position (" + x + ", " + y + ", " + z
                    + "); " + (suspect != null ? "most likely cause: " + suspect + "; " : "")
                    + "the model is frozen until clearDivergence()";
            message = m;
        }
        return m;
    }

    /**
     * The module most likely at fault, as the stability analysis of the diverged model finds it: its type and name,
     * the parameter, its value and limit, and the fix; or what to look for when every module is within its limit.
     *
     * @return the text, or null if the analysis could not be made
     */
    public String getSuspect() {
        return suspect;
    }

    /** {@return the name of the first offending mass} */
    public String getMassName() {
        return massName;
    }

    /** {@return the step count at which the divergence was detected} */
    public long getStep() {
        return step;
    }
}
