package tactus.internal.model;

/**
 * The one warning of a model stepped before {@code init()}: printed to standard error once per model, the first
 * time a stepping call finds the model not initialised. Without {@code init()} the model steps, but its stability is
 * never checked, so an unstable link shows only later, as a {@code DivergenceException}.
 *
 * <p>A stepping call costs one read of a boolean once the warning was printed or the model initialised; the text is
 * built only the one time it is printed.
 */
public final class InitNotice {
    private volatile boolean told;

    /**
     * Prints the warning if the model is not initialised and it was not printed yet for this model.
     *
     * @param initialized whether {@code init()} was called
     * @param call the stepping call, for example "computeStep()"
     * @return true if the warning was printed now
     */
    public boolean check(boolean initialized, String call) {
        if (initialized || told) {
            return false;
        }
        synchronized (this) {
            if (told) {
                return false;
            }
            told = true;
        }
        System.err.println(text(call));
        System.err.flush();
        return true;
    }

    /** The warning's text for a stepping call made before {@code init()}. */
    public static String text(String call) {
        return "Tactus: " + call + " on a model whose init() was never called: it steps, but its stability is not"
                + " checked, so an unstable link shows only later, as a DivergenceException. Call init() once the model"
                + " is built (at the end of setup()); it checks the model and names any link above its limit"
                + " (printed once per model)";
    }
}
