package tactus;

import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicReference;
import java.util.concurrent.locks.LockSupport;

/**
 * Test helper (not a test class): a daemon thread that steps a realtime model as an audio thread would, in calls of
 * {@code batch} steps with a pause of {@code pauseNanos} after each, until stopped. It keeps the first exception a
 * stepping call threw (and counts them) instead of dying, and counts the calls that ran no step.
 */
final class OwnerLoop extends Thread {
    private final PhysicalModel pm;
    private final int batch;
    private final long pauseNanos;
    private final AtomicBoolean stop = new AtomicBoolean();
    final AtomicReference<Throwable> firstError = new AtomicReference<>();
    final AtomicLong errors = new AtomicLong();
    final AtomicLong calls = new AtomicLong();
    final AtomicLong zeroStepCalls = new AtomicLong();

    OwnerLoop(PhysicalModel pm, int batch, long pauseNanos, String name) {
        super(name);
        this.pm = pm;
        this.batch = batch;
        this.pauseNanos = pauseNanos;
        setDaemon(true);
    }

    /** Starts the loop and waits (at most 5 s) until it owns the model or has made a first stepping call. */
    OwnerLoop begin() throws InterruptedException {
        start();
        long until = System.nanoTime() + 5_000_000_000L;
        while (calls.get() == 0 && pm.getRealtimeOwner() != this && System.nanoTime() < until) {
            Thread.sleep(1);
        }
        return this;
    }

    @Override
    public void run() {
        while (!stop.get()) {
            try {
                long before = pm.getStepCount();
                pm.computeNSteps(batch);
                if (pm.getStepCount() == before) {
                    zeroStepCalls.incrementAndGet();
                }
            } catch (Throwable t) {
                firstError.compareAndSet(null, t);
                errors.incrementAndGet();
            }
            calls.incrementAndGet();
            if (pauseNanos > 0) {
                LockSupport.parkNanos(pauseNanos);
            }
        }
    }

    /** Waits until the loop has made {@code more} further calls (at most 10 s); false on time-out. */
    boolean awaitCalls(long more) throws InterruptedException {
        long target = calls.get() + more;
        long until = System.nanoTime() + 10_000_000_000L;
        while (calls.get() < target) {
            if (System.nanoTime() > until || !isAlive()) {
                return false;
            }
            Thread.sleep(1);
        }
        return true;
    }

    /** Stops the loop and waits for it (at most 10 s); false when it did not end (it hangs). */
    boolean halt() throws InterruptedException {
        stop.set(true);
        join(10_000);
        return !isAlive();
    }
}
