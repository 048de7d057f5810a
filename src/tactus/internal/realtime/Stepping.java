package tactus.internal.realtime;

import java.util.function.IntConsumer;
import tactus.internal.ModelCore;
import tactus.internal.snapshot.SnapshotBuffer;
import tactus.internal.snapshot.SnapshotWriter;

/**
 * The stepping calls of a model ({@code draw_physics}, {@code computeStep}, {@code computeNSteps}) in both modes:
 * in locked mode a batch runs in slices and lets a waiting thread in between two of them; in realtime mode the
 * calling thread steps as the owner, without the lock, after applying what other threads queued. Also the snapshot
 * read, and the rate that a realtime driver holds. Not API.
 */
public final class Stepping {
    /** Element updates (masses plus interactions) after which a stepping batch lets a waiting thread in. */
    private static final int SLICE_ELEMENTS = 65_536;
    /** Results of {@link #stepOwned} other than a step count. */
    private static final int ENDED = -1, REFUSED = -2;

    private final ModelCore core;
    private final ModelLock lock;
    /** The realtime driver that fixes the rate (see {@link #holdSimRate(Object)}), and the session it holds it for. */
    private volatile Object simRateHolder;
    private volatile Object simRateSession;

    public Stepping(ModelCore core, ModelLock lock) {
        this.core = core;
        this.lock = lock;
    }

    /**
     * One stepping call of a realtime-stepped model on the calling thread (which takes the owner role if it is free):
     * applies the queued changes, runs n steps (advancing parameter ramps), checks for divergence. Takes no lock.
     *
     * @param call the facade call, for the message when another thread owns the model
     * @return the number of steps run; {@link #ENDED} when the mode is ending (the caller steps in locked mode);
     *     {@link #REFUSED} when another thread owns the model (nothing was done, the message was printed once)
     */
    private int stepOwned(Ownership o, int n, String call) {
        return stepOwned(o, n, call, null, null, null, 0, null);
    }

    /**
     * As {@link #stepOwned(Ownership, int, String)}, recording after each step the coordinates of masses (see
     * {@link #stepsRecording}) when {@code ids} is not null; the masses are checked after the queued changes are
     * applied and before the first step.
     */
    private int stepOwned(Ownership o, int n, String call, int[] ids, int[] stamps, int[] axes, int count,
                          double[] out) {
        int r = o.beginStep(n);
        if (r == Ownership.ENDED) {
            return ENDED;
        }
        if (r == Ownership.REFUSED) {
            o.refused(call);
            return REFUSED;
        }
        try {
            o.applyQueued();
            checkRecorded(ids, stamps, count);
            return batch(n, ids, axes, count, out, false);
        } finally {
            o.endStep();
        }
    }

    /**
     * {@code computeNStepsRecording(n, ...)}: n simulation steps as one stepping call, recording after each step
     * coordinate {@code axes[i]} of mass {@code ids[i]} (checked against {@code stamps[i]} before the first step) into
     * {@code out[s * count + i]}. A recorded batch is short (an audio block): in locked mode it holds the lock for
     * the whole batch, without slices.
     *
     * @return the number of steps run: fewer than n when the model diverged, 0 when another thread owns it
     */
    public int stepsRecording(int n, int[] ids, int[] stamps, int[] axes, int count, double[] out) {
        Ownership o = lock.mode();
        if (o != null && !o.isEnding()) {
            int done = stepOwned(o, n, "computeNStepsRecording()", ids, stamps, axes, count, out);
            if (done == REFUSED) {
                return 0;
            }
            if (done != ENDED) {
                return done;
            }
        }
        lock.enter();
        try {
            checkRecorded(ids, stamps, count);
            return batch(n, ids, axes, count, out, true);
        } finally {
            lock.exit();
        }
    }

    /**
     * Runs n steps without slices, one at a time while parameter ramps run (they advance every step), recording when
     * {@code ids} is not null, then checks for divergence.
     *
     * @param settleRamps true (locked mode): after steps that advanced a ramp, check stability once, as
     *     {@link #runRampedSteps} does
     * @return the number of steps run
     */
    private int batch(int n, int[] ids, int[] axes, int count, double[] out, boolean settleRamps) {
        boolean ramped = false;
        int done = 0;
        while (done < n) {
            boolean ramping = core.ramping();
            if (ramping) {
                advanceRamps();
                ramped = true;
            }
            int ran = engineSteps(ramping ? 1 : n - done, done, ids, axes, count, out);
            core.snapshots.afterSteps(ran);
            done += ran;
            if (ran == 0) {
                break;
            }
        }
        if (ramped && settleRamps) {
            core.guard.afterChange(null);
        }
        core.watch.check();
        return done;
    }

    /** Throws the handle's IllegalStateException when a recorded mass has left the model. */
    private void checkRecorded(int[] ids, int[] stamps, int count) {
        for (int i = 0; i < count; i++) {
            core.dir.checkMass(ids[i], stamps[i]);
        }
    }

    /** k engine steps; when recording, into {@code out} from step {@code done} of the batch on. */
    private int engineSteps(int k, int done, int[] ids, int[] axes, int count, double[] out) {
        return ids == null ? core.engine.step(k) : core.engine.stepRecording(k, ids, axes, count, out, done * count);
    }

    /** {@code draw_physics()}: one display frame. @return the number of steps of this frame */
    public int frame() {
        Ownership o = lock.mode();
        if (o != null && !o.isEnding()) {
            if (o.refusesStepping()) {
                o.refused("draw_physics()");
                return 0;
            }
            int frame = lock.structural(() -> core.time.stepsForFrame());
            int done = stepOwned(o, frame, "draw_physics()");
            if (done == REFUSED) {
                return 0;
            }
            return done == ENDED ? lockedFrame(frame) : frame; // ended meanwhile: this frame's steps, locked
        }
        return lockedFrame(-1);
    }

    /** Runs one display frame in locked mode: {@code n} steps, or the frame's own count when n &lt; 0. */
    private int lockedFrame(int frame) {
        lock.enter();
        try {
            int n = frame >= 0 ? frame : core.time.stepsForFrame();
            core.snapshots.beginFrame();
            try {
                runSteps(n);
            } catch (RuntimeException | Error e) {
                core.snapshots.abandonFrame();
                throw e;
            }
            core.snapshots.endFrame();
            return n;
        } finally {
            lock.exit();
        }
    }

    /** {@code computeStep()}: one simulation step. */
    public void step() {
        Ownership o = lock.mode();
        if (o != null && !o.isEnding() && stepOwned(o, 1, "computeStep()") != ENDED) {
            return;
        }
        lock.enter();
        try {
            if (core.ramping()) {
                runRampedSteps(1);
                return;
            }
            core.snapshots.afterSteps(core.engine.step(1));
            core.watch.check();
        } finally {
            lock.exit();
        }
    }

    /** {@code computeNSteps(n)}: n simulation steps (n &ge; 0, checked by the caller). */
    public void steps(int n) {
        Ownership o = lock.mode();
        if (o != null && !o.isEnding() && stepOwned(o, n, "computeNSteps()") != ENDED) {
            return;
        }
        lock.enter();
        try {
            runSteps(n);
        } finally {
            lock.exit();
        }
    }

    /**
     * Runs n steps in slices; between two slices a thread waiting for the lock goes first. A divergence stops
     * the batch and is reported.
     */
    private void runSteps(int n) {
        if (core.ramping()) {
            runRampedSteps(n);
            return;
        }
        int slice = sliceSteps();
        int done = 0;
        while (done < n) {
            int chunk = Math.min(slice, n - done);
            int ran = core.engine.step(chunk);
            core.snapshots.afterSteps(ran);
            done += ran;
            if (ran < chunk) {
                break;
            }
            if (done < n) {
                lock.letWaitingThreadIn();
            }
        }
        core.watch.check();
    }

    /**
     * Runs n steps one at a time while parameter controllers ramp, then checks stability once. Like
     * {@link #runSteps}, it lets a thread waiting for the lock in after every slice of steps, so that a change made
     * during a long ramped batch never waits for the whole batch.
     */
    private void runRampedSteps(int n) {
        int slice = sliceSteps();
        int done = 0;
        int inSlice = 0;
        while (done < n) {
            boolean ramping = core.ramping();
            if (ramping) {
                advanceRamps();
            }
            int ran = core.engine.step(1);
            core.snapshots.afterSteps(ran);
            done += ran;
            if (ran == 0) {
                break;
            }
            if (!ramping) {
                core.guard.afterChange(null);
                runSteps(n - done);
                return;
            }
            if (++inSlice == slice && done < n) {
                inSlice = 0;
                lock.letWaitingThreadIn();
            }
        }
        core.guard.afterChange(null);
        core.watch.check();
    }

    /** Advances every running ramp by one step, with the stability check deferred to the end of the batch. */
    private void advanceRamps() {
        Ownership o = lock.mode();
        if (o != null) {
            o.inRamp = true;
        }
        core.guard.defer();
        try {
            core.ramps.advanceAll();
        } finally {
            core.guard.resume();
            if (o != null) {
                o.inRamp = false;
            }
        }
    }

    /** @return the steps of one slice of a locked-mode batch: about {@link #SLICE_ELEMENTS} element updates. */
    private int sliceSteps() {
        int elements = Math.max(1, core.dir.mats.size() + core.dir.links.size());
        return Math.max(core.engine.threads() > 1 ? 8 : 1, SLICE_ELEMENTS / elements);
    }

    /** {@code getSnapshot()}: the newest snapshot, published by this thread first when it may (see there). */
    public SnapshotBuffer snapshot() {
        SnapshotWriter w = core.snapshots;
        w.request();
        if (core.own == null) {
            // locked mode: this thread may publish, holding the lock; it waits for it only to publish a topology
            // change nobody has read yet, else it leaves a busy lock alone (the writer's next frame publishes)
            boolean locked;
            if (w.dirty()) {
                lock.lock().lock();
                locked = true;
            } else {
                locked = lock.lock().tryLock();
            }
            if (locked) {
                try {
                    if (core.own == null) {
                        w.publishForReader();
                    }
                } finally {
                    lock.lock().unlock();
                }
            }
        }
        return w.exchange.latest();
    }

    /** {@code setSimRate(rate)}: refused while a realtime driver holds the rate. */
    public void setSimRate(int rate) {
        checkSimRate(rate);
        Object holder = simRateHolder;
        if (holder != null && simRateSession == core.own) {
            int now;
            lock.enter();
            try {
                now = core.time.simRate();
            } finally {
                lock.exit();
            }
            throw new IllegalStateException("setSimRate(" + rate + "): refused, the model stays at " + now
                    + " steps/s: " + holder);
        }
        changeSimRate(rate);
    }

    private void changeSimRate(int rate) {
        checkSimRate(rate);
        lock.structuralDo(() -> {
            core.time.setSimRate(rate, core.subsets.groupIds(), core.guard::afterChange);
        });
    }

    private static void checkSimRate(int rate) {
        if (rate <= 0) {
            throw new IllegalArgumentException("setSimRate: the rate must be > 0 Hz, got " + rate);
        }
    }

    /** {@code holdSimRate(holder)}: the rate is the driver's until the realtime mode ends. */
    public IntConsumer holdSimRate(Object holder) {
        if (holder == null) {
            throw new IllegalArgumentException("holdSimRate: the holder must not be null");
        }
        lock.enter();
        try {
            Ownership o = lock.mode();
            if (o == null) {
                throw new IllegalStateException("holdSimRate: the model is not stepped in realtime; call "
                        + "beginRealtimeStepping() first");
            }
            simRateSession = o;
            simRateHolder = holder;
        } finally {
            lock.exit();
        }
        return this::changeSimRate;
    }
}
