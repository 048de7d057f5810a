package tactus;

import tactus.internal.realtime.ModelLock;
import tactus.internal.ModelCore;

/**
 * A kinematic position driver: it follows a target position through an exponentially weighted
 * moving average and pushes whatever it is linked to. It reports no force.
 */
public final class PosInput3D extends Mass {
    PosInput3D(ModelCore core, ModelLock gate, int id) {
        super(core, gate, id);
    }

    /** Sets the target position the driver follows, in model units. */
    public void drivePosition(Vect3D pos) {
        checkVector("drivePosition", "pos", pos);
        enter();
        try {
            core.state.setInputTarget(id, pos.x, pos.y, pos.z);
        } finally {
            exit();
        }
    }
}
