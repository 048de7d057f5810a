package tactus;

import tactus.internal.realtime.ModelLock;
import tactus.internal.ModelCore;

/** A spring and a damper in parallel: f = -K (d - l0) - Z (d(n) - d(n-1)) along the line between the masses. */
public final class SpringDamper3D extends ElasticInteraction {
    SpringDamper3D(ModelCore core, ModelLock gate, int id) {
        super(core, gate, id);
    }
}
