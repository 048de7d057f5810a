package tactus;

import tactus.internal.realtime.ModelLock;
import tactus.internal.ModelCore;

/** A free 3D mass subject to its interactions, air friction and gravity. */
public final class Mass3D extends InertialMass {
    Mass3D(ModelCore core, ModelLock gate, int id) {
        super(core, gate, id);
    }
}
