package tactus;

import tactus.internal.realtime.ModelLock;
import tactus.internal.ModelCore;

/** A free 3D mass subject to its interactions only: it ignores air friction and gravity. */
public final class Mass3DSimple extends InertialMass {
    Mass3DSimple(ModelCore core, ModelLock gate, int id) {
        super(core, gate, id);
    }
}
