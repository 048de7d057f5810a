package tactus;

import tactus.internal.realtime.ModelLock;
import tactus.internal.ModelCore;

/** A pluck along the line between two masses, on the elongation d - l0 (mi.lib's nlPluck in 3-D). */
public final class Pluck3D extends Pluck {
    Pluck3D(ModelCore core, ModelLock gate, int id) {
        super(core, gate, id);
    }
}
