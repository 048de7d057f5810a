package tactus.haptics;

import tactus.PhysicalModel;
import tactus.Vect3D;

/**
 * {@link AvatarLink} over the public {@link PhysicalModel} API: a HapticInput3D avatar by name, positioned
 * with {@code setHapticPosition} and read with {@code getHapticForce}. The only class to change when the
 * model's haptic API changes. Nothing here allocates per tick.
 */
public final class PhysicalModelAvatar implements AvatarLink {
    private final PhysicalModel model;
    private final String avatar;
    private final Vect3D target = new Vect3D();
    private final Vect3D force = new Vect3D();

    /** Links to the avatar (a HapticInput3D) of this name in the model. */
    public PhysicalModelAvatar(PhysicalModel model, String avatar) {
        if (model == null) {
            throw new IllegalArgumentException("PhysicalModelAvatar: model must not be null");
        }
        if (avatar == null || avatar.isEmpty()) {
            throw new IllegalArgumentException("PhysicalModelAvatar: avatar name must be a non-empty string, got "
                    + (avatar == null ? "null" : "\"\""));
        }
        this.model = model;
        this.avatar = avatar;
        model.getHapticForce(avatar);   // fails now, naming the avatar, if it is not an input module
    }

    @Override
    public void setTarget(double x, double y, double z) {
        target.set(x, y, z);
        model.setHapticPosition(avatar, target);
    }

    @Override
    public void takeForce(double[] out) {
        takeForceCounted(out);
    }

    /**
     * The force summed since the last call and the number of steps it covers, read together (also while another
     * thread steps the model in realtime, as a PhyUGen does).
     */
    @Override
    public long takeForceCounted(double[] out) {
        long n = model.getHapticForceCounted(avatar, force);
        out[0] = force.x;
        out[1] = force.y;
        out[2] = force.z;
        return n;
    }

    @Override
    public void step(int n) {
        model.computeNSteps(n);
    }
}
