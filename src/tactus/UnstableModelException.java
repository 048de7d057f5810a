package tactus;

/**
 * Thrown under {@link StabilityPolicy#THROW} when a model, as built or as changed, is outside the
 * stable region of the explicit scheme. The message names the module, the parameter, its value and
 * the limit.
 */
public class UnstableModelException extends IllegalStateException {
    private static final long serialVersionUID = 1L;
    private final transient StabilityReport report;

    UnstableModelException(String message, StabilityReport report) {
        super(message);
        this.report = report;
    }

    /** {@return the analysis that found the model unstable} */
    public StabilityReport getReport() {
        return report;
    }
}
