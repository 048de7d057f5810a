package tactus.engine;

import java.util.ArrayList;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;
import java.util.concurrent.locks.LockSupport;

/**
 * Steps a plan on several threads, with results bit-identical to single-threaded stepping.
 *
 * <p>The plan's kernels run in their usual order, as a sequence of phases separated by a barrier. A
 * {@link RangeKernel} stage is a parallel phase: its index range is cut into one contiguous chunk per
 * thread, and since every index of a stage touches only its own memory, each element is computed by
 * exactly the same operations in the same order as on one thread. Any other kernel (irregular links,
 * contacts) is a serial phase run by the calling thread while the others wait, so no force sum can race.
 * Between batches of steps the worker threads park; during a batch they spin at the barriers, so a batch
 * should hold many steps. Stepping allocates nothing.
 *
 * <p>Batches: the caller writes a batch's parameters (phases, step count) and then publishes a new
 * generation number; each worker copies the parameters into locals as soon as it sees the new generation,
 * before its first barrier, and reads nothing shared afterwards except the generation at which a batch
 * stops ({@link #stopGeneration}), which the caller can only set for a generation the worker has joined. So
 * a worker that is slow to leave a batch never sees the next batch's parameters.
 *
 * <p>An exception thrown by a kernel on any thread is recorded, the step is finished by every thread (the
 * barriers stay in step), the batch stops there and {@link #run} rethrows it on the calling thread; the
 * stepper stays usable. {@link #close()} stops the worker threads and drops every reference to the plan.
 * The workers refer only to this object, never to the {@link Engine}, so an unreachable engine can be
 * cleaned up (the engine registers {@link #close()} with a {@link java.lang.ref.Cleaner}).
 */
final class ParallelStepper implements AutoCloseable {
    /** Decides after each step whether the batch must stop early (the divergence guard). */
    interface StepHook {
        /** @return true to stop after this step */
        boolean afterStep();
    }

    private static final Kernel[] NO_KERNELS = new Kernel[0];
    /** Barrier spins before a waiting thread yields its core (keeps oversubscribed machines moving). */
    private static final int SPINS_BEFORE_YIELD = 1 << 12;

    private final int parties;
    private final Thread[] workers;
    private final boolean[] localSense;
    private final AtomicInteger arrived = new AtomicInteger();
    private volatile boolean sense;
    /** Incremented by the caller to start a batch or to stop the workers; workers wait for it to change. */
    private volatile int generation;
    /** The generation whose batch ends after the step in progress; written by thread 0 before a barrier. */
    private volatile int stopGeneration;
    private volatile boolean closed;
    private final AtomicReference<Throwable> failure = new AtomicReference<>();

    private StepPlan cachedPlan;
    private int cachedVersion;
    private Kernel[] phaseKernel = NO_KERNELS;
    private int[] phaseStage = new int[0];
    private Kernel[][] serialGroup = new Kernel[0][];

    /** Batch parameters: written by the caller before it publishes a generation. */
    private int batchSteps;
    private StepHook hook;
    private int done;

    ParallelStepper(int threads) {
        if (threads < 2) {
            throw new IllegalArgumentException("a parallel stepper needs at least 2 threads, got " + threads);
        }
        parties = threads;
        localSense = new boolean[threads * 16];
        workers = new Thread[threads - 1];
        for (int t = 1; t < threads; t++) {
            final int me = t;
            Thread w = new Thread(() -> workerLoop(me), "tactus-step-" + t);
            w.setDaemon(true);
            workers[t - 1] = w;
            w.start();
        }
    }

    int threads() {
        return parties;
    }

    /** @return the worker threads (the calling thread is the remaining party), for tests. */
    Thread[] workers() {
        return workers.clone();
    }

    /**
     * Stops the worker threads, waits until they have ended and drops the cached plan. Idempotent; must not
     * be called while a batch is running. After closing, {@link #run} throws {@link IllegalStateException}.
     */
    @Override
    public void close() {
        if (closed) {
            return;
        }
        closed = true;
        generation++;
        for (Thread w : workers) {
            LockSupport.unpark(w);
        }
        boolean interrupted = false;
        for (Thread w : workers) {
            while (w.isAlive() && w != Thread.currentThread()) {
                try {
                    w.join();
                } catch (InterruptedException e) {
                    interrupted = true;
                }
            }
        }
        if (interrupted) {
            Thread.currentThread().interrupt();
        }
        cachedPlan = null;
        phaseKernel = NO_KERNELS;
        phaseStage = new int[0];
        serialGroup = new Kernel[0][];
        hook = null;
    }

    /** @return true once {@link #close()} has been called. */
    boolean isClosed() {
        return closed;
    }

    /**
     * Runs up to n steps of a plan on all threads.
     *
     * @return the number of steps run (fewer when the hook stopped the batch)
     * @throws RuntimeException or Error thrown by a kernel on any thread (wrapped in an
     *     {@link IllegalStateException} if it is a checked exception), after the step in which it happened
     */
    int run(StepPlan plan, int n, StepHook stepHook) {
        if (closed) {
            throw new IllegalStateException("the parallel stepper is closed");
        }
        if (n <= 0) {
            return 0;
        }
        if (plan != cachedPlan || plan.kernelsVersion() != cachedVersion) {
            buildPhases(plan);
        }
        hook = stepHook;
        batchSteps = n;
        done = 0;
        failure.set(null);
        generation++;
        for (Thread w : workers) {
            LockSupport.unpark(w);
        }
        try {
            runSteps(0, generation);
        } finally {
            hook = null;
        }
        Throwable t = failure.getAndSet(null);
        if (t != null) {
            if (t instanceof RuntimeException) {
                throw (RuntimeException) t;
            }
            if (t instanceof Error) {
                throw (Error) t;
            }
            throw new IllegalStateException("a kernel failed during parallel stepping", t);
        }
        return done;
    }

    private void buildPhases(StepPlan plan) {
        ArrayList<Kernel> kernels = new ArrayList<>();
        ArrayList<Integer> stages = new ArrayList<>();
        ArrayList<Kernel[]> groups = new ArrayList<>();
        ArrayList<Kernel> serial = new ArrayList<>();
        for (Kernel k : plan.kernels()) {
            if (k instanceof RangeKernel) {
                if (!serial.isEmpty()) {
                    kernels.add(null);
                    stages.add(-1);
                    groups.add(serial.toArray(new Kernel[0]));
                    serial.clear();
                }
                for (int s = 0; s < ((RangeKernel) k).stages(); s++) {
                    kernels.add(k);
                    stages.add(s);
                    groups.add(null);
                }
            } else {
                serial.add(k);
            }
        }
        if (!serial.isEmpty()) {
            kernels.add(null);
            stages.add(-1);
            groups.add(serial.toArray(new Kernel[0]));
        }
        phaseKernel = kernels.toArray(new Kernel[0]);
        phaseStage = stages.stream().mapToInt(Integer::intValue).toArray();
        serialGroup = groups.toArray(new Kernel[0][]);
        cachedPlan = plan;
        cachedVersion = plan.kernelsVersion();
    }

    private void workerLoop(int me) {
        int seen = 0;
        while (true) {
            int spins = 0;
            int g;
            while ((g = generation) == seen) {
                if (++spins < 2000) {
                    Thread.onSpinWait();
                } else {
                    LockSupport.park(this);
                }
            }
            seen = g;
            if (closed) {
                return;
            }
            runSteps(me, g);
        }
    }

    /** Runs one batch on one thread; every shared parameter is read once, before the first barrier. */
    private void runSteps(int me, int gen) {
        final Kernel[] ks = phaseKernel;
        final int[] st = phaseStage;
        final Kernel[][] groups = serialGroup;
        final int steps = batchSteps;
        final StepHook h = me == 0 ? hook : null;
        final int t = parties;
        for (int step = 0; step < steps; step++) {
            for (int ph = 0; ph < ks.length; ph++) {
                try {
                    runPhase(ks[ph], st[ph], groups[ph], me, t);
                } catch (Throwable e) {
                    failure.compareAndSet(null, e);
                }
                await(me);
            }
            if (me == 0) {
                boolean stop = failure.get() != null;
                if (!stop) {
                    done = step + 1;
                    try {
                        stop = h.afterStep();
                    } catch (Throwable e) {
                        failure.compareAndSet(null, e);
                        stop = true;
                    }
                }
                if (stop || step + 1 == steps) {
                    stopGeneration = gen;
                }
            }
            await(me);
            if (stopGeneration == gen) {
                return;
            }
        }
    }

    private static void runPhase(Kernel k, int stage, Kernel[] group, int me, int t) {
        if (k == null) {
            if (me == 0) {
                for (Kernel g : group) {
                    g.run();
                }
            }
        } else {
            RangeKernel rk = (RangeKernel) k;
            int s = rk.start(stage), len = rk.end(stage) - s;
            int from = s + (int) ((long) len * me / t);
            int to = s + (int) ((long) len * (me + 1) / t);
            if (to > from) {
                rk.run(stage, from, to);
            }
        }
    }

    private void await(int me) {
        boolean s = !localSense[me * 16];
        localSense[me * 16] = s;
        if (arrived.incrementAndGet() == parties) {
            arrived.set(0);
            sense = s;
        } else {
            int spins = 0;
            while (sense != s) {
                if (++spins < SPINS_BEFORE_YIELD) {
                    Thread.onSpinWait();
                } else {
                    spins = 0;
                    Thread.yield();
                }
            }
        }
    }
}
