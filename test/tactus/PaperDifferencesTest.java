package tactus;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * The places where Tactus follows the paper's words instead of the original engine's behaviour, as listed in
 * docs/coming-from-miphysics.md: each checked against the scheme's closed form.
 */
class PaperDifferencesTest {
    private static Vect3D v(double x, double y, double z) {
        return new Vect3D(x, y, z);
    }

    @Test
    void oneDimensionalMassesFeelGravityAlongZ() {
        PhysicalModel m = new PhysicalModel(100, 50);
        m.addMass1D("m", 1, v(0, 0, 0), v(0, 0, 0));
        m.setGravity(0.01);   // per step squared, ALGO_UNITS
        m.init();
        int n = 10;
        m.computeNSteps(n);
        // free fall in the scheme: z(n) = -g n (n + 1) / 2
        assertEquals(-0.01 * n * (n + 1) / 2, m.getMatPosition("m").z, 1e-15);
    }

    @Test
    void anOscillatorAddedAfterSetFrictionFeelsIt() {
        PhysicalModel a = new PhysicalModel(1000, 50);
        a.setFriction(0.01);
        a.addOsc3D("o", 1, 0.1, 0, v(0, 0, 0), v(100, 0, 0));
        PhysicalModel b = new PhysicalModel(1000, 50);
        b.addOsc3D("o", 1, 0.1, 0, v(0, 0, 0), v(100, 0, 0));
        b.setFriction(0.01);
        a.computeNSteps(500);
        b.computeNSteps(500);
        assertEquals(b.getMatPosition("o").x, a.getMatPosition("o").x, 0.0);
        assertTrue(Math.abs(a.getMatPosition("o").x) < 0.1, "damped by the friction");
    }

    @Test
    void changingAnOscillatorStiffnessChangesItsPitch() {
        PhysicalModel m = new PhysicalModel(1000, 50);
        m.addOsc3D("o", 1, 0.1, 0, v(0, 0, 0), v(0, 0, 0));
        double before = m.getOscFrequency("o");
        m.setMatStiffness("o", 0.4);
        double after = m.getOscFrequency("o");
        // f = fs / 2pi acos(1 - K / 2M)
        assertEquals(1000 / (2 * Math.PI) * Math.acos(1 - 0.4 / 2), after, 1e-9);
        assertTrue(after > 1.9 * before);
        // and the motion follows: one period of the new pitch brings it back
        m.setMatPosition("o", v(1, 0, 0));
        double period = 2 * Math.PI / Math.acos(1 - 0.4 / 2);
        int steps = (int) Math.round(period * 10);
        m.computeNSteps(steps);
        // x(n) = (2 - K) x(n-1) - x(n-2) from x(0) = x(-1) = 1: x(n) = cos((n + 1/2) w) / cos(w / 2)
        double w = Math.acos(1 - 0.4 / 2);
        assertEquals(Math.cos((steps + 0.5) * w) / Math.cos(w / 2), m.getMatPosition("o").x, 1e-9);
    }

    @Test
    void gravityDirectionTakesEffectAtOnce() {
        PhysicalModel m = new PhysicalModel(100, 50);
        m.addMass3D("m", 1, v(0, 0, 0), v(0, 0, 0));
        m.setGravity(0.01);
        m.setGravityDirection(v(1, 0, 0));   // no setGravity afterwards
        m.computeStep();
        assertEquals(-0.01, m.getMatPosition("m").x, 1e-18);
        assertEquals(0, m.getMatPosition("m").z, 0.0);
    }

    @Test
    void aLinkAddedAfterInitStartsAtRest() {
        PhysicalModel m = new PhysicalModel(1000, 50);
        m.addGround3D("g", v(0, 0, 0));
        m.addMass3D("a", 1, v(2, 0, 0), v(0, 0, 0));
        m.init();
        m.computeNSteps(10);
        m.addDamper3D("d", 0.5, "a", "g");   // a pure damper between two masses at rest: no force at all
        m.computeNSteps(3);
        assertEquals(2, m.getMatPosition("a").x, 0.0);
        assertEquals(0, m.getMatForce("a").x, 0.0);
    }

    @Test
    void aPlaneContactsFirstStepUsesTheRealPreviousCoordinate() {
        PhysicalModel m = new PhysicalModel(1000, 50);
        m.addMass3D("a", 1, v(0, 5, 0), v(0, 0, 0));
        m.init();
        m.computeNSteps(5);
        // a mass at rest 0.05 inside a plane: the first force is the spring alone, -K t (no damping kick)
        m.addPlaneContact("floor", 0, 0.1, 0.3, 1, 5.05, "a");
        m.computeStep();
        assertEquals(0.1 * 0.05, m.getMatForce("a").y, 1e-15);
    }

    @Test
    void drawPhysicsLosesNoStepAt1000HzAnd60Fps() {
        PhysicalModel m = new PhysicalModel(1000, 60);
        m.addMass3D("a", 1, v(0, 0, 0), v(0, 0, 0));
        m.init();
        for (int frame = 0; frame < 600; frame++) {
            m.draw_physics();
        }
        assertEquals(10_000, m.getStepCount(), "ten seconds of frames, ten thousand steps");
    }

    @Test
    void movingAMassByHandDoesNotKickItsDampers() {
        PhysicalModel m = new PhysicalModel(1000, 50);
        m.addGround3D("g", v(0, 0, 0));
        m.addMass3D("a", 1, v(1, 0, 0), v(0, 0, 0));
        m.addDamper3D("d", 0.5, "a", "g");
        m.init();
        m.computeNSteps(3);
        m.setMatPosition("a", v(3, 0, 0));
        m.computeStep();
        assertEquals(0, m.getMatForce("a").x, 0.0, "the jump of 2 is not taken for a velocity");
        assertEquals(3, m.getMatPosition("a").x, 0.0);
    }
}
