package tactus.haptics.passivity;

import tactus.PhysicalModel;
import tactus.Vect3D;
import tactus.paramSystem;
import tactus.haptics.AvatarLink;
import tactus.haptics.PhysicalModelAvatar;

/**
 * Test fixture: a {@link HapticPort} between a {@link SampledPlant} and a REAL_UNITS model whose avatar (no smoothing)
 * touches a wall, run tick by tick in simulated time as the haptic loop runs them: read the position, move the avatar,
 * step the model once, take its force, send it.
 */
final class PortRig {
    final SampledPlant plant;
    final HapticPort port = new HapticPort();
    final AvatarLink avatar;
    private final double[] target = new double[3];
    private final double[] force = new double[3];
    /** The force sent at the last tick, N. */
    double sent;

    PortRig(SampledPlant plant, AvatarLink avatar) {
        this.plant = plant;
        this.avatar = avatar;
    }

    /** Starts the port (and sets its delay to the plant's, and a damping limit for the plant's mass). */
    PortRig start(int delayTicks) {
        port.setDelay(delayTicks);
        // about m / (T (d + 1/2)) for the 0.15 kg of handle and hand, d = 1 (the loop's default suits a 0.02 kg 2DIY)
        port.setDampingLimit(50);
        port.start(plant.period);
        return this;
    }

    /**
     * A model with a wall normal to x at 0 (free space at x > 0) of stiffness K (N/m) and damping Z (N s/m per step,
     * the model's backward difference), touched by an avatar that starts at x0 (m).
     */
    static AvatarLink wall(double stiffness, double damping, double x0) {
        PhysicalModel pm = new PhysicalModel(1000, paramSystem.REAL_UNITS);
        pm.addHapticInput3D("avatar", new Vect3D(x0, 0, 0), 1);
        pm.addPlaneContact("wall", 0, stiffness, damping, 0, 0, "avatar");
        pm.init();
        return new PhysicalModelAvatar(pm, "avatar");
    }

    void tick() {
        port.sense(plant.x, 0, 0, target);
        avatar.setTarget(target[0], target[1], target[2]);
        avatar.step(1);
        avatar.takeForceCounted(force);
        port.command(force);
        port.sent(1);
        sent = force[0];
        plant.send(force[0]);
        plant.advance();
    }
}
