package tactus;

import tactus.internal.realtime.ModelLock;
import tactus.internal.ModelCore;

/** A spring-damper that acts only while the masses are farther apart than its length. */
public final class Rope3D extends ElasticInteraction {
    Rope3D(ModelCore core, ModelLock gate, int id) {
        super(core, gate, id);
    }
}
