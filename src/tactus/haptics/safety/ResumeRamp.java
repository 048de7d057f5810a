package tactus.haptics.safety;

/**
 * The factor (0 to 1) by which a device's force is scaled while it comes back after a guard zeroed it (a paused
 * JVM, a reconnection): it grows from 0 by the time that passed between one force write and the next, divided by
 * the ramp's duration, and by at most one step per write. Not API: public for {@link tactus.haptics.Board} and
 * {@code tactus.haptics.inverse.Inverse3Device}.
 *
 * <p>Counting the time between writes, rather than since the ramp began, keeps the ramp as long in the hand
 * whatever the writer does: a writer that catches up after a pause with a burst of writes (a fixed-rate executor
 * does) moves the force by the little time between them, and a pause in the middle of a ramp adds one step at
 * most. One writer at a time calls {@link #factor}; the caller holds whatever lock guards the device.
 */
public final class ResumeRamp {
    private final double durationNanos;
    private final long longestGapNanos;
    private boolean running;
    private double last = 1;
    private long lastNanos;

    /**
     * A ramp over durationNanos (above 0) whose factor grows by at most maxStep (0 to 1] from one write to the
     * next.
     */
    public ResumeRamp(long durationNanos, double maxStep) {
        if (durationNanos <= 0 || !(maxStep > 0 && maxStep <= 1)) {
            throw new IllegalArgumentException("a resume ramp needs a duration above 0 ns and a step in (0, 1]; got "
                    + durationNanos + " ns and " + maxStep);
        }
        this.durationNanos = durationNanos;
        this.longestGapNanos = (long) Math.ceil(maxStep * durationNanos);
    }

    /** Starts (or restarts) the ramp from a factor of 0 at time nowNanos ({@link System#nanoTime()}). */
    public void start(long nowNanos) {
        running = true;
        last = 0;
        lastNanos = nowNanos;
    }

    /** True from {@link #start} until the factor reaches 1. */
    public boolean isRunning() {
        return running;
    }

    /** The factor of the last write (1 when no ramp runs). */
    public double last() {
        return last;
    }

    /**
     * The factor for a write at nowNanos: 1 when no ramp runs; otherwise the last factor plus the time since the
     * last write (at most one step's worth) over the duration; the ramp ends when it reaches 1.
     */
    public double factor(long nowNanos) {
        if (!running) {
            return 1;
        }
        long gap = Math.max(0, Math.min(nowNanos - lastNanos, longestGapNanos));
        lastNanos = nowNanos;
        double f = last + gap / durationNanos;
        if (f >= 1) {
            running = false;
            f = 1;
        }
        last = f;
        return f;
    }
}
