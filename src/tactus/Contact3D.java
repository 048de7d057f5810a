package tactus;

import tactus.internal.realtime.ModelLock;
import tactus.internal.ModelCore;

/** A spring-damper that acts only while the masses are closer than its threshold (its length). */
public final class Contact3D extends ElasticInteraction {
    Contact3D(ModelCore core, ModelLock gate, int id) {
        super(core, gate, id);
    }
}
