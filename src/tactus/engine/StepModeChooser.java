package tactus.engine;

import java.util.function.LongSupplier;

/**
 * Chooses, batch by batch, between stepping a plan on one thread and on the {@link ParallelStepper}, so that
 * parallel stepping is never kept where it is slower: a loaded or oversubscribed machine can make every barrier
 * wait for a descheduled thread. It times one step in each mode (a probe), runs the rest of the batch in the
 * faster one (the parallel mode only if it was at least 10 % faster), and probes the other mode again every
 * {@value #REPROBE_STEPS} steps, since the load changes.
 * Both modes give the same results bit for bit, so the choice changes only the time. Allocates nothing.
 */
final class StepModeChooser {
    /** Steps run in the chosen mode between two probes of the other. */
    static final int REPROBE_STEPS = 4096;
    /**
     * Parallel stepping is chosen only where its probe took at most this share of one thread's: two nearly equal modes
     * (a memory-bound plan on two cores) are told apart by one-step probes no better than their noise, and a wrong
     * pick of the parallel mode costs more (a barrier per step) than a wrong pick of one thread.
     */
    static final double PARALLEL_MARGIN = 0.9;

    private final LongSupplier clock;
    private long serialNanos = -1;      // the last probe's time of one step on one thread (-1: not measured)
    private long parallelNanos = -1;    // the same on all threads
    private long sinceProbe;
    private long parallelSteps;
    private long serialSteps;

    StepModeChooser(LongSupplier nanoClock) {
        this.clock = nanoClock;
    }

    /** The clock the engine times its batches with (System.nanoTime, or a test's). */
    long now() {
        return clock.getAsLong();
    }

    /** True if the next run must be a one-step probe (a mode not measured yet, or measured too long ago). */
    boolean probing() {
        return serialNanos < 0 || parallelNanos < 0 || sinceProbe >= REPROBE_STEPS;
    }

    /** The mode of the next run: the one not measured (or not measured last) when probing, else the faster. */
    boolean parallelNext() {
        if (serialNanos < 0) {
            return false;
        }
        if (parallelNanos < 0) {
            return true;
        }
        boolean faster = parallelNanos < PARALLEL_MARGIN * serialNanos;
        return sinceProbe >= REPROBE_STEPS ? !faster : faster;
    }

    /** Records a run of {@code steps} steps in a mode that took {@code nanos}. */
    void record(boolean parallel, int steps, long nanos) {
        if (steps <= 0) {
            return;
        }
        if (parallel) {
            parallelSteps += steps;
        } else {
            serialSteps += steps;
        }
        if (probing()) {
            long perStep = nanos / steps;
            if (parallel) {
                parallelNanos = perStep;
            } else {
                serialNanos = perStep;
            }
            if (serialNanos >= 0 && parallelNanos >= 0) {
                sinceProbe = 0;
            }
        } else {
            sinceProbe += steps;
        }
    }

    /** Steps run on all threads so far. */
    long parallelSteps() {
        return parallelSteps;
    }

    /** Steps run on one thread so far (on a plan big enough for the parallel stepper). */
    long serialSteps() {
        return serialSteps;
    }
}
