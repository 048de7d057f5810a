package tactus;

import tactus.internal.realtime.ModelLock;
import tactus.internal.ModelCore;

/** Keeps the first mass within a radius (its length) of the second: a spring-damper that acts only outside it. */
public final class Bubble3D extends ElasticInteraction {
    Bubble3D(ModelCore core, ModelLock gate, int id) {
        super(core, gate, id);
    }
}
