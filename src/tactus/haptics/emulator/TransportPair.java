package tactus.haptics.emulator;

import java.io.IOException;
import tactus.haptics.transport.Transport;

/**
 * Two in-process {@link Transport} ends joined back to back, like a null-modem cable: what one writes the
 * other reads. Serve a {@link BoardEmulator} on {@link #boardEnd()} and open a {@code Board} on
 * {@link #hostEnd()} to run the emulator on its own thread, with the firmware's timing, without a
 * pseudo-terminal. Closing either end closes the pair.
 */
public final class TransportPair {
    private final ByteRing toBoard = new ByteRing();
    private final ByteRing toHost = new ByteRing();
    private volatile boolean closed;
    private final Transport host = new End(toBoard, toHost, "pair host end");
    private final Transport board = new End(toHost, toBoard, "pair board end");

    /** The host's end (open a Board on it). */
    public Transport hostEnd() {
        return host;
    }

    /** The board's end (serve the emulator on it). */
    public Transport boardEnd() {
        return board;
    }

    private final class End implements Transport {
        private final ByteRing out;
        private final ByteRing in;
        private final String name;

        End(ByteRing out, ByteRing in, String name) {
            this.out = out;
            this.in = in;
            this.name = name;
        }

        @Override
        public void write(byte[] data, int offset, int length) throws IOException {
            check();
            out.put(data, offset, length);
        }

        @Override
        public int available() throws IOException {
            check();
            return in.size();
        }

        @Override
        public int read(byte[] buffer, int offset, int length) throws IOException {
            check();
            return in.take(buffer, offset, length);
        }

        /** Waits up to 10 ms for the first byte (woken as soon as the other end writes). */
        @Override
        public int readWaiting(byte[] buffer, int offset, int length) throws IOException {
            check();
            try {
                return in.takeWaiting(buffer, offset, length, 10_000_000L);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return 0;
            }
        }

        private void check() throws IOException {
            if (closed) {
                throw new IOException(name + ": the other end was closed (cable pulled)");
            }
        }

        @Override
        public void close() {
            closed = true;
        }

        @Override
        public String describe() {
            return name;
        }
    }
}
