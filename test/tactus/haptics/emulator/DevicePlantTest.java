package tactus.haptics.emulator;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import tactus.haptics.Board;
import tactus.haptics.Device;
import tactus.haptics.HaplyPreset;
import tactus.haptics.pantograph.PantographKinematics;

/** The device plant: inertia, viscous damping, Coulomb friction with a static threshold, actuation delay. */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class DevicePlantTest {
    private static final double[] NO_FORCE = new double[3];

    private static DevicePlant axis(PlantParameters p) {
        return new DevicePlant(p, new CartesianPlantKinematics(1), new double[] {0});
    }

    @Test
    void aFrictionlessAxisAcceleratesAsForceOverMassAndDecaysAsDampingOverMass() {
        double m = 0.2;
        double b = 0.5;
        DevicePlant pl = axis(PlantParameters.cartesian3Dof().withoutFriction().withJointInertia(m).withJointDamping(b));
        pl.commandTorques(new double[] {1.0});
        double h = pl.parameters().substep();
        int steps = (int) Math.round(0.4 / h);
        for (int i = 0; i < steps; i++) {
            pl.step(h, NO_FORCE, 0);
        }
        // v(t) = F/b (1 - exp(-b t / m)) under a constant force F = 1 N
        double t = pl.time();
        double expected = 1.0 / b * (1 - Math.exp(-b * t / m));
        assertEquals(expected, pl.qd(0), 2e-3 * expected, "velocity under 1 N after " + t + " s");
        double v0 = pl.qd(0);
        pl.commandTorques(new double[] {0});
        for (int i = 0; i < steps; i++) {
            pl.step(h, NO_FORCE, 0);
        }
        assertEquals(v0 * Math.exp(-b * 0.4 / m), pl.qd(0), 2e-3 * v0, "free decay");
    }

    @Test
    void aTorqueBelowTheStaticThresholdDoesNotMoveAJointAndOneAboveSlidesAgainstCoulombFriction() {
        double m = 0.2;
        PlantParameters p = PlantParameters.cartesian3Dof().withJointInertia(m).withJointDamping(0).withFriction(0.05, 0.08);
        DevicePlant pl = axis(p);
        double h = p.substep();
        pl.commandTorques(new double[] {0.079});
        for (int i = 0; i < 2000; i++) {
            pl.step(h, NO_FORCE, 0);
        }
        assertEquals(0, pl.q(0), 0.0, "0.079 N against a static threshold of 0.08 N");
        assertEquals(0, pl.qd(0), 0.0);
        pl.commandTorques(new double[] {0.09});
        for (int i = 0; i < 2000; i++) {
            pl.step(h, NO_FORCE, 0);
        }
        // above the threshold it slides; the Coulomb friction 0.05 N leaves 0.04 N to accelerate it
        assertEquals((0.09 - 0.05) / m * pl.time() / 2, pl.qd(0), 0.01 * (0.04 / m * pl.time() / 2),
                "v = (F - Fc) / m * t after breaking away");
        // with no torque it slows down at Fc / m and stops, without reversing
        pl.commandTorques(new double[] {0});
        for (int i = 0; i < 20000; i++) {
            pl.step(h, NO_FORCE, 0);
        }
        assertEquals(0, pl.qd(0), 0.0, "stopped by friction");
        // an external force counts as a torque on the joint, as the hand's push does
        double q = pl.q(0);
        for (int i = 0; i < 2000; i++) {
            pl.step(h, new double[] {-0.07}, 0);
        }
        assertEquals(q, pl.q(0), 0.0, "-0.07 N from outside does not break it loose");
    }

    @Test
    void aTorqueActsFromExactlyTheActuationDelayOnRoundedUpToASubstep() {
        // delays of whole substeps and between them; the handle first moves in the substep that starts at the delay
        // (before the fix it moved one 50 us substep early: a 1 ms delay acted from 0.95 ms)
        double[] delays = {0, 5e-5, 4e-4, 5e-4, 1e-3, 2.5e-3, 1.02e-3};
        for (double delay : delays) {
            PlantParameters p = PlantParameters.cartesian3Dof().withoutFriction().withActuationDelay(delay);
            DevicePlant pl = axis(p);
            double h = p.substep();
            pl.commandTorques(new double[] {1});
            double[] v = new double[1];
            double movedFrom = Double.NaN;
            for (int i = 0; i < 200 && movedFrom != movedFrom; i++) {
                double start = pl.time();
                pl.step(h, NO_FORCE, 0);
                pl.velocity(v);
                if (v[0] != 0) {
                    movedFrom = start;
                }
            }
            double expected = Math.ceil(delay / h - 1e-9) * h;
            assertEquals(expected, movedFrom, 1e-12, "a torque commanded at 0 with an actuation delay of " + delay
                    + " s acts from the first substep starting at or after it");
        }
    }

    @Test
    void aPantographHandleHasTheTaskSpaceMassOfItsJointInertiaAndHandleMass() {
        PlantParameters p = PlantParameters.twoDiy().withoutFriction().withJointDamping(0);
        PantographPlantKinematics k = new PantographPlantKinematics(0.07, 0.09, 0.038);
        double[] q = new double[2];
        assertTrue(k.inverse(new double[] {0.019, 0.10}, q));
        DevicePlant pl = new DevicePlant(p, k, q);
        double fy = 0.1;
        double h = p.substep();
        pl.step(h, new double[] {0, fy}, 0);
        double[] v = new double[2];
        pl.velocity(v);
        // M_task = J^-T I J^-1 + m 1; along y at this pose
        double[] x = new double[2];
        double[] j = new double[4];
        k.forward(q, x, j);
        double det = j[0] * j[3] - j[1] * j[2];
        double[] inv = {j[3] / det, -j[1] / det, -j[2] / det, j[0] / det};   // J^-1
        // y-row of J^-T J^-1: sum_k (J^-1)_{k,1}^2
        double myy = p.jointInertia() * (inv[1] * inv[1] + inv[3] * inv[3]) + p.handleMass();
        double mxy = p.jointInertia() * (inv[0] * inv[1] + inv[2] * inv[3]);
        // a = M^-1 F with M = [[mxx, mxy], [mxy, myy]]
        double mxx = p.jointInertia() * (inv[0] * inv[0] + inv[2] * inv[2]) + p.handleMass();
        double d = mxx * myy - mxy * mxy;
        double ay = mxx * fy / d;
        double ax = -mxy * fy / d;
        assertEquals(ay, v[1] / h, 1e-6 * Math.abs(ay), "y acceleration");
        assertEquals(ax, v[0] / h, 1e-6 * Math.abs(ay) + 1e-9, "x acceleration");
    }

    @Test
    void theEmulatorWithAPlantSettlesASpringHeldHandleAtForceOverStiffness() {
        HaplyPreset preset = HaplyPreset.TWO_DIY_V3;
        BoardEmulator emulator = new BoardEmulator(preset);
        emulator.setLockstep(0.001);
        emulator.setPlant(PlantParameters.twoDiy().withoutFriction());
        double x0 = emulator.x();
        double y0 = emulator.y();
        double k = 200;
        emulator.setHand(Hand.grasp((t, out) -> {
            out[0] = x0;
            out[1] = y0;
        }, 0.05, k, 3));
        try (Board board = new Board(emulator.connect())) {
            // this test counts its own writes: a loaded machine can hold this thread back beyond the torque
            // watchdog's 50 ms, and the watchdog's zero torques are a write too (one more lockstep millisecond)
            board.setTorqueWatchdogMillis(0);
            Device dev = setUp(preset, board);
            pushFor(dev, preset.newKinematics(), 0.4, -0.2, 2000);
            assertEquals(0.4 / k, emulator.x() - x0, 0.03 * 0.4 / k, "x");
            assertEquals(-0.2 / k, emulator.y() - y0, 0.03 * 0.4 / k, "y");
            assertEquals(2.0, emulator.time(), 1e-9, "2000 writes of 1 ms");
        }
    }

    @Test
    void frictionHoldsTheHandleAgainstASmallForceAndNoHand() {
        HaplyPreset preset = HaplyPreset.TWO_DIY_V3;
        BoardEmulator emulator = new BoardEmulator(preset);
        emulator.setLockstep(0.001);
        emulator.setPlant(PlantParameters.twoDiy());
        emulator.setHand(Hand.none());
        double x0 = emulator.x();
        double y0 = emulator.y();
        try (Board board = new Board(emulator.connect())) {
            Device dev = setUp(preset, board);
            PantographKinematics kin = preset.newKinematics();
            pushFor(dev, kin, 0, 0.005, 100);   // N along y: below the joints' static threshold
            double small = Math.hypot(emulator.x() - x0, emulator.y() - y0);
            pushFor(dev, kin, 0, 0.3, 100);     // well above it
            double large = Math.hypot(emulator.x() - x0, emulator.y() - y0);
            assertEquals(0, small, 0.0, "5 mN does not break the joints loose");
            assertTrue(large > 1e-3, "0.3 N moves the handle: " + large + " m");
        }
    }

    @Test
    void theInverse3EmulatorWithACartesianPlantHoldsAgainstStaticFrictionAndSlidesAboveIt() {
        SimulatedInverse3 dev = new SimulatedInverse3();
        PlantParameters p = PlantParameters.cartesian3Dof();   // 0.2 kg, 0.5 N s/m, Coulomb 0.05 N, static 0.08 N
        dev.setPlant(p);
        double[] start = new double[3];
        dev.position(start);
        dev.setForce(0.07, 0, 0);
        dev.advance(0.2);
        double[] at = new double[3];
        dev.position(at);
        assertEquals(start[0], at[0], 0.0, "0.07 N is below the 0.08 N static threshold");
        dev.setForce(0.3, 0, 0);
        dev.advance(0.2);
        dev.position(at);
        double[] vel = new double[3];
        dev.velocity(vel);
        // (F - Fc) / b (1 - exp(-b t / m)) with F - Fc = 0.25 N
        double expected = 0.25 / 0.5 * (1 - Math.exp(-0.5 * 0.2 / 0.2));
        assertEquals(expected, vel[0], 0.01 * expected, "sliding under 0.3 N");
        assertEquals(0, vel[1], 0.0, "no force on y");
        // the box stops it: the plant follows the clamp
        dev.setForce(2, 0, 0);
        dev.advance(2.0);
        dev.position(at);
        assertEquals(SimulatedInverse3.HOME[0] + SimulatedInverse3.HALF_EXTENT[0], at[0], 1e-12, "at the wall");
        dev.velocity(vel);
        assertEquals(0, vel[0], 0.0, "at rest against the wall");
    }

    private static Device setUp(HaplyPreset preset, Board board) {
        Device dev = new Device((byte) 7, board);
        preset.configure(dev);
        dev.device_set_parameters();
        return dev;
    }

    /** Sends J^T F for a task-space force (N) at the measured pose for n ticks, as a sketch's loop does. */
    private static void pushFor(Device dev, PantographKinematics kin, double fx, double fy, int n) {
        double[] tau = new double[2];
        for (int i = 0; i < n; i++) {
            dev.device_read_data();
            kin.forward(Math.toRadians(dev.angle(1)), Math.toRadians(dev.angle(2)));
            kin.torques(fx, fy, 1.0, tau);
            dev.set_actuator_torque(1, (float) tau[0]);
            dev.set_actuator_torque(2, (float) tau[1]);
            dev.device_write_torques();
        }
    }

    @Test
    void parametersAreValidatedNamingTheValue() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> PlantParameters.twoDiy().withFriction(0.01, 0.005));
        assertTrue(e.getMessage().contains("static torque"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> PlantParameters.twoDiy().withJointDamping(-1));
        assertTrue(e.getMessage().contains("-1"), e.getMessage());
        assertFalse(new BoardEmulator(HaplyPreset.TWO_DIY_V3).place(1.0, 1.0), "out of reach");
    }
}
