package tactus.haptics.transport;

import java.io.IOException;
import java.util.concurrent.locks.LockSupport;
import tactus.haptics.Board;

/**
 * A byte link to a Haply board: a serial port ({@link SerialTransport}), an in-process board emulator, or
 * a test double. Reads never block ({@link Board} does the waiting), except {@link #readWaiting}, which is for
 * a thread with nothing else to do until bytes arrive (the board emulator's firmware loop).
 */
public interface Transport {

    /**
     * Writes length bytes in one operation (a command must never be split across writes). Never waits without
     * a bound: when the other side stops taking bytes, the write fails with an IOException after a short time
     * (a quarter of a second for {@link SerialTransport}) instead of blocking or spinning.
     */
    void write(byte[] data, int offset, int length) throws IOException;

    /** Number of bytes that can be read now without waiting; throws if the link is gone. */
    int available() throws IOException;

    /** Reads up to length bytes that are available now, without waiting; returns the count read. */
    int read(byte[] buffer, int offset, int length) throws IOException;

    /**
     * Reads what has arrived; when nothing has, first waits for a byte, for a time the transport chooses (at
     * most about a tenth of a second), and returns 0 if none came. A thread that calls it sleeps instead of
     * polling, and wakes as soon as a byte arrives. The default polls {@link #available()} every 50 us for up
     * to a millisecond.
     */
    default int readWaiting(byte[] buffer, int offset, int length) throws IOException {
        long deadline = System.nanoTime() + 1_000_000L;
        while (available() <= 0 && System.nanoTime() - deadline < 0) {
            LockSupport.parkNanos(50_000);
        }
        return read(buffer, offset, length);
    }

    /** Closes the link; further calls throw IOException. Closing twice does nothing. */
    void close();

    /** A short human-readable name of the link (the port name, or "emulator"). */
    String describe();
}
