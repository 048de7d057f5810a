package tactus;

import tactus.internal.realtime.ModelLock;
import tactus.internal.ModelCore;

/** A clipped cubic spring-damper along the line between two masses, on the elongation d - l0 (mi.lib's nlSpringDamperClipped in 3-D). */
public final class ClippedSpringDamper3D extends ClippedInteraction {
    ClippedSpringDamper3D(ModelCore core, ModelLock gate, int id) {
        super(core, gate, id);
    }
}
