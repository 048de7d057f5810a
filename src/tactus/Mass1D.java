package tactus;

import tactus.internal.realtime.ModelLock;
import tactus.internal.ModelCore;

/** A mass that moves along z only; x and y keep their initial values. */
public final class Mass1D extends InertialMass {
    Mass1D(ModelCore core, ModelLock gate, int id) {
        super(core, gate, id);
    }
}
