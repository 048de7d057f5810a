package tactus.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;
import tactus.HapticInput3D;
import tactus.PhysicalModel;
import tactus.PosInput3D;
import tactus.Vect3D;
import tactus.paramSystem;

/**
 * HapticInput3D and PosInput3D are kinematic: each step X(n+1) = X(n) + (target - X(n)) / s, an exponentially
 * weighted moving average of weight 1/s, so X(n) - target = (X(0) - target) (1 - 1/s)^n whatever forces act
 * on them. The haptic avatar accumulates the force that links apply to it, one contribution per interaction
 * phase, until getHapticForce returns the sum and resets it; a PosInput3D reports no force.
 */
class InputModulesTest {

    private static void assertEwma(PhysicalModel pm, String name, Vect3D x0, Vect3D target, int s) {
        double decay = 1 - 1.0 / s;
        for (int n = 1; n <= 60; n++) {
            pm.computeStep();
            Vect3D p = pm.getMatPosition(name);
            double r = Math.pow(decay, n);
            // each step rounds X once (|X| < 4): the error stays below n ulps
            assertEquals(target.x + (x0.x - target.x) * r, p.x, 1e-15 * n, name + " x at step " + n);
            assertEquals(target.y + (x0.y - target.y) * r, p.y, 1e-15 * n, name + " y at step " + n);
            assertEquals(target.z + (x0.z - target.z) * r, p.z, 1e-15 * n, name + " z at step " + n);
        }
    }

    // EWMA with s = 4, with a stiff spring to a heavy mass attached: the avatar ignores the force.
    @Test
    void hapticInputFollowsTheTargetWithWeightOneOverS() {
        PhysicalModel pm = new PhysicalModel(1000, 30);
        Vect3D x0 = new Vect3D(0.5, -0.5, 1);
        HapticInput3D h = pm.addHapticInput3D("h", x0, 4);
        pm.addMass3D("m", 1, new Vect3D(0, 0, 0), new Vect3D(0, 0, 0));
        pm.addSpring3D("s", 0.2, 0.5, "h", "m");
        pm.init();
        Vect3D target = new Vect3D(1.5, 2, -0.25);
        h.setDevicePosition(target);
        assertEwma(pm, "h", x0, target, 4);
    }

    @Test
    void posInputFollowsTheTargetWithWeightOneOverS() {
        PhysicalModel pm = new PhysicalModel(1000, 30);
        Vect3D x0 = new Vect3D(2, 1, 0);
        PosInput3D d = pm.addPosInput3D("d", x0, 7);
        pm.addMass3D("m", 1, new Vect3D(0, 0, 0), new Vect3D(0, 0, 0));
        pm.addSpringDamper3D("s", 0.2, 0.5, 0.1, "d", "m");
        pm.init();
        Vect3D target = new Vect3D(-1, 3, 0.5);
        d.drivePosition(target);
        assertEwma(pm, "d", x0, target, 7);
    }

    // The avatar at rest 1 m below a ground, spring K = 200 N/m, rest 0.5 m: each interaction phase applies
    // K (d - l0) = 100 N towards the ground (+z). After 7 steps the accumulator holds 700 N; reading it
    // empties it, and 3 more steps give 300 N.
    @Test
    void hapticForceAccumulatesUntilReadThenResets() {
        PhysicalModel pm = new PhysicalModel(1000, 30, paramSystem.REAL_UNITS);
        HapticInput3D h = pm.addHapticInput3D("h", new Vect3D(0, 0, 0), 1);
        pm.addGround3D("g", new Vect3D(0, 0, 1));
        pm.addSpring3D("s", 0.5, 200, "h", "g");
        pm.init();
        pm.computeNSteps(7);
        Vect3D f = pm.getHapticForce("h");
        assertEquals(0.0, f.x, 0.0);
        assertEquals(0.0, f.y, 0.0);
        assertEquals(700.0, f.z, 1e-9);
        assertEquals(0.0, pm.getHapticForce("h").z, 0.0, "reading resets the accumulator");
        pm.computeNSteps(3);
        assertEquals(300.0, h.takeForce().z, 1e-9);
        // the avatar never moved: its target is where it started
        assertEquals(0.0, pm.getMatPosition("h").z, 0.0);
    }

    // A PosInput3D under the same spring is pushed just as hard, but it reports no force.
    @Test
    void posInputReportsNoForce() {
        PhysicalModel pm = new PhysicalModel(1000, 30, paramSystem.REAL_UNITS);
        pm.addPosInput3D("d", new Vect3D(0, 0, 0), 1);
        pm.addGround3D("g", new Vect3D(0, 0, 1));
        pm.addSpring3D("s", 0.5, 200, "d", "g");
        pm.init();
        pm.computeNSteps(7);
        Vect3D f = pm.getHapticForce("d");
        assertEquals(0.0, f.norm(), 0.0, "PosInput3D reported " + f);
        pm.computeNSteps(1);
        assertEquals(0.0, pm.getHapticForce("d").norm(), 0.0);
    }
}
