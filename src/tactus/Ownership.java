package tactus;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;
import java.util.concurrent.locks.LockSupport;
import java.util.function.Supplier;

/**
 * The realtime-stepping mode of one model ({@link PhysicalModel#beginRealtimeStepping()}): the thread that steps
 * the model (the owner, typically Minim's audio thread) never takes the model's lock, and every other thread changes
 * the model through commands that the owner applies between two steps.
 *
 * <ul>
 *   <li>Queue: an intrusive multi-producer, single-consumer queue of {@link Command}s (producers swap the tail, the
 *       consumer follows {@code next} links): posting never blocks and draining never allocates. Producers hold the
 *       model's lock, so commands are applied in the order the calls were made.</li>
 *   <li>Gate: an atomic flag the owner sets around each stepping call (drain, step, snapshot) with one
 *       compare-and-set and one release store. An editor sets it only to drain the queue itself when the owner is
 *       idle (has not stepped for {@link #IDLE_NANOS}, or never has): then the owner, should it come back at that
 *       very moment, skips one stepping call instead of waiting.</li>
 *   <li>Roles: while an editor holds the lock it is the preparer: its engine writes go into a {@link WriteBatch}
 *       and its stability checks are collected; whoever drains is the applier: its writes go to the engine.</li>
 * </ul>
 * Every field without a lock is either confined to one role or volatile/atomic.
 */
final class Ownership {
    /** An owner that has not stepped for this long is idle: editors drain its queue themselves. */
    static final long IDLE_NANOS = 250_000_000L;
    private static final int FREE = 0, STEPPING = 1, DRAINING = 2;

    private final ModelCore core;
    private final AtomicInteger gate = new AtomicInteger(FREE);
    private final AtomicReference<Command> tail;
    /** The consumer's stub: the last command applied (or the initial stub). Touched only under the gate. */
    private Command head;
    private volatile long applied;
    /** Last sequence number posted; written under the model lock. */
    private volatile long posted;
    volatile Thread owner;
    /** System.nanoTime() of the owner's latest stepping call (refreshed every 64 steps and when it starts). */
    private volatile long lastStep;
    private long stepsSinceClock;
    /** The thread applying commands right now (the owner, or an editor draining an idle queue). */
    private volatile Thread applier;
    private RunCommand running;
    /** The editor preparing a change under the lock, its batch and its collected checks. */
    private volatile Thread preparer;
    private WriteBatch batch;
    private final List<Runnable> prepUndo = new ArrayList<>();
    private boolean prepAnalyse;
    /** True while the owner advances parameter ramps (those are not analysed step by step). */
    boolean inRamp;
    private final Analyzer analyzer;
    private volatile boolean closed;
    /** Sequence number of the last command that changed parameters or structure: what a reader must wait for. */
    private volatile long lastParamSeq;
    /** Avatar forces for readers on other threads. */
    final ForceTaps taps = new ForceTaps();

    Ownership(ModelCore core) {
        this.core = core;
        Command stub = new WriteBatch();
        this.head = stub;
        this.tail = new AtomicReference<>(stub);
        this.analyzer = new Analyzer();
    }

    // ---------------------------------------------------------------- roles

    boolean isOwnerThread() {
        return owner == Thread.currentThread();
    }

    /** @return true when the current thread is applying queued commands (the owner, or an editor draining). */
    boolean isApplying() {
        return applier == Thread.currentThread();
    }

    /** @return where the current thread's engine writes go. */
    EngineWrites writes(EngineWrites direct) {
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
    boolean interceptCheck(Runnable undo) {
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
    boolean ignoresDeferral() {
        Thread t = Thread.currentThread();
        return t == applier || t == preparer || t == owner;
    }

    // ---------------------------------------------------------------- the owner's side

    /**
     * Starts a stepping call on the current thread, making it the owner. Applies every queued command first.
     *
     * @return false when an editor is draining the queue of what it took for an idle model: skip this call
     */
    boolean beginStep() {
        Thread t = Thread.currentThread();
        if (owner != t) {
            owner = t;
            lastStep = System.nanoTime();
            while (!gate.compareAndSet(FREE, STEPPING)) {
                LockSupport.parkNanos(50_000L); // a new owner (not yet the audio thread) may wait once
            }
        } else if (!gate.compareAndSet(FREE, STEPPING)) {
            return false;
        }
        if ((++stepsSinceClock & 63) == 0) {
            lastStep = System.nanoTime();
        }
        drain();
        return true;
    }

    void endStep() {
        if (!taps.isEmpty()) {
            taps.collect(core.engine);
        }
        gate.set(FREE);
    }

    /** Applies every queued command, in order. The caller holds the gate. */
    private void drain() {
        Command h = head;
        Command n = h.next;
        if (n == null) {
            return;
        }
        applier = Thread.currentThread();
        try {
            while (n != null) {
                head = n;
                running = n instanceof RunCommand ? (RunCommand) n : null;
                n.apply(core);
                running = null;
                applied = n.seq;
                n = n.next;
            }
        } finally {
            running = null;
            applier = null;
        }
    }

    // ---------------------------------------------------------------- the editors' side (they hold the model lock)

    /** Queues a command; returns its sequence number. */
    long post(Command c) {
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
    long postedSeq() {
        return posted;
    }

    /** @return the sequence number of the last command applied (for tests and measurements). */
    long appliedSeq() {
        return applied;
    }

    /** @return true when the owner has not stepped for {@link #IDLE_NANOS} (or never has). */
    boolean ownerIdle() {
        return owner == null || System.nanoTime() - lastStep > IDLE_NANOS;
    }

    /**
     * Waits until the command with sequence number {@code seq} (and every earlier one) has been applied: by the owner
     * at its next stepping call, or here, at once, when the owner is idle.
     */
    void awaitApplied(long seq) {
        while (applied < seq) {
            if (ownerIdle() && gate.compareAndSet(FREE, DRAINING)) {
                try {
                    drain();
                } finally {
                    gate.set(FREE);
                }
                continue;
            }
            LockSupport.parkNanos(50_000L);
        }
    }

    /** Waits until everything posted so far is applied. */
    void awaitAll() {
        awaitApplied(posted);
    }

    /**
     * The outermost lock entry of an editor: earlier changes of parameters or structure are applied first (so that
     * getters see them), then it prepares. Queued state pokes (avatar targets, impulses, positions) are not waited
     * for: the state moves every step anyway.
     */
    void beginEdit() {
        awaitApplied(lastParamSeq);
        preparer = Thread.currentThread();
    }

    /**
     * The outermost lock entry of a parameter or state change: it prepares at once (its writes are absolute, or keep
     * the value current when applied), except under THROW, where it first waits for earlier changes so that the
     * values its undo restores are the applied ones.
     */
    void beginChange() {
        if (core.guard.policy() == StabilityPolicy.THROW) {
            awaitAll();
        }
        preparer = Thread.currentThread();
    }

    /**
     * The outermost lock exit of an editor: posts what it prepared. Under THROW it waits for the change to be
     * applied, analyses it and undoes it if it is unstable; under WARN the analysis runs on a helper thread; when
     * the owner is idle the change is applied at once.
     */
    void endEdit() {
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
        if (ownerIdle()) {
            awaitApplied(seq);
        }
    }

    /**
     * Runs a structural change on the stepping thread and waits for it; then compiles the new step plan on this
     * thread while the owner keeps stepping the old one, has the owner swap it in between two steps
     * ({@link InstallCommand}), and analyses the change on this thread.
     */
    @SuppressWarnings("unchecked")
    <T> T run(Supplier<T> body) {
        RunCommand c = new RunCommand(() -> {
            core.engine.holdTopology();
            return body.get();
        });
        Thread me = Thread.currentThread();
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
        assert me == Thread.currentThread();
        return (T) c.result;
    }

    /** Undoes collected changes, newest first, on the stepping thread, and waits for it. */
    private void runUndo(List<Runnable> undo) {
        RunCommand c = new RunCommand(() -> {
            for (int i = undo.size() - 1; i >= 0; i--) {
                undo.get(i).run();
            }
            return null;
        });
        Thread p = preparer;
        preparer = null;
        try {
            awaitApplied(post(c));
        } finally {
            preparer = p;
        }
    }

    /** Ends the mode: drains what is queued (waiting for a running owner's current step) and stops the helper. */
    void close() {
        awaitAll();
        while (!gate.compareAndSet(FREE, DRAINING)) {
            LockSupport.parkNanos(50_000L);
        }
        try {
            drain();
        } finally {
            gate.set(FREE);
        }
        closed = true;
        Thread t = analyzer.thread;
        if (t != null) {
            LockSupport.unpark(t);
        }
    }

    /**
     * Runs the stability analysis of changes posted under WARN on its own daemon thread (once for a burst of
     * changes), so that the calls return as soon as they are queued. It takes the model's lock like any editor, and
     * rests seven times as long as each analysis took (however many requests arrive meanwhile), so that it never uses more than an eighth of a core (the
     * audio thread needs the rest): a warning may come some tens of milliseconds after the change on a big model.
     */
    private final class Analyzer implements Runnable {
        /** How long the helper thread waits for work before it ends (a later change starts a new one). */
        private static final long IDLE_EXIT_NANOS = 5_000_000_000L;
        private volatile boolean requested;
        private volatile Thread thread;

        /**
         * Asks for an analysis. Never blocks and never allocates when the helper thread runs; an editor's request
         * starts it if it is not running. A request from the stepping thread itself never starts it: its changes are
         * then analysed with the next editor's.
         */
        void request() {
            requested = true;
            Thread t = thread;
            if (t != null) {
                LockSupport.unpark(t);
            } else if (!isOwnerThread()) {
                start();
            }
        }

        private synchronized void start() {
            if (thread == null && !closed) {
                Thread t = new Thread(this, "Tactus stability analysis");
                t.setDaemon(true);
                thread = t;
                t.start();
            }
        }

        @Override
        public void run() {
            long idleSince = System.nanoTime();
            while (!closed) {
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
                java.util.concurrent.locks.Lock lock = core.model.getLock();
                lock.lock();
                try {
                    awaitAll();
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
                for (long now = System.nanoTime(); now < until && !closed; now = System.nanoTime()) {
                    LockSupport.parkNanos(this, until - now);
                }
                idleSince = System.nanoTime();
            }
            thread = null;
        }
    }
}
