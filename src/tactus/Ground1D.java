package tactus;

import tactus.internal.realtime.ModelLock;
import tactus.internal.ModelCore;

/** A fixed point for 1D models. */
public final class Ground1D extends Mass {
    Ground1D(ModelCore core, ModelLock gate, int id) {
        super(core, gate, id);
    }
}
