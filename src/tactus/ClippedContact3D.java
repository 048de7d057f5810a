package tactus;

import tactus.internal.realtime.ModelLock;
import tactus.internal.ModelCore;

/** A clipped cubic contact that pushes two masses apart while they are closer than its threshold, on the penetration threshold - d (mi.lib's nlCollisionClipped in 3-D). */
public final class ClippedContact3D extends ClippedInteraction {
    ClippedContact3D(ModelCore core, ModelLock gate, int id) {
        super(core, gate, id);
    }
}
