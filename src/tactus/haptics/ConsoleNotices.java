package tactus.haptics;

import java.util.EnumSet;

/**
 * Prints a board's failures to standard error where they happen, once per kind, so that they show even when
 * the sketch's thread is an executor task that swallows the exception. Never on the haptic path: only on a
 * failure or a watchdog trip.
 */
final class ConsoleNotices {
    /** The kinds of failure printed once each. */
    enum Kind {
        /** The link was lost while reading or writing. */
        LOST,
        /** A call on a board that was closed. */
        CLOSED_USE,
        /** The torque watchdog zeroed the motors. */
        WATCHDOG,
        /** close() could not get the board from another thread in time. */
        CLOSE_TIMEOUT
    }

    private final EnumSet<Kind> printed = EnumSet.noneOf(Kind.class);

    /** Prints the message to standard error if no message of this kind was printed before. */
    void once(Kind kind, String message) {
        synchronized (printed) {
            if (!printed.add(kind)) {
                return;
            }
        }
        System.err.println(message);
        System.err.flush();
    }
}
