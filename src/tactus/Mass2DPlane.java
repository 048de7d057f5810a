package tactus;

import tactus.internal.realtime.ModelLock;
import tactus.internal.ModelCore;

/** A mass that moves in the plane z = constant of its initial position. */
public final class Mass2DPlane extends InertialMass {
    Mass2DPlane(ModelCore core, ModelLock gate, int id) {
        super(core, gate, id);
    }
}
