package tactus;

/**
 * A kinematic position driver: it follows a target position through an exponentially weighted
 * moving average and pushes whatever it is linked to. It reports no force.
 */
public final class PosInput3D extends Mass {
    PosInput3D(PhysicalModel model, int id) {
        super(model, id);
    }

    /** Sets the target position the driver follows, in model units. */
    public void drivePosition(Vect3D pos) {
        checkVector("drivePosition", "pos", pos);
        model.enter(this);
        try {
            model.core.state.setInputTarget(id, pos.x, pos.y, pos.z);
        } finally {
            model.exit();
        }
    }
}
