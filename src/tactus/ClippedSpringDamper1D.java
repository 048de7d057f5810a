package tactus;

import tactus.internal.realtime.ModelLock;
import tactus.internal.ModelCore;

/** A clipped cubic spring-damper along z only, on z1 - z2 - l0 (mi.lib's nlSpringDamperClipped). */
public final class ClippedSpringDamper1D extends ClippedInteraction {
    ClippedSpringDamper1D(ModelCore core, ModelLock gate, int id) {
        super(core, gate, id);
    }
}
