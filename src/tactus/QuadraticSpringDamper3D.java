package tactus;

import tactus.internal.realtime.ModelLock;
import tactus.internal.ModelCore;

/** A quadratic spring-damper along the line between two masses, on the elongation d - l0 (mi.lib's nlSpringDamper2 in 3-D). */
public final class QuadraticSpringDamper3D extends QuadraticSpringDamper {
    QuadraticSpringDamper3D(ModelCore core, ModelLock gate, int id) {
        super(core, gate, id);
    }
}
