package tactus.internal.realtime;

import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicReference;
import java.util.concurrent.locks.LockSupport;
import java.util.function.Supplier;
import tactus.StabilityPolicy;
import tactus.internal.model.EngineWrites;
import tactus.internal.ModelCore;
import tactus.internal.model.RealtimeMode;

/**
 * The realtime-stepping mode of one model ({@link PhysicalModel#beginRealtimeStepping()}): exactly one thread, the
 * owner, steps the model and writes its engine; every other thread changes the model through commands that the
 * owner applies between two steps.
 *
 * <p>The owner role ({@link #owner}) is explicit. The first thread that makes a stepping call takes it; it passes
 * on only (a) when the mode ends ({@link #close()}, or {@link #requestEnd()} from the owner itself), (b) when the
 * owner has died or has not begun a stepping call for {@link #idleNanos} and another thread needs it (a waiting
 * editor then sets the role to nobody and applies the queue itself; a stepping thread takes the role). Every
 * change of the role is made while holding the gate, so it never meets a stepping call. A stepping call from a
 * thread that is not the owner while the owner is active does nothing and is reported once.
 *
 * <ul>
 *   <li>Queue: an intrusive multi-producer, single-consumer queue of {@link Command}s (producers swap the tail, the
 *       consumer follows {@code next} links): posting never blocks and draining never allocates. Producers hold the
 *       model's lock, so commands are applied in the order the calls were made. A command whose target is gone
 *       when it is applied is dropped (in part or in full) and counted, never thrown.</li>
 *   <li>Gate: an atomic flag that whoever applies commands or steps holds: the owner for each of its stepping
 *       calls and facade calls ({@link #enterAsOwner()}), an editor to apply the queue when there is no owner, or
 *       to take the role from an idle one. Every holder releases it in a {@code finally}.</li>
 *   <li>Roles: while an editor is in a facade call it is the preparer: its engine writes go into a
 *       {@link WriteBatch} and its stability checks are collected; whoever holds the gate and drains is the
 *       applier: its writes go to the engine.</li>
 * </ul>
 * Every field without a lock is either confined to one role, guarded by the gate, or volatile/atomic (the gate's
 * holder is opaque: see {@link #gateHolder}). The owner releases the gate with a release store.
 */
public final class Ownership implements RealtimeMode {
    /** An owner that has not begun a stepping call for this long is idle: another thread may take its role. */
    public static final long IDLE_NANOS = 250_000_000L;
    /** The longest an editor waits for the owner to apply its commands before it gives up with an exception. */
    public static final long WAIT_LIMIT_NANOS = 10_000_000_000L;
    private static final int FREE = 0, STEPPING = 1, DRAINING = 2;
    /** Results of {@link #beginStep}: step now (the gate is held), do nothing, or step in locked mode. */
    public static final int STEP = 0, REFUSED = 1, ENDED = 2;

    private final ModelCore core;
    private final AtomicInteger gate = new AtomicInteger(FREE);
    private final AtomicReference<Command> tail;
    /** The consumer's stub: the last command consumed (or the initial stub). Touched only under the gate. */
    private Command head;
    private volatile long applied;
    /** Last sequence number posted; written under the model lock. */
    private volatile long posted;
    /** Commands applied in full, and commands that found a target gone: written under the gate. */
    private volatile long completed, dropped;
    /** Ramp members found removed while their ramp ran (each counted once): written by the owner. */
    public volatile long droppedRampMembers;
    /** The thread that holds the stepping role, or null; changed only under the gate. */
    private volatile Thread owner;
    /** How many times the role changed hands (taken by a new thread or set to nobody). */
    private volatile long handOvers;
    /** The owner's nesting of gate-holding calls (stepping calls and facade calls); touched under the gate. */
    private int ownerDepth;
    /**
     * The thread holding the gate for a stepping or facade call of the owner, or null; written only by that thread
     * while it holds the gate. A nested call asks "do I hold the gate?" with it, never with {@link #ownerDepth}
     * alone: a thread that has just lost the role would otherwise read the new owner's depth as its own and step
     * beside it (and their unsynchronised counts could leave the gate held for good).
     */
    private Thread gateHolder;
    /**
     * Opaque access to {@link #gateHolder}: only ever compared with the reading thread, and a thread always sees its
     * own last write (a stale value written by another thread is never the reader), so the owner's entry and exit
     * need no fence for it. The gate's compare-and-set and release order everything else.
     */
    private static final VarHandle GATE_HOLDER;

    static {
        try {
            GATE_HOLDER = MethodHandles.lookup().findVarHandle(Ownership.class, "gateHolder", Thread.class);
        } catch (ReflectiveOperationException e) {
            throw new ExceptionInInitializerError(e);
        }
    }
    /** System.nanoTime() of the owner's latest stepping call (refreshed every 64 calls or every call of 64 steps). */
    private volatile long lastStep;
    private long callsSinceClock;
    /** The thread applying commands right now (under the gate). */
    private volatile Thread applier;
    private RunCommand running;
    /** The editor preparing a change under the lock, its batch and its collected checks. */
    private volatile Thread preparer;
    private WriteBatch batch;
    private final List<Runnable> prepUndo = new ArrayList<>();
    private boolean prepAnalyse;
    /** True while the owner advances parameter ramps (those are not analysed step by step). */
    public boolean inRamp;
    private final AnalysisThread analyzer;
    /** The owner asked to end the mode from inside a stepping call; done when its outermost call returns. */
    private volatile boolean endRequested;
    /** No thread may take the role any more: the mode is ending or has ended. */
    private volatile boolean ending;
    private volatile boolean closed;
    /** Sequence number of the last command that changed parameters or structure: what a reader must wait for. */
    private volatile long lastParamSeq;
    private final AtomicBoolean refusalReported = new AtomicBoolean();
    private final AtomicLong refusedCalls = new AtomicLong();
    /** See {@link #IDLE_NANOS} and {@link #WAIT_LIMIT_NANOS}; tests shorten them. */
    public long idleNanos = IDLE_NANOS;
    public long waitLimitNanos = WAIT_LIMIT_NANOS;
    /** Avatar forces for readers on other threads. */
    public final ForceTaps taps = new ForceTaps();

    /** How calls get in and out of this model (the owner ends the mode through it). */
    private final ModelLock lock;

    public Ownership(ModelCore core, ModelLock lock) {
        this.core = core;
        this.lock = lock;
        Command stub = new WriteBatch();
        this.head = stub;
        this.tail = new AtomicReference<>(stub);
        this.analyzer = new AnalysisThread(this, core, lock.lock());
    }

    // ---------------------------------------------------------------- roles

    /** @return true when the current thread holds the stepping role. */
    @Override
    public boolean isOwnerThread() {
        return owner == Thread.currentThread();
    }

    /** @return the thread that holds the stepping role, or null. */
    public Thread owner() {
        return owner;
    }

    /** @return true when {@code t} (the calling thread) holds the gate for a stepping or facade call of the owner. */
    private boolean holdsGate(Thread t) {
        return (Thread) GATE_HOLDER.getOpaque(this) == t;
    }

    /** @return true when the current thread is the owner inside a stepping or facade call (it holds the gate). */
    public boolean ownerInCall() {
        return holdsGate(Thread.currentThread());
    }

    /** @return true when the current thread is applying queued commands. */
    public boolean isApplying() {
        return applier == Thread.currentThread();
    }

    /** @return true once the mode is ending: stepping calls go to the locked path. */
    public boolean isEnding() {
        return ending;
    }

    /** @return where the current thread's engine writes go. */
    @Override
    public EngineWrites writes(EngineWrites direct) {
        Thread t = Thread.currentThread();
        if (t == preparer && t != applier) {
            if (batch == null) {
                batch = new WriteBatch();
            }
            return batch;
        }
        return direct;
    }

    /**
     * The stability guard asks what to do with a change: returns true when the change was taken care of here
     * (collected for a later analysis, or not analysed at all), false when the guard should analyse it at once.
     */
    @Override
    public boolean interceptCheck(Runnable undo) {
        Thread t = Thread.currentThread();
        if (t == applier) {
            if (running != null) {
                running.capture(undo);
            }
            return true;
        }
        if (t == preparer) {
            prepAnalyse = true;
            if (undo != null) {
                prepUndo.add(undo);
            }
            return true;
        }
        if (t == owner) {
            if (!inRamp) {
                analyzer.request();
            }
            return true;
        }
        return false;
    }

    /** @return true when the current thread's deferral of checks must be ignored (it is not the guard's to count). */
    @Override
    public boolean ignoresDeferral() {
        Thread t = Thread.currentThread();
        return t == applier || t == preparer || t == owner;
    }

    // ---------------------------------------------------------------- the owner's side

    /**
     * Starts a stepping call of {@code n} steps on the current thread. Takes the role when nobody holds it, or when
     * its holder has died or has been idle for {@link #idleNanos}; then holds the gate. When this returns {@link
     * #STEP} the caller applies the queue ({@link #applyQueued()}) and steps inside a {@code try} whose {@code
     * finally} calls {@link #endStep()}.
     *
     * @return {@link #STEP}; {@link #REFUSED} when another thread owns the model (the call must do nothing);
     *     {@link #ENDED} when the mode is ending (the call must step in locked mode)
     */
    public int beginStep(int n) {
        Thread me = Thread.currentThread();
        if (holdsGate(me)) {
            ownerDepth++; // a stepping call from inside one (a listener): the gate is already held
            return STEP;
        }
        int r = acquireAsOwner(true);
        if (r != STEP) {
            return r;
        }
        if (n >= 64 || (++callsSinceClock & 63) == 0) {
            lastStep = System.nanoTime();
        }
        return STEP;
    }

    /**
     * Begins a run of the owner's calls that holds the gate once (a PhyUGen's sample: its step, its listening points'
     * reads, its avatar exchange): takes the role as a stepping call would ({@link #beginStep}), holds the gate,
     * applies what is queued; every stepping or facade call of this thread until {@link #endSection()} is then nested
     * in it and takes nothing. Counts as the start of a stepping call for the owner's idle clock.
     *
     * @return true when the gate is held (the caller calls {@link #endSection()} in a {@code finally}); false when
     *     the mode is ending or another active thread owns the model (nothing is held; calls behave as without it)
     */
    public boolean beginSection() {
        if (beginStep(1) != STEP) {
            return false;
        }
        try {
            drain();
        } catch (RuntimeException | Error e) {
            endStep(); // never leave the gate held
            throw e;
        }
        return true;
    }

    /**
     * Ends a run begun by {@link #beginSection()} (publishes avatar forces and releases the gate when it is the
     * outermost); does nothing when the current thread does not hold the gate.
     */
    public void endSection() {
        if (holdsGate(Thread.currentThread())) {
            endStep();
        }
    }

    /**
     * Makes the current thread the owner, even if another thread holds the role and is active (a PhyUGen's audio
     * thread takes the model from a sketch that stepped it first). Waits only for a stepping or facade call that
     * holds the gate, at most {@link #waitLimitNanos}. Costs one volatile read when the current thread already owns
     * the role.
     *
     * @return true when the current thread owns the role; false when the mode is ending or the gate stayed busy
     */
    public boolean claim() {
        Thread me = Thread.currentThread();
        if (owner == me) {
            return true;
        }
        long start = System.nanoTime();
        for (;;) {
            if (ending) {
                return false;
            }
            if (gate.compareAndSet(FREE, STEPPING)) {
                try {
                    if (ending) {
                        return false;
                    }
                    if (owner != me) {
                        takeRole(me);
                        ownerDepth = 0;
                    }
                    return true;
                } finally {
                    gate.set(FREE);
                }
            }
            if (System.nanoTime() - start > waitLimitNanos) {
                return false;
            }
            LockSupport.parkNanos(50_000L);
        }
    }

    /** Applies every queued command; the owner calls it at the start of a stepping call, holding the gate. */
    public void applyQueued() {
        drain();
    }

    /** Ends a stepping call begun by {@link #beginStep}: publishes avatar forces, releases the gate. */
    public void endStep() {
        if (--ownerDepth > 0) {
            return;
        }
        if (!taps.isEmpty()) {
            taps.collect(core.engine);
        }
        releaseAsOwner();
    }

    /**
     * A facade call made by the owner outside a stepping call (a {@code uGenerate} reading a position): holds the
     * gate for its duration, so that no other thread applies commands meanwhile.
     *
     * @return false when the current thread lost the role (it then acts as any other thread)
     */
    public boolean enterAsOwner() {
        if (holdsGate(Thread.currentThread())) {
            ownerDepth++;
            return true;
        }
        if (acquireAsOwner(false) != STEP) {
            return false;
        }
        try {
            drain();
        } catch (RuntimeException | Error e) {
            exitAsOwner(); // never leave the gate held
            throw e;
        }
        return true;
    }

    /** Ends a facade call begun by {@link #enterAsOwner()}. */
    public void exitAsOwner() {
        if (--ownerDepth == 0) {
            releaseAsOwner();
        }
    }

    /**
     * Takes the gate as the owner, taking the role first if it is free (or {@code mayTake} and its holder is gone
     * or idle). Waits only for a thread applying commands, at most {@link #waitLimitNanos}.
     */
    private int acquireAsOwner(boolean mayTake) {
        Thread me = Thread.currentThread();
        long start = 0;
        for (;;) {
            if (ending) {
                return ENDED;
            }
            Thread o = owner;
            if (o != me && !(mayTake && (o == null || !o.isAlive() || idle()))) {
                return REFUSED; // another thread holds the role (or, for a facade call, this one lost it)
            }
            if (gate.compareAndSet(FREE, STEPPING)) {
                if (ending || owner != o) {
                    gate.set(FREE); // the role changed hands meanwhile: look again
                    continue;
                }
                if (o != me) {
                    takeRole(me);
                }
                ownerDepth = 1;
                GATE_HOLDER.setOpaque(this, me);
                return STEP;
            }
            // a thread is applying commands (no owner, or taking the role from an idle one): wait for it
            if (start == 0) {
                start = System.nanoTime();
            } else if (System.nanoTime() - start > waitLimitNanos) {
                return REFUSED;
            }
            LockSupport.parkNanos(50_000L);
        }
    }

    private void releaseAsOwner() {
        try {
            if (endRequested) {
                finishRole();
            }
        } finally {
            GATE_HOLDER.setOpaque(this, (Thread) null);
            gate.setRelease(FREE); // a release store: the next holder's compare-and-set sees this call's writes
        }
        if (endRequested) {
            lock.finishEndIfFree(this);
        }
    }

    /** Under the gate: applies what is queued, gives the role up for good (the mode is ending). */
    private void finishRole() {
        drain();
        ending = true;
        freeRole();
    }

    /** Under the gate: the role passes to {@code t}, which counts as having just stepped. */
    private void takeRole(Thread t) {
        owner = t;
        handOvers++;
        lastStep = System.nanoTime();
    }

    /** Under the gate: nobody holds the role. */
    private void freeRole() {
        owner = null;
        handOvers++;
    }

    /** @return true when the owner has not begun a stepping call for {@link #idleNanos}. */
    private boolean idle() {
        return System.nanoTime() - lastStep > idleNanos;
    }

    /** @return true when the role is free, or its holder has died or is idle. */
    private boolean ownerGone() {
        Thread o = owner;
        return o == null || !o.isAlive() || idle();
    }

    /**
     * Applies every queued command, in order. The caller holds the gate. A command that throws or finds a target
     * gone is counted as dropped; {@code head} and {@code applied} always move past it.
     */
    private void drain() {
        Command n = head.next;
        if (n == null || applier == Thread.currentThread()) {
            return; // nothing queued, or called from inside a command this thread is applying
        }
        Thread previous = applier;
        applier = Thread.currentThread();
        try {
            while (n != null) {
                head = n;
                boolean full = false;
                try {
                    running = n instanceof RunCommand ? (RunCommand) n : null;
                    full = n.apply(core);
                } catch (RuntimeException e) {
                    full = false; // a target vanished in a way apply did not foresee: the command is dropped
                } finally {
                    running = null;
                    if (full) {
                        completed++;
                    } else {
                        dropped++;
                    }
                    applied = n.seq;
                }
                n = n.next;
            }
        } finally {
            applier = previous;
        }
    }

    /**
     * Asks to end the mode from the owner's own stepping call (a divergence listener): when that call returns, the
     * owner applies what is queued and gives the role up, and the model returns to the locked mode as soon as no
     * other thread holds its lock.
     */
    public void requestEnd() {
        endRequested = true;
    }

    /**
     * @return true when a stepping call from the current thread would be refused now: another thread holds the role
     *     and is active (alive, and stepped within {@link #idleNanos})
     */
    public boolean refusesStepping() {
        Thread o = owner;
        return o != null && o != Thread.currentThread() && !ending && o.isAlive() && !idle();
    }

    /** Reports once that a stepping call from {@code caller} was refused because another thread owns the model. */
    public void refused(String call) {
        refusedCalls.incrementAndGet();
        if (refusalReported.compareAndSet(false, true)) {
            Thread o = owner;
            System.err.println(call + ": this model is stepped in realtime by thread \"" + (o == null ? "?" : o.getName())
                    + "\" (the audio thread when a PhyUGen plays it), so this call does nothing. Remove " + call
                    + " from draw(): only that thread steps the model; draw() should read it with getSnapshot(). "
                    + "(Printed once.)");
        }
    }

    // ---------------------------------------------------------------- the editors' side (they hold the model lock)

    /** Queues a command; returns its sequence number. The caller holds the model's lock. */
    public long post(Command c) {
        long s = posted + 1;
        c.seq = s;
        posted = s;
        if (!(c instanceof WriteBatch) || ((WriteBatch) c).changesParameters()) {
            lastParamSeq = s;
        }
        Command prev = tail.getAndSet(c);
        prev.next = c;
        return s;
    }

    /** @return the sequence number of the last command posted (for tests and measurements). */
    public long postedSeq() {
        return posted;
    }

    /** @return the sequence number of the last command applied or dropped (for tests and measurements). */
    public long appliedSeq() {
        return applied;
    }

    /** @return the number of commands applied in full. */
    public long completedCount() {
        return completed;
    }

    /** @return the number of commands dropped in full or in part because a target was gone. */
    public long droppedCount() {
        return dropped;
    }

    /** @return how many times the role changed hands. */
    public long handOvers() {
        return handOvers;
    }

    /** @return how many stepping calls were refused (another thread owned the model). */
    public long refusedCalls() {
        return refusedCalls.get();
    }

    /** @return true when no thread holds the gate (for tests). */
    public boolean gateFree() {
        return gate.get() == FREE;
    }

    /**
     * Waits until the command with sequence number {@code seq} (and every earlier one) has been applied: by the owner
     * at its next stepping call, or here, at once, when there is no owner or it has died or is idle (the role is then
     * set to nobody, under the gate). Gives up after {@link #waitLimitNanos} with an exception naming the owner.
     */
    public void awaitApplied(long seq) {
        long start = 0;
        while (applied < seq) {
            if (ownerGone()) {
                applyNow(seq); // an explicit hand-over: the role is set free, the next stepping call takes it
                if (applied >= seq) {
                    return;
                }
            }
            if (start == 0) {
                start = System.nanoTime();
            } else if (System.nanoTime() - start > waitLimitNanos) {
                Thread o = owner;
                throw new IllegalStateException("waited " + waitLimitNanos / 1_000_000 + " ms for the thread that "
                        + "steps this model in realtime (\"" + (o == null ? "?" : o.getName()) + "\", "
                        + (o == null ? "none" : o.getState()) + ") to apply queued changes: it is stuck inside a "
                        + "stepping call (a DivergenceListener or uGenerate that blocks?); the change is still queued");
            }
            LockSupport.parkNanos(50_000L);
        }
    }

    /**
     * Waits, holding no lock, until the command {@code seq} has been applied, the owner is gone (then the caller's
     * locked wait applies the queue itself) or {@link #waitLimitNanos} has passed. A read waits here before it takes
     * the model's lock, so that a thread waiting for the stepping thread never holds the lock a setter needs.
     */
    public void awaitAppliedUnlocked(long seq) {
        long start = 0;
        while (applied < seq && !ownerGone() && !closed) {
            if (start == 0) {
                start = System.nanoTime();
            } else if (System.nanoTime() - start > waitLimitNanos) {
                return;
            }
            LockSupport.parkNanos(50_000L);
        }
    }

    /** @return the sequence number of the last command that changed parameters or structure. */
    public long paramSeq() {
        return lastParamSeq;
    }

    /** Waits until everything posted so far is applied. */
    public void awaitAll() {
        awaitApplied(posted);
    }

    /**
     * The outermost facade entry of an editor: earlier changes of parameters or structure are applied first (so that
     * getters see them), then it prepares. Queued state pokes (avatar targets, impulses, positions) are not waited
     * for: the state moves every step anyway.
     */
    public void beginEdit() {
        awaitApplied(lastParamSeq);
        preparer = Thread.currentThread();
    }

    /**
     * The outermost facade entry of a parameter or state change: it prepares at once (its writes are absolute, or
     * keep the value current when applied), except under THROW, where it first waits for earlier changes so that the
     * values its undo restores are the applied ones.
     */
    public void beginChange() {
        if (core.guard.policy() == StabilityPolicy.THROW) {
            awaitAll();
        }
        preparer = Thread.currentThread();
    }

    /**
     * The outermost facade exit of an editor: posts what it prepared. Under THROW it waits for the change to be
     * applied, analyses it and undoes it if it is unstable; under WARN the analysis runs on a helper thread; when
     * there is no active owner the change is applied at once.
     */
    public void endEdit() {
        if (preparer != Thread.currentThread()) {
            return;
        }
        preparer = null;
        WriteBatch b = batch;
        batch = null;
        boolean analyse = prepAnalyse;
        List<Runnable> undo = prepUndo.isEmpty() ? null : new ArrayList<>(prepUndo);
        prepAnalyse = false;
        prepUndo.clear();
        long seq = posted;
        if (b != null && !b.isEmpty()) {
            seq = post(b);
        }
        if (analyse && core.guard.policy() == StabilityPolicy.THROW) {
            awaitApplied(seq);
            core.guard.check(undo == null ? null : () -> runUndo(undo));
        } else if (analyse && core.guard.policy() == StabilityPolicy.WARN) {
            analyzer.request();
        }
        if (ownerGone()) {
            applyNow(seq);
        }
    }

    /**
     * Applies the queue at once when there is no active owner and no stepping call holds the gate (a stepping call
     * that holds it applies the change at its next call): never waits.
     */
    private void applyNow(long seq) {
        if (applied < seq && gate.compareAndSet(FREE, DRAINING)) {
            try {
                if (ownerGone()) {
                    if (owner != null) {
                        freeRole();
                    }
                    drain();
                }
            } finally {
                gate.set(FREE);
            }
        }
    }

    /**
     * Runs a structural change on the stepping thread and waits for it ({@link #runOnOwner}), then analyses the
     * change on this thread (under THROW an unstable change is undone the same way and refused).
     */
    @SuppressWarnings("unchecked")
    public <T> T run(Supplier<T> body) {
        RunCommand c = runOnOwner(body);
        if (c.error instanceof RuntimeException) {
            throw (RuntimeException) c.error;
        }
        if (c.error instanceof Error) {
            throw (Error) c.error;
        }
        if (c.error != null) {
            throw new IllegalStateException(c.error);
        }
        if (c.analyse) {
            List<Runnable> undo = c.undo;
            core.guard.check(undo.isEmpty() ? null : () -> runUndo(undo));
        }
        return (T) c.result;
    }

    /**
     * Runs {@code body} on the stepping thread between two steps and waits for it; then compiles the new step plan
     * on this thread while the owner keeps stepping the old one, and has the owner swap it in ({@link
     * InstallCommand}). The owner never compiles.
     */
    private RunCommand runOnOwner(Supplier<?> body) {
        RunCommand c = new RunCommand(() -> {
            core.engine.holdTopology();
            return body.get();
        });
        Thread p = preparer;
        preparer = null; // the body's own writes are made by the applier, straight to the engine
        try {
            try {
                awaitApplied(post(c));
            } finally {
                // the expensive part of the compile, here; the owner only swaps (it compiles in full if raced)
                awaitApplied(post(new InstallCommand(core.engine.prepareCompile())));
            }
        } finally {
            preparer = p;
        }
        return c;
    }

    /** Undoes collected changes, newest first, on the stepping thread (compiled here, swapped in there). */
    private void runUndo(List<Runnable> undo) {
        RunCommand c = runOnOwner(() -> {
            for (int i = undo.size() - 1; i >= 0; i--) {
                undo.get(i).run();
            }
            return null;
        });
        if (c.error instanceof Error) {
            throw (Error) c.error;
        }
    }

    /**
     * Ends the mode (the caller holds the model's lock and is not the owner inside a call): drains what is queued
     * (waiting for a running owner's current call), takes the role away for good and stops the helper.
     */
    public void close() {
        awaitAll();
        long start = System.nanoTime();
        while (!gate.compareAndSet(FREE, DRAINING)) {
            if (System.nanoTime() - start > waitLimitNanos) {
                throw new IllegalStateException("endRealtimeStepping: the stepping thread \""
                        + (owner == null ? "?" : owner.getName()) + "\" has not finished its call for "
                        + waitLimitNanos / 1_000_000 + " ms");
            }
            LockSupport.parkNanos(50_000L);
        }
        try {
            finishRole();
        } finally {
            gate.set(FREE);
        }
        closed = true;
        analyzer.wake();
    }

    /**
     * Gives the role up now, from the owner thread outside any call (before it ends the mode like any other
     * thread): applies what is queued, and the role is free.
     */
    public void releaseRole() {
        if (acquireAsOwner(false) != STEP) {
            return;
        }
        try {
            drain();
            freeRole();
        } finally {
            ownerDepth = 0;
            GATE_HOLDER.setOpaque(this, (Thread) null);
            gate.set(FREE);
        }
    }

    /** @return true once the mode has ended ({@link #close()}). */
    public boolean isClosed() {
        return closed;
    }

    /** @return true when the owner asked to end the mode and has given the role up: close at the next entry. */
    public boolean endPending() {
        return ending && !closed;
    }

    @Override
    public long takeTappedForce(int id, double[] xyz, boolean create) {
        ForceTaps.Tap t = create ? taps.tap(id) : taps.find(id);
        return t == null ? -1 : taps.take(core.engine, t, xyz);
    }

    @Override
    public void countDroppedRampMembers(int n) {
        droppedRampMembers += n;
    }
}
