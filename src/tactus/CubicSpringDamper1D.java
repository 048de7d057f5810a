package tactus;

import tactus.internal.realtime.ModelLock;
import tactus.internal.ModelCore;

/** A cubic spring-damper along z only, on z1 - z2 - l0 (mi.lib's nlSpringDamper3). */
public final class CubicSpringDamper1D extends CubicSpringDamper {
    CubicSpringDamper1D(ModelCore core, ModelLock gate, int id) {
        super(core, gate, id);
    }
}
