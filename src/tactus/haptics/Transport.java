package tactus.haptics;

import java.io.IOException;

/**
 * A byte link to a Haply board: a serial port ({@link SerialTransport}), an in-process board emulator, or
 * a test double. Reads never block; {@link Board} does the waiting.
 */
public interface Transport {

    /** Writes length bytes in one operation (a command must never be split across writes). */
    void write(byte[] data, int offset, int length) throws IOException;

    /** Number of bytes that can be read now without waiting; throws if the link is gone. */
    int available() throws IOException;

    /** Reads up to length bytes that are available now, without waiting; returns the count read. */
    int read(byte[] buffer, int offset, int length) throws IOException;

    /** Closes the link; further calls throw IOException. Closing twice does nothing. */
    void close();

    /** A short human-readable name of the link (the port name, or "emulator"). */
    String describe();
}
