package tactus;

import tactus.internal.realtime.ModelLock;
import tactus.internal.ModelCore;

/** A bow along z only, on the relative velocity (z1 - z1') - (z2 - z2') (mi.lib's nlBow). */
public final class Bow1D extends Bow {
    Bow1D(ModelCore core, ModelLock gate, int id) {
        super(core, gate, id);
    }
}
