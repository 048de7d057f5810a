package tactus.internal.model;

/**
 * A library that the model compiles against but does not bundle (Processing core), and the check that turns its
 * absence into a message saying what to do instead of a bare {@link NoClassDefFoundError}.
 *
 * <p>The check loads one class of the library by name, once per JVM, and never touches the library's types itself,
 * so it works in a program that has only Tactus.jar and its bundled dependencies on the class path.
 */
public enum OptionalLibrary {
    /** Processing's core.jar: {@code PVector}, {@code PApplet}; needed only to draw and by the PVector calls. */
    PROCESSING_CORE("processing.core.PVector", "Processing core (core.jar, org.processing:core)");

    private final String probeClass;
    private final String label;
    /** 0 = not checked yet, 1 = present, -1 = absent (a race checks twice, harmlessly). */
    private volatile int state;

    OptionalLibrary(String probeClass, String label) {
        this.probeClass = probeClass;
        this.label = label;
    }

    /** Whether the library is on the class path of Tactus's class loader (checked once, then remembered). */
    public boolean isPresent() {
        int s = state;
        if (s == 0) {
            s = load() ? 1 : -1;
            state = s;
        }
        return s > 0;
    }

    private boolean load() {
        try {
            Class.forName(probeClass, false, OptionalLibrary.class.getClassLoader());
            return true;
        } catch (ClassNotFoundException | LinkageError e) {
            return false;
        }
    }

    /** The library's name as a message shows it, with where to get it. */
    public String label() {
        return label;
    }

    /**
     * Throws when the library is missing; does nothing when it is present.
     *
     * @param call the call that needs the library, as the user wrote it (for example "getMatPVector")
     * @param instead what to do without the library (a call to use instead, or how to add it)
     * @throws IllegalStateException naming the call, the library and the alternative
     */
    public void require(String call, String instead) {
        if (!isPresent()) {
            throw new IllegalStateException(missing(call, instead));
        }
    }

    /** The message of {@link #require} for a missing library. */
    public String missing(String call, String instead) {
        return "Tactus: " + call + " needs " + label + ", which is not on the class path (" + probeClass
                + " was not found); " + instead;
    }
}
