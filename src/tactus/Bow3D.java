package tactus;

import tactus.internal.realtime.ModelLock;
import tactus.internal.ModelCore;

/** A bow between two masses whose friction acts against their relative velocity vector (mi.lib's nlBow in 3-D). */
public final class Bow3D extends Bow {
    Bow3D(ModelCore core, ModelLock gate, int id) {
        super(core, gate, id);
    }
}
