package tactus;


/**
 * The haptic avatar: a mass-type module whose position follows the device position through an
 * exponentially weighted moving average (weight 1/smoothing per step) and which accumulates the
 * force the model applies to it, over as many steps as run, until {@link #takeForce()} reads it.
 */
public final class HapticInput3D extends Mass {
    HapticInput3D(ModuleHandles handles, int id, int stamp) {
        super(handles, id, stamp);
    }

    /** Sets the device position the avatar follows, in model units. */
    public void setDevicePosition(Vect3D pos) {
        checkVector("setDevicePosition", "pos", pos);
        calls.setInputTarget(id, stamp, pos);
    }

    /** {@return the force accumulated since the last call (REAL_UNITS: N), and resets the accumulator} */
    public Vect3D takeForce() {
        return takeForce(new Vect3D());
    }

    /**
     * Writes the force accumulated since the last call (REAL_UNITS: N) into {@code out} without allocating,
     * resets the accumulator, and returns {@code out}.
     */
    public Vect3D takeForce(Vect3D out) {
        checkValid();
        return calls.takeAvatarForce(id, stamp, out);
    }
}
