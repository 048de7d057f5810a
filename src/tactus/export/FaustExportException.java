package tactus.export;

/**
 * Thrown when a model, or an option, cannot be exported to Faust: the message names the module (or the option)
 * and says why. The model is never changed by an export.
 */
public final class FaustExportException extends RuntimeException {
    private static final long serialVersionUID = 1L;

    private final String module;

    FaustExportException(String module, String why) {
        super("Faust export: " + module + ": " + why);
        this.module = module;
    }

    /** {@return the name of the module or option that cannot be exported} */
    public String getModule() {
        return module;
    }
}
