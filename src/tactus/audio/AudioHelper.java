package tactus.audio;

import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.locks.LockSupport;

/**
 * The audio side's helper thread ("Tactus audio helper", a daemon at normal priority): an audio thread hands it a
 * job that may wait or take time (printing a fault notice, {@link FaultReporter}; asking Linux for real-time
 * scheduling, {@link AudioScheduling}; putting a model back in realtime stepping, {@link PhysicalModelStepper})
 * through a lock-free queue and an unpark, and never waits for it.
 * Started with the first PhyUGen, from the thread that creates it, so that neither this thread nor the threads it
 * starts inherit a real-time policy.
 */
final class AudioHelper {
    private static final ConcurrentLinkedQueue<Runnable> QUEUE = new ConcurrentLinkedQueue<>();
    private static final Thread THREAD = start();

    private AudioHelper() {
    }

    private static Thread start() {
        Thread t = new Thread(AudioHelper::run, "Tactus audio helper");
        t.setDaemon(true);
        t.start();
        return t;
    }

    /** Makes sure the helper runs (it starts with the class); called outside the audio path. */
    static void ensureStarted() {
        if (!THREAD.isAlive()) {
            throw new IllegalStateException("AudioHelper: the helper thread is not running");
        }
    }

    /** Hands a job over; never blocks (one queue node per call: for rare events, not per sample). */
    static void post(Runnable job) {
        QUEUE.offer(job);
        LockSupport.unpark(THREAD);
    }

    private static void run() {
        while (true) {
            Runnable job = QUEUE.poll();
            if (job == null) {
                LockSupport.park(AudioHelper.class);
                continue;
            }
            try {
                job.run();
            } catch (Throwable t) {
                // a job reports its own failures; the helper keeps running
            }
        }
    }
}
