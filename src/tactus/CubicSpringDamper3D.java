package tactus;

import tactus.internal.realtime.ModelLock;
import tactus.internal.ModelCore;

/** A cubic spring-damper along the line between two masses, on the elongation d - l0 (mi.lib's nlSpringDamper3 in 3-D). */
public final class CubicSpringDamper3D extends CubicSpringDamper {
    CubicSpringDamper3D(ModelCore core, ModelLock gate, int id) {
        super(core, gate, id);
    }
}
