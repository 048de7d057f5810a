package tactus.audio;

import java.io.ByteArrayOutputStream;
import java.io.OutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;

/** Keeps a copy of what is printed on standard error while it runs (it still reaches the console). */
final class StderrCapture {
    private final PrintStream before;
    private final ByteArrayOutputStream copy = new ByteArrayOutputStream();
    private final java.util.Set<String> writers = java.util.concurrent.ConcurrentHashMap.newKeySet();

    private StderrCapture() {
        before = System.err;
        OutputStream tee = new OutputStream() {
            @Override
            public void write(int b) {
                writers.add(Thread.currentThread().getName());
                before.write(b);
                synchronized (copy) {
                    copy.write(b);
                }
            }

            @Override
            public void write(byte[] b, int off, int len) {
                writers.add(Thread.currentThread().getName());
                before.write(b, off, len);
                synchronized (copy) {
                    copy.write(b, off, len);
                }
            }
        };
        System.setErr(new PrintStream(tee, true, StandardCharsets.UTF_8));
    }

    /** Starts copying standard error. */
    static StderrCapture start() {
        return new StderrCapture();
    }

    /** @return what was printed on standard error since {@link #start()}. */
    String text() {
        synchronized (copy) {
            return copy.toString(StandardCharsets.UTF_8);
        }
    }

    /** @return the names of the threads that printed on standard error since {@link #start()}. */
    java.util.Set<String> writers() {
        return writers;
    }

    /** Puts standard error back. */
    void stop() {
        System.setErr(before);
    }
}
