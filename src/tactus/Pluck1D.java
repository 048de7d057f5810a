package tactus;

import tactus.internal.realtime.ModelLock;
import tactus.internal.ModelCore;

/** A pluck along z only, on z1 - z2 - l0 (mi.lib's nlPluck). */
public final class Pluck1D extends Pluck {
    Pluck1D(ModelCore core, ModelLock gate, int id) {
        super(core, gate, id);
    }
}
