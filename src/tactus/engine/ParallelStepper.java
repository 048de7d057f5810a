package tactus.engine;

import java.util.ArrayList;
import java.util.concurrent.atomic.AtomicInteger;
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
 */
final class ParallelStepper {
    /** Decides after each step whether the batch must stop early (the divergence guard). */
    interface StepHook {
        /** @return true to stop after this step */
        boolean afterStep();
    }

    private final int parties;
    private final Thread[] workers;
    private final boolean[] localSense;
    private final AtomicInteger arrived = new AtomicInteger();
    private volatile boolean sense;
    private volatile int generation;
    private volatile boolean shutdown;
    private volatile boolean stop;

    private StepPlan cachedPlan;
    private Kernel[] phaseKernel = new Kernel[0];
    private int[] phaseStage = new int[0];
    private Kernel[][] serialGroup = new Kernel[0][];

    private StepHook hook;
    private int steps;
    private int done;

    ParallelStepper(int threads) {
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

    /** Stops the worker threads. */
    void shutdown() {
        shutdown = true;
        generation++;
        for (Thread w : workers) {
            LockSupport.unpark(w);
        }
    }

    /**
     * Runs up to n steps of a plan on all threads.
     *
     * @return the number of steps run (fewer when the hook stopped the batch)
     */
    int run(StepPlan plan, int n, StepHook stepHook) {
        if (plan != cachedPlan || plan.kernelsVersion() != cachedVersion) {
            buildPhases(plan);
        }
        hook = stepHook;
        steps = n;
        done = 0;
        stop = false;
        generation++;
        for (Thread w : workers) {
            LockSupport.unpark(w);
        }
        runSteps(0);
        return done;
    }

    private int cachedVersion;

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
            while (generation == seen) {
                if (++spins < 2000) {
                    Thread.onSpinWait();
                } else {
                    LockSupport.park(this);
                }
            }
            seen = generation;
            if (shutdown) {
                return;
            }
            runSteps(me);
        }
    }

    private void runSteps(int me) {
        final Kernel[] ks = phaseKernel;
        final int[] st = phaseStage;
        final Kernel[][] groups = serialGroup;
        final int t = parties;
        for (int step = 0; step < steps; step++) {
            for (int ph = 0; ph < ks.length; ph++) {
                Kernel k = ks[ph];
                if (k == null) {
                    if (me == 0) {
                        for (Kernel g : groups[ph]) {
                            g.run();
                        }
                    }
                } else {
                    RangeKernel rk = (RangeKernel) k;
                    int stage = st[ph];
                    int s = rk.start(stage), len = rk.end(stage) - s;
                    int from = s + (int) ((long) len * me / t);
                    int to = s + (int) ((long) len * (me + 1) / t);
                    if (to > from) {
                        rk.run(stage, from, to);
                    }
                }
                await(me);
            }
            if (me == 0) {
                done = step + 1;
                stop = hook.afterStep();
            }
            await(me);
            if (stop) {
                return;
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
            while (sense != s) {
                Thread.onSpinWait();
            }
        }
    }
}
