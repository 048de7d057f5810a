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

    DivergenceException(String message, String massName, long step) {
        super(message);
        this.massName = massName;
        this.step = step;
    }

    /** @return the name of the first offending mass. */
    public String getMassName() {
        return massName;
    }

    /** @return the step count at which the divergence was detected. */
    public long getStep() {
        return step;
    }
}
