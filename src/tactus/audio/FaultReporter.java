package tactus.audio;

import java.io.PrintStream;
import java.util.concurrent.atomic.AtomicLong;

/**
 * Prints the {@link FaultNotice}s of every {@link PhyUGen} on standard error, from the {@link AudioHelper} thread, so
 * that an audio thread hands a notice over (a lock-free queue and an unpark) and never formats or prints.
 */
final class FaultReporter {
    private static final AtomicLong POSTED = new AtomicLong();
    private static volatile long printed;

    private FaultReporter() {
    }

    /** Makes sure the printing thread runs; called outside the audio path (a PhyUGen's constructor). */
    static void ensureStarted() {
        AudioHelper.ensureStarted();
    }

    /** Hands a notice to the printing thread; never blocks, never prints. */
    static void post(FaultNotice n) {
        POSTED.incrementAndGet();
        AudioHelper.post(() -> print(n));
    }

    /** On the helper thread. */
    private static void print(FaultNotice n) {
        try {
            PrintStream err = System.err;
            err.println(n.message());
            if (n.wantsStackTrace()) {
                n.error.printStackTrace(err);
            }
        } catch (Throwable t) {
            // a notice that cannot be printed is dropped; the helper keeps running
        } finally {
            printed++;
        }
    }

    /**
     * Waits until every notice posted so far is printed (for tests).
     *
     * @return false if that took longer than {@code millis}
     */
    static boolean awaitPrinted(long millis) throws InterruptedException {
        long target = POSTED.get();
        long deadline = System.nanoTime() + millis * 1_000_000L;
        while (printed < target) {
            if (System.nanoTime() > deadline) {
                return false;
            }
            Thread.sleep(2);
        }
        return true;
    }
}
