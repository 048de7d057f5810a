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
    /** True while this link has put the model in realtime stepping for the haptic loop thread. */
    private volatile boolean stepsInRealtime;

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
        if (stepsInRealtime) {
            model.takeRealtimeStepping();   // one volatile read once the loop thread holds the role
        }
        model.computeNSteps(n);
    }

    /**
     * Puts the model in realtime stepping ({@link PhysicalModel#beginRealtimeStepping()}) with the haptic loop
     * thread as its stepping thread, unless it is already stepped in realtime by someone else (then the loop steps
     * it as before). The loop thread then never takes the model's lock: a {@code draw()} or another thread that
     * reads or changes the model while the machine is loaded can no longer hold a tick up (a reader preempted
     * while it held the lock delayed ticks by up to 498 ms under load; see docs/haptics.md). Other threads' changes
     * are queued and applied by the loop thread between two steps, as for a PhyUGen.
     */
    @Override
    public void beginStepping() {
        if (!model.isRealtimeStepping()) {
            model.beginRealtimeStepping();
            stepsInRealtime = true;
        }
    }

    /** Returns the model to the locked mode if {@link #beginStepping()} put it in realtime stepping. */
    @Override
    public void endStepping() {
        if (stepsInRealtime) {
            stepsInRealtime = false;
            model.endRealtimeStepping();
        }
    }
}
