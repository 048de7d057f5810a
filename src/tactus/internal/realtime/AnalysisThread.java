package tactus.internal.realtime;

import java.util.concurrent.locks.LockSupport;
import tactus.StabilityPolicy;
import tactus.internal.ModelCore;

/**
 * The stability analysis of a realtime-stepped model ({@link Ownership}): runs the analysis of changes posted under
 * WARN on its own daemon thread (once for a burst of
 * changes), so that the calls return as soon as they are queued. It waits for the changes to be applied, then takes
 * the model's lock like any editor (so it never holds the lock while it waits for the stepping thread), and
 * rests seven times as long as each analysis took (however many requests arrive meanwhile), so that it never
 * uses more than an eighth of a core (the audio thread needs the rest): a warning may come some tens of
 * milliseconds after the change on a big model.
 */
public final class AnalysisThread implements Runnable {
    /** How long the helper thread waits for work before it ends (a later change starts a new one). */
    private static final long IDLE_EXIT_NANOS = 5_000_000_000L;
    private final Ownership own;
    private final ModelCore core;
    private final java.util.concurrent.locks.Lock lock;
    private volatile boolean requested;
    private volatile Thread thread;

    public AnalysisThread(Ownership own, ModelCore core, java.util.concurrent.locks.Lock lock) {
        this.own = own;
        this.core = core;
        this.lock = lock;
    }

    /** Wakes the helper thread so that it sees the mode has ended. */
    public void wake() {
        Thread t = thread;
        if (t != null) {
            LockSupport.unpark(t);
        }
    }

    /**
     * Asks for an analysis. Never blocks and never allocates when the helper thread runs; an editor's request
     * starts it if it is not running. A request from the stepping thread itself never starts it: its changes are
     * then analysed with the next editor's.
     */
    public void request() {
        requested = true;
        Thread t = thread;
        if (t != null) {
            LockSupport.unpark(t);
        } else if (!own.isOwnerThread()) {
            start();
        }
    }

    private synchronized void start() {
        if (thread == null && !own.isClosed()) {
            Thread t = new Thread(this, "Tactus stability analysis");
            t.setDaemon(true);
            thread = t;
            t.start();
        }
    }

    @Override
    public void run() {
        long idleSince = System.nanoTime();
        while (!own.isClosed()) {
            if (!requested) {
                if (System.nanoTime() - idleSince > IDLE_EXIT_NANOS) {
                    synchronized (this) {
                        if (!requested) {
                            thread = null;
                            return;
                        }
                    }
                }
                LockSupport.parkNanos(this, IDLE_EXIT_NANOS / 4);
                continue;
            }
            requested = false;
            long t0 = System.nanoTime();
            own.awaitAppliedUnlocked(own.postedSeq()); // never hold the lock while the stepping thread is busy
            lock.lock();
            try {
                own.awaitAll();
                if (core.guard.policy() == StabilityPolicy.WARN) {
                    core.guard.check(null);
                }
            } catch (RuntimeException e) {
                // a model changed under the analysis (removed modules): the next request analyses again
            } finally {
                lock.unlock();
            }
            // at most an eighth of a core: changes arriving meanwhile are analysed together afterwards (a loop,
            // since each request unparks this thread)
            long until = System.nanoTime() + 7 * (System.nanoTime() - t0);
            for (long now = System.nanoTime(); now < until && !own.isClosed(); now = System.nanoTime()) {
                LockSupport.parkNanos(this, until - now);
            }
            idleSince = System.nanoTime();
        }
        thread = null;
    }
}
