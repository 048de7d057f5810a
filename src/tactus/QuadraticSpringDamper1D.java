package tactus;

import tactus.internal.realtime.ModelLock;
import tactus.internal.ModelCore;

/** A quadratic spring-damper along z only, on z1 - z2 - l0 (mi.lib's nlSpringDamper2). */
public final class QuadraticSpringDamper1D extends QuadraticSpringDamper {
    QuadraticSpringDamper1D(ModelCore core, ModelLock gate, int id) {
        super(core, gate, id);
    }
}
