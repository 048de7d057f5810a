package tactus;


/**
 * A kinematic position driver: it follows a target position through an exponentially weighted
 * moving average and pushes whatever it is linked to. It reports no force.
 */
public final class PosInput3D extends Mass {
    PosInput3D(ModuleHandles handles, int id, int stamp) {
        super(handles, id, stamp);
    }

    /** Sets the target position the driver follows, in model units. */
    public void drivePosition(Vect3D pos) {
        checkVector("drivePosition", "pos", pos);
        calls.setInputTarget(id, stamp, pos);
    }
}
