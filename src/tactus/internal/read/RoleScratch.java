package tactus.internal.read;

import tactus.internal.model.ModelBase;
import tactus.internal.model.RealtimeMode;

/**
 * A three-element scratch vector for each side of a realtime-stepped model: one for its owner (the stepping thread,
 * which takes no lock) and one for the threads that hold the model's lock (they take turns). An owner's read and a
 * lock holder's read may run at the same time; with one shared vector each could return the other's value.
 */
public final class RoleScratch {
    private final ModelBase core;
    private final double[] owner = new double[3];
    private final double[] locked = new double[3];

    public RoleScratch(ModelBase core) {
        this.core = core;
    }

    /** @return the calling thread's scratch vector: the owner's own while the model is stepped in realtime. */
    public double[] get() {
        RealtimeMode o = core.own;
        return o != null && o.isOwnerThread() ? owner : locked;
    }
}
