package tactus;

import tactus.internal.realtime.ModelLock;
import tactus.internal.ModelCore;

/** A clipped cubic contact along z, mass 2 above mass 1: it acts while z2 - z1 is below its threshold, on the penetration z1 + threshold - z2 (mi.lib's nlCollisionClipped). */
public final class ClippedContact1D extends ClippedInteraction {
    ClippedContact1D(ModelCore core, ModelLock gate, int id) {
        super(core, gate, id);
    }
}
