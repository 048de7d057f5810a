package tactus.haptics;

/** The link to a Haply board failed (unplugged, closed, or an I/O error); the message says what to check. */
public class HaplyLinkException extends RuntimeException {
    private static final long serialVersionUID = 1L;

    /** Creates the exception with a message and its cause. */
    public HaplyLinkException(String message, Throwable cause) {
        super(message, cause);
    }

    /** Creates the exception with a message. */
    public HaplyLinkException(String message) {
        super(message);
    }
}
