package tactus.audio;

import java.io.PrintStream;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.locks.LockSupport;

/**
 * Prints the {@link FaultNotice}s of every {@link PhyUGen} on standard error, from a daemon thread of its own
 * ("Tactus audio notices"), so that an audio thread hands a notice over (a lock-free queue and an unpark) and never
 * formats or prints. Started when the first PhyUGen is created; idle (parked) otherwise.
 */
final class FaultReporter {
    private static final ConcurrentLinkedQueue<FaultNotice> QUEUE = new ConcurrentLinkedQueue<>();
    private static final AtomicLong POSTED = new AtomicLong();
    private static volatile long printed;
    private static final Thread THREAD = start();

    private FaultReporter() {
    }

    private static Thread start() {
        Thread t = new Thread(FaultReporter::run, "Tactus audio notices");
        t.setDaemon(true);
        t.start();
        return t;
    }

    /** Makes sure the printing thread runs (it starts with the class); called outside the audio path. */
    static void ensureStarted() {
        AudioHelper.ensureStarted();   // the audio side's other helper thread, started here for the same reason
        if (!THREAD.isAlive()) {
            throw new IllegalStateException("FaultReporter: the notice thread is not running");
        }
    }

    /** Hands a notice to the printing thread; never blocks, never prints. */
    static void post(FaultNotice n) {
        QUEUE.offer(n);
        POSTED.incrementAndGet();
        LockSupport.unpark(THREAD);
    }

    private static void run() {
        while (true) {
            FaultNotice n = QUEUE.poll();
            if (n == null) {
                LockSupport.park(FaultReporter.class);
                continue;
            }
            try {
                PrintStream err = System.err;
                err.println(n.message());
                if (n.wantsStackTrace()) {
                    n.error.printStackTrace(err);
                }
            } catch (Throwable t) {
                // a notice that cannot be printed is dropped; the reporter keeps running
            } finally {
                printed++;
            }
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
