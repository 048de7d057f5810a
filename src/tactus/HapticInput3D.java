package tactus;

/**
 * The haptic avatar: a mass-type module whose position follows the device position through an
 * exponentially weighted moving average (weight 1/smoothing per step) and which accumulates the
 * force the model applies to it, over as many steps as run, until {@link #takeForce()} reads it.
 */
public final class HapticInput3D extends Mass {
    HapticInput3D(PhysicalModel model, int id) {
        super(model, id);
    }

    /** Sets the device position the avatar follows, in model units. */
    public void setDevicePosition(Vect3D pos) {
        checkValid();
        model.setHapticPosition(model.massName(id), pos);
    }

    /** @return the force accumulated since the last call (REAL_UNITS: N), and resets the accumulator. */
    public Vect3D takeForce() {
        checkValid();
        return model.getHapticForce(model.massName(id));
    }
}
