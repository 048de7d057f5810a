package tactus;

import tactus.internal.realtime.ModelLock;
import tactus.internal.ModelCore;

/** A spring-damper along z only, on the signed difference z1 - z2. */
public final class SpringDamper1D extends ElasticInteraction {
    SpringDamper1D(ModelCore core, ModelLock gate, int id) {
        super(core, gate, id);
    }
}
