package tactus.io;

/**
 * A model file that cannot be read or written: malformed XML, an unknown module type, a missing or
 * bad attribute, a reference to a mass that does not exist, or an I/O failure. The message names the
 * file, the line and the element; a failed load leaves the model unchanged.
 */
public class ModelFileException extends IllegalArgumentException {
    private static final long serialVersionUID = 1L;
    private final int line;
    private final String element;

    /**
     * Creates an error about one element of a model file, with its line.
     *
     * @param source the file name (or another description of the input)
     * @param line the 1-based line of the offending element, or -1 when unknown
     * @param element the offending element's name, or null when none
     * @param message what is wrong
     * @param cause the underlying exception, or null
     */
    public ModelFileException(String source, int line, String element, String message, Throwable cause) {
        super(describe(source, line, element) + message, cause);
        this.line = line;
        this.element = element;
    }

    private static String describe(String source, int line, String element) {
        StringBuilder b = new StringBuilder(source == null ? "model file" : source);
        if (line > 0) {
            b.append(", line ").append(line);
        }
        if (element != null) {
            b.append(", element <").append(element).append('>');
        }
        return b.append(": ").toString();
    }

    /** {@return the 1-based line of the offending element, or -1 when unknown} */
    public int getLine() {
        return line;
    }

    /** {@return the name of the offending element, or null when none} */
    public String getElement() {
        return element;
    }
}
