package tactus.hapticstability;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import tactus.haptics.emulator.PlantParameters;

/**
 * Stiff walls on the emulated Inverse3 (the generic 3-DoF plant) through the real haptic loop in lockstep
 * ({@link Inverse3WallRig}; each run is 2 s of simulated time and takes about as long: the loop runs at its own
 * rate so that its passivity port has the right period): the device-alone edge on an axis and on the 3-D diagonal
 * against {@link SampledWallTheory} with the emulator's exchange (d = 0), within 5 %; the passivity controller
 * holding a wall that is unstable without it; and at audio rate (the model in a PhyUGen at 44.1 kHz, rendered
 * offline in step with the ticks) the bound of one tick of delay, the observer equal to the plant's own record of
 * the work, and the controller still making the contact stable and passive.
 */
@Timeout(value = 150, unit = TimeUnit.SECONDS)
class Inverse3WallTest {
    private static final PlantParameters FULL = PlantParameters.cartesian3Dof();
    private static final double M = Inverse3WallSweep.mass(FULL);
    private static final double B = Inverse3WallSweep.damping(FULL);
    private static final double T = 0.001;

    private static Inverse3WallRig.Trace run(PlantParameters p, double[] dir, double k, boolean pc,
                                            Inverse3WallRig.Mode mode) {
        Inverse3WallRig.Config c = new Inverse3WallRig.Config();
        c.plant = p;
        c.direction = dir;
        c.stiffness = k;
        c.control = pc;
        c.dampingLimit = 100;
        c.mode = mode;
        Inverse3WallRig.Trace t = Inverse3WallRig.run(c);
        assertNull(t.failure, "the loop failed");
        assertEquals(c.ticks, t.n, "ticks recorded");
        return t;
    }

    @Test
    void theDeviceAloneEdgeMatchesTheSampledTheoryOnAnAxisAndOnTheDiagonal() {
        double theory = SampledWallTheory.stiffnessLimit(M, B, T, 0, 0);
        assertEquals(2 * B / T, theory, 0.01 * theory, "the d = 0 limit is about 2 b / T");
        PlantParameters linear = FULL.withoutFriction();
        for (double[] dir : new double[][] {Inverse3WallSweep.AXIS_Y, Inverse3WallSweep.DIAGONAL}) {
            String at = "direction " + java.util.Arrays.toString(dir);
            Inverse3WallRig.Trace below = run(linear, dir, 0.95 * theory, false, Inverse3WallRig.Mode.HAPTICS_ONLY);
            Inverse3WallRig.Trace above = run(linear, dir, 1.05 * theory, false, Inverse3WallRig.Mode.HAPTICS_ONLY);
            assertFalse(below.unstable(), "stable at 0.95 of the theory's edge, " + at);
            assertTrue(above.unstable(), "unstable at 1.05 of the theory's edge, " + at);
            // the isotropic plant keeps the motion on the wall's line, whatever the direction
            assertTrue(below.offLine < 1e-9, "off the line by " + below.offLine + " m, " + at);
            // the observer is the plant's record of the work, exactly (d = 0: the held force acts over the next tick)
            assertEquals(-below.work, below.net, 1e-12, "observer against plant, " + at);
        }
    }

    @Test
    void anActuationDelayOfOneTickMovesTheEdgeToTheTheorysOneTickLimit() {
        // the plant's torques act 1 ms after the command: the loop is the d = 1 one (333.6 N/m here); when the delay
        // acted one 50 us substep early the edge came out at 345.5 N/m, 3.6 % above, and 1.02 of the theory held
        double theory = SampledWallTheory.stiffnessLimit(M, B, T, 1, 0);
        PlantParameters delayed = FULL.withoutFriction().withActuationDelay(T);
        Inverse3WallRig.Trace below = run(delayed, Inverse3WallSweep.AXIS_Y, 0.98 * theory, false,
                Inverse3WallRig.Mode.HAPTICS_ONLY);
        Inverse3WallRig.Trace above = run(delayed, Inverse3WallSweep.AXIS_Y, 1.02 * theory, false,
                Inverse3WallRig.Mode.HAPTICS_ONLY);
        assertFalse(below.unstable(), "stable at 0.98 of the one-tick edge " + theory + " N/m");
        assertTrue(above.unstable(), "unstable at 1.02 of the one-tick edge " + theory + " N/m");
    }

    @Test
    void thePassivityControllerHoldsADiagonalWallThatIsUnstableWithoutIt() {
        double k = 4 * SampledWallTheory.stiffnessLimit(M, B, T, 0, 0);   // the edge with friction is 2.9 K0 here
        Inverse3WallRig.Trace off = run(FULL, Inverse3WallSweep.DIAGONAL, k, false, Inverse3WallRig.Mode.HAPTICS_ONLY);
        Inverse3WallRig.Trace on = run(FULL, Inverse3WallSweep.DIAGONAL, k, true, Inverse3WallRig.Mode.HAPTICS_ONLY);
        assertTrue(off.unstable(), "uncontrolled, " + k + " N/m on the diagonal buzzes");
        assertTrue(off.net < -1e-3, "uncontrolled, the wall gave the handle energy: net " + off.net + " J");
        assertFalse(on.unstable(), "with the controller it settles");
        assertTrue(on.dissipated > 0, "the controller dissipated");
        assertTrue(on.net > -0.5 * k * 1e-6 - 1e-9, "with the controller the handle gets back at most the step's own "
                + "spring energy: net " + on.net + " J");
    }

    @Test
    void atAudioRateTheBoundIsOneTickOfDelayAndTheControllerStillMakesTheWallPassive() {
        double theory1 = SampledWallTheory.stiffnessLimit(M, B, T, 1, 0);
        PlantParameters linear = FULL.withoutFriction();
        Inverse3WallRig.Trace below = run(linear, Inverse3WallSweep.AXIS_Y, 0.95 * theory1, false, Inverse3WallRig.Mode.AUDIO);
        Inverse3WallRig.Trace above = run(linear, Inverse3WallSweep.AXIS_Y, 1.05 * theory1, false, Inverse3WallRig.Mode.AUDIO);
        assertFalse(below.unstable(), "stable at 0.95 of the d = 1 edge");
        assertTrue(above.unstable(), "unstable at 1.05 of the d = 1 edge");
        double k = 3 * theory1;
        Inverse3WallRig.Trace off = run(FULL, Inverse3WallSweep.AXIS_Y, k, false, Inverse3WallRig.Mode.AUDIO);
        Inverse3WallRig.Trace on = run(FULL, Inverse3WallSweep.AXIS_Y, k, true, Inverse3WallRig.Mode.AUDIO);
        assertTrue(off.unstable(), "uncontrolled at audio rate, " + k + " N/m buzzes");
        assertFalse(on.unstable(), "with the controller it settles");
        assertTrue(on.net > -0.5 * k * 1e-6 - 1e-9, "passive with the controller: net " + on.net + " J");
        for (Inverse3WallRig.Trace t : new Inverse3WallRig.Trace[] {off, on}) {
            // in AUDIO mode the port still sees exactly the force that was held over each tick
            assertEquals(-t.work, t.net, 1e-9 * Math.max(1, Math.abs(t.work)), "observer against plant");
        }
    }
}
