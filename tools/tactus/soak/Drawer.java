package tactus.soak;

import java.util.concurrent.locks.LockSupport;

import tactus.ModelSnapshot;
import tactus.PhysicalModel;

/**
 * The sketch's {@code draw()} at 60 frames per second: reads the snapshot's positions and the model's energies,
 * divergence flag, step count and realtime flag, each call timed by the {@link CallWatch}. None of these calls is documented to
 * throw, so any exception here is an escape into {@code draw()}. It publishes the step count and the two flags it
 * read, for the monitor's stall check.
 */
final class Drawer implements Runnable {
    static final long FRAME_NANOS = 1_000_000_000L / 60;

    private final PhysicalModel m;
    private final SoakReport report;
    private final CallWatch watch;
    private volatile boolean running = true;
    /** The step count and divergence flag read at the last frame, and when (System.nanoTime). */
    volatile long steps = -1;
    volatile boolean diverged;
    /** Whether the model was in realtime stepping (a PhyUGen owns it) at the last frame. */
    volatile boolean realtime;
    volatile long readAt;
    /** A checksum of the positions read, so that the reads are not optimised away. */
    volatile double checksum;

    Drawer(PhysicalModel m, SoakReport report, CallWatch watch) {
        this.m = m;
        this.report = report;
        this.watch = watch;
    }

    void stop() {
        running = false;
    }

    @Override
    public void run() {
        long next = System.nanoTime();
        while (running) {
            frame();
            next += FRAME_NANOS;
            long wait = next - System.nanoTime();
            if (wait > 0) {
                LockSupport.parkNanos(wait);
            } else {
                next = System.nanoTime();
            }
        }
    }

    private void frame() {
        try {
            ModelSnapshot s = watch.call("draw: getSnapshot", m::getSnapshot);
            double sum = 0;
            int n = s.getNumberOfMats();
            for (int i = 0; i < n; i++) {
                sum += s.x(i) + s.y(i);
            }
            sum += watch.call("draw: getTotalEnergy", m::getTotalEnergy);
            sum += watch.call("draw: getKineticEnergy", m::getKineticEnergy);
            sum += watch.call("draw: getPotentialEnergy", m::getPotentialEnergy);
            boolean d = watch.call("draw: isDiverged", m::isDiverged);
            long st = watch.call("draw: getStepCount", m::getStepCount);
            boolean rt = watch.call("draw: isRealtimeStepping", m::isRealtimeStepping);
            checksum = sum;
            diverged = d;
            realtime = rt;
            steps = st;
            readAt = System.nanoTime();
            report.draws.incrementAndGet();
        } catch (Throwable t) {
            report.escape("draw thread", t);
        }
    }
}
