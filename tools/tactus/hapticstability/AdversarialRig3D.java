package tactus.hapticstability;

import java.util.function.Consumer;
import tactus.PhysicalModel;
import tactus.PlaneContact3D;
import tactus.Vect3D;
import tactus.haptics.HapticLoop;
import tactus.haptics.PhysicalModelAvatar;
import tactus.haptics.WorkspaceMapping;
import tactus.haptics.emulator.Hand3D;
import tactus.haptics.emulator.PlantParameters;
import tactus.haptics.emulator.SimulatedInverse3;
import tactus.paramSystem;

/**
 * Runs one {@link AdversarialCase} on the emulated 3-DoF device instead of the 2DIY: the real {@link HapticLoop} on
 * the device path with the emulated Inverse3 on its Cartesian plant ({@link PlantParameters#cartesian3Dof}: 0.2 kg,
 * 0.5 N s/m and 0.05 N of Coulomb friction per axis, or without the friction) in lockstep ({@link LockstepInverse3}:
 * a zero-order hold, no tick of delay, positions not quantised), the same REAL_UNITS model (the avatar and a
 * one-sided plane wall along y at the start pose) and the same scripted scene; measured by
 * {@link AdversarialRig#measure} from the plant's record at every 50 µs substep.
 *
 * <p>The grasp is {@link Hand3D#followingScript}: the case's grip's spring and damper (the damper on the handle's
 * velocity, not on its velocity relative to the script) with no mass of its own, so the hand's mass is the plant's.
 * Simulated time: the device advances by one period per tick on the loop's thread, and the scene's change is made
 * at a fixed tick as in {@link AdversarialRig}.
 */
public final class AdversarialRig3D {
    /** The tick period, seconds. */
    public static final double PERIOD = 0.001;

    private AdversarialRig3D() {
    }

    /** Runs the case with the loop configured by the configuration under test (called before the loop starts). */
    public static AdversarialRig.Result run(AdversarialCase c, Consumer<HapticLoop> configuration) {
        return run(c, configuration, PlantParameters.cartesian3Dof());
    }

    /**
     * Runs the case on another Cartesian plant (its mass, damping and friction per axis; the friction is dropped for a
     * case without friction), with the loop configured by the configuration under test.
     */
    public static AdversarialRig.Result run(AdversarialCase c, Consumer<HapticLoop> configuration,
                                            PlantParameters withFriction) {
        PlantParameters plant = c.friction ? withFriction : withFriction.withoutFriction();
        int rate = (int) Math.round(1 / PERIOD);
        int perTick = (int) Math.round(PERIOD / plant.substep());
        int ticks = (int) Math.ceil(c.duration() / PERIOD);
        double[] home = SimulatedInverse3.HOME;
        SimulatedInverse3 sim = new SimulatedInverse3();
        sim.setPlant(plant);
        LockstepInverse3 device = new LockstepInverse3(sim, PERIOD);
        AdversarialRig.Record rec = new AdversarialRig.Record((ticks + 20) * perTick + 16);
        AdversarialRig.Result r = new AdversarialRig.Result(c);
        double tStart = sim.time();
        Hand3D.Script script = scene(c, home, tStart);
        sim.setHand(Hand3D.followingScript(script, c.grip.stiffness, c.grip.damping));
        sim.setProbe((t, p, v, hand) -> {
            int i = rec.n;
            if (i < rec.t.length) {
                rec.t[i] = t - tStart;
                rec.y[i] = p[1] - home[1];
                rec.vx[i] = v[0];
                rec.vy[i] = v[1];
                rec.vz[i] = v[2];
                rec.fx[i] = hand[0];
                rec.fy[i] = hand[1];
                rec.fz[i] = hand[2];
                rec.n = i + 1;
            }
        });
        PhysicalModel pm = new PhysicalModel(rate, paramSystem.REAL_UNITS);
        pm.addHapticInput3D("avatar", new Vect3D(home[0], home[1], home[2]), 1);
        PlaneContact3D wall = pm.addPlaneContact("wall", 0, c.initialStiffness(), 0, 1, home[1] - c.initialGap(),
                "avatar");
        pm.init();
        double eventAt = c.eventTime();
        AdversarialRig.Watch watch = new AdversarialRig.Watch(new PhysicalModelAvatar(pm, "avatar"), sim::time,
                tStart, Double.isNaN(eventAt) ? Double.POSITIVE_INFINITY : eventAt, ticks * PERIOD, ticks + 20);
        HapticLoop loop = new HapticLoop(device, watch);
        loop.setWorkspaceMapping(WorkspaceMapping.identity());   // the model's metres are the device's
        loop.setForceGain(1);
        loop.setHeapWarmup(false);
        AdversarialRig.drive(loop, rate, configuration, watch, sim::time, tStart + (ticks + 2) * PERIOD,
                () -> AdversarialRig.change(c, pm, wall, home[1] - c.gap(), () -> sim.setHand(Hand3D.none())), r,
                "AdversarialRig3D");
        sim.setProbe(null);
        loop.close();
        rec.n = Math.min(rec.n, ticks * perTick);
        AdversarialRig.measure(c, rec, watch, r, plant.jointInertia());
        return r;
    }

    /** The case's intended motion in the device's axes: the 2DIY script's y, from the home position. */
    private static Hand3D.Script scene(AdversarialCase c, double[] home, double tStart) {
        tactus.haptics.emulator.Hand.Script planar = c.script(home[0], home[1], tStart);
        double[] xy = new double[2];
        return (t, out) -> {
            planar.at(t, xy);
            out[0] = xy[0];
            out[1] = xy[1];
            out[2] = home[2];
        };
    }
}
