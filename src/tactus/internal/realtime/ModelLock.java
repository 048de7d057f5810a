package tactus.internal.realtime;

import java.util.concurrent.locks.ReentrantLock;
import java.util.function.Supplier;
import tactus.internal.ModelCore;

/**
 * How a facade call gets in and out of a model, and how the realtime mode begins and ends: the model's fair lock
 * in locked mode, the owner's gate while the model is stepped in realtime (docs/architecture.md, "The ownership
 * rule"). Every public call of {@code PhysicalModel} and of its handles enters once and exits once. Not API.
 */
public final class ModelLock {
    private final ReentrantLock lock = new ReentrantLock(true);
    private final ModelCore core;
    /** Commands dropped in realtime modes that have ended (see {@link #droppedCommands()}); volatile for readers. */
    private volatile long droppedInEndedModes;
    /** Nesting of the facade calls of the thread that holds the lock (guarded by the lock). */
    private int editDepth;
    /** The realtime mode the outermost facade call of the lock holder began an edit in, or null (guarded by it). */
    private Ownership editOwn;

    public ModelLock(ModelCore core) {
        this.core = core;
    }

    /** @return the model's fair lock (what {@code PhysicalModel.getLock()} returns). */
    public ReentrantLock lock() {
        return lock;
    }

    /** @return the realtime mode, or null in locked mode. */
    public Ownership mode() {
        return (Ownership) core.own;
    }

    /**
     * Enters a facade call. While the model is stepped in realtime, the owner takes no lock (it holds the mode's
     * gate for the call); any other thread takes the lock, and its outermost facade call, whatever locks it already
     * holds ({@code getLock()} included), first waits until the changes it queued earlier are applied, then prepares
     * its own change as a command (see {@link Ownership}).
     */
    public void enter() {
        enter(false);
    }

    /**
     * Enters a facade call that makes a parameter or state change. While the model is stepped in realtime, the change
     * is prepared without waiting for earlier queued changes to be applied (under THROW it does wait, so that its
     * undo is exact): a run of setters returns at once, in order.
     */
    public void enterChange() {
        enter(true);
    }

    private void enter(boolean change) {
        Ownership o = mode();
        if (o != null && o.isOwnerThread() && o.enterAsOwner()) {
            return;
        }
        if (o != null && !change && !lock.isHeldByCurrentThread()) {
            o.awaitAppliedUnlocked(o.paramSeq()); // wait for the stepping thread without holding the lock
        }
        lock.lock();
        if (editDepth++ > 0) {
            return;
        }
        try {
            o = mode();
            if (o != null && o.endPending()) {
                endMode(o); // the owner ended the mode from inside a stepping call: finish it here
                o = null;
            }
            editOwn = o;
            if (o != null) {
                if (change) {
                    o.beginChange();
                } else {
                    o.beginEdit();
                }
            }
        } catch (RuntimeException | Error e) {
            editDepth--;
            editOwn = null;
            lock.unlock();
            throw e;
        }
    }

    /**
     * Begins a run of calls of the realtime owner that enters the model once (see
     * {@code PhysicalModel.beginRealtimeCalls()} and {@link Ownership#beginSection()}).
     *
     * @return true when the run holds the owner's gate; false in locked mode, while the mode ends, or when another
     *     active thread owns the model
     */
    public boolean beginOwnerSection() {
        Ownership o = mode();
        return o != null && o.beginSection();
    }

    /** Ends a run begun by {@link #beginOwnerSection()} that returned true. */
    public void endOwnerSection() {
        Ownership o = mode();
        if (o != null) {
            o.endSection();
        }
    }

    /** Leaves a facade call; the outermost call of an editor of a realtime-stepped model posts what it prepared. */
    public void exit() {
        Ownership o = mode();
        if (o != null && o.ownerInCall()) {
            o.exitAsOwner();
            return;
        }
        if (!lock.isHeldByCurrentThread()) {
            return;
        }
        try {
            if (--editDepth == 0) {
                Ownership e = editOwn;
                editOwn = null;
                if (e != null) {
                    e.endEdit();
                }
            }
        } finally {
            lock.unlock();
        }
    }

    /**
     * Runs a structural change (modules, subsets, groups, rates, divergence settings): under the lock, or, while the
     * model is stepped in realtime, as a command the stepping thread runs between two steps while this thread waits
     * (its stability analysis then runs here).
     */
    public <T> T structural(Supplier<T> body) {
        enter();
        try {
            Ownership o = mode();
            if (o == null || o.ownerInCall() || o.isApplying()) {
                return body.get(); // not realtime, or already on the thread that applies changes
            }
            return o.run(body);
        } finally {
            exit();
        }
    }

    /** {@link #structural(Supplier)} for a change that returns nothing. */
    public void structuralDo(Runnable body) {
        structural(() -> {
            body.run();
            return null;
        });
    }

    /** Enters the realtime mode (see {@code PhysicalModel.beginRealtimeStepping()}); again, it does nothing. */
    public void beginRealtime() {
        enter();
        try {
            if (core.own == null) {
                core.snapshots.publishIfDirty(); // from now on only the owner may publish
                core.setOwnership(new Ownership(core, this));
            }
        } finally {
            exit();
        }
    }

    /** Ends the realtime mode (see {@code PhysicalModel.endRealtimeStepping()}). */
    public void endRealtime() {
        Ownership o = mode();
        if (o != null && o.isOwnerThread()) {
            if (o.ownerInCall()) {
                o.requestEnd();
                return;
            }
            o.releaseRole(); // the owner between two calls: give the role up, then end the mode as any thread
        }
        enter();
        try {
            o = mode();
            if (o != null) {
                endMode(o);
            }
        } finally {
            exit();
        }
    }

    /**
     * Called by the owner once it gave the role up after {@code endRealtimeStepping()} from inside a stepping call:
     * ends the mode now if no other thread holds the lock (else the next thread that enters does).
     */
    void finishEndIfFree(Ownership o) {
        if (!lock.tryLock()) {
            return;
        }
        try {
            if (core.own == o && o.endPending() && editDepth == 0) {
                endMode(o);
            }
        } finally {
            lock.unlock();
        }
    }

    /** Ends a realtime mode (the caller holds the lock): drains and closes it, keeps its count of dropped commands. */
    void endMode(Ownership o) {
        o.close();
        droppedInEndedModes += o.droppedCount();
        core.setOwnership(null);
    }

    /** @return the thread that steps the model in realtime, or null (see {@code PhysicalModel.getRealtimeOwner()}). */
    public Thread owner() {
        Ownership o = mode();
        return o == null ? null : o.owner();
    }

    /** Makes the calling thread the realtime owner (see {@code PhysicalModel.takeRealtimeStepping()}). */
    public boolean claim() {
        Ownership o = mode();
        return o != null && o.claim();
    }

    /** @return the commands dropped over the life of the model (see {@code PhysicalModel.getDroppedCommands()}). */
    public long droppedCommands() {
        Ownership o = mode();
        return droppedInEndedModes + (o == null ? 0 : o.droppedCount());
    }

    /** Between two slices of a locked-mode batch: a thread waiting for the (fair) lock goes first. */
    void letWaitingThreadIn() {
        if (lock.hasQueuedThreads()) {
            lock.unlock();
            lock.lock();
        }
    }
}
