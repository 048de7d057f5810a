package tactus;

import tactus.internal.realtime.ModelLock;
import tactus.internal.ModelCore;

/** A fixed point in 3D: interactions act on it but it never moves. */
public final class Ground3D extends Mass {
    Ground3D(ModelCore core, ModelLock gate, int id) {
        super(core, gate, id);
    }
}
