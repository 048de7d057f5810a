package tactus;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** Gravity magnitude and direction, air friction: the API and their effect. */
class GravityApiTest {
    static Vect3D v(double x, double y, double z) {
        return new Vect3D(x, y, z);
    }

    @Test
    void defaultsAreNoGravityNoFrictionAndDirectionPlusZ() {
        PhysicalModel m = new PhysicalModel(1000);
        assertEquals(0.0, m.getGravity(), 0.0);
        assertEquals(0.0, m.getFriction(), 0.0);
        Vect3D d = m.getGravityDirection();
        assertEquals(0.0, d.x, 0.0);
        assertEquals(0.0, d.y, 0.0);
        assertEquals(1.0, d.z, 0.0);
    }

    @Test
    void setAndGet() {
        PhysicalModel m = new PhysicalModel(1000);
        m.setGravity(0.25);
        m.setFriction(0.125);
        assertEquals(0.25, m.getGravity(), 0.0);
        assertEquals(0.125, m.getFriction(), 0.0);
        m.setGravity(-0.5);   // a negative magnitude is allowed: it reverses gravity
        assertEquals(-0.5, m.getGravity(), 0.0);
    }

    @Test
    void directionIsNormalisedAndACopy() {
        PhysicalModel m = new PhysicalModel(1000);
        Vect3D in = v(3, 0, -4);
        m.setGravityDirection(in);
        Vect3D d = m.getGravityDirection();
        assertEquals(0.6, d.x, 1e-15);
        assertEquals(0.0, d.y, 0.0);
        assertEquals(-0.8, d.z, 1e-15);
        assertEquals(1.0, d.norm(), 1e-15);
        assertEquals(3.0, in.x, 0.0, "the argument is not modified");
        d.x = 100;
        assertEquals(0.6, m.getGravityDirection().x, 1e-15, "the getter returns a copy");
        m.setGravityDirection(v(0, 1e-30, 0));   // tiny but non-zero is fine
        assertEquals(1.0, m.getGravityDirection().y, 0.0);
    }

    @Test
    void directionRejectsZeroAndNonFiniteAndKeepsThePreviousOne() {
        PhysicalModel m = new PhysicalModel(1000);
        m.setGravityDirection(v(0, 2, 0));
        assertThrows(IllegalArgumentException.class, () -> m.setGravityDirection(v(0, 0, 0)));
        assertThrows(IllegalArgumentException.class, () -> m.setGravityDirection(v(Double.NaN, 0, 1)));
        assertThrows(IllegalArgumentException.class, () -> m.setGravityDirection(v(0, Double.POSITIVE_INFINITY, 0)));
        assertThrows(IllegalArgumentException.class, () -> m.setGravityDirection((Vect3D) null));
        assertThrows(IllegalArgumentException.class, () -> m.setGravity(Double.NaN));
        assertThrows(IllegalArgumentException.class, () -> m.setFriction(Double.NEGATIVE_INFINITY));
        assertEquals(1.0, m.getGravityDirection().y, 0.0);
        assertEquals(0.0, m.getGravity(), 0.0);
    }

    @Test
    void defaultDirectionMakesMassesFallTowardMinusZIndependentlyOfTheirMass() {
        PhysicalModel m = new PhysicalModel(1000);   // ALGO: g is a displacement per step^2
        double g = 1e-6;
        m.setGravity(g);
        m.addMass3D("light", 0.1, v(0, 0, 0), v(0, 0, 0));
        m.addMass3D("heavy", 100, v(1, 0, 0), v(0, 0, 0));
        m.addGround3D("fixed", v(2, 0, 0));
        m.init();
        for (int n = 1; n <= 50; n++) {
            m.computeStep();
            double expected = -g * n * (n + 1) / 2.0;   // z(n+1) = 2z(n) - z(n-1) - g
            assertEquals(expected, m.getMatPosition("light").z, 1e-16, "step " + n);
            assertEquals(expected, m.getMatPosition("heavy").z, 1e-16, "step " + n);
        }
        assertEquals(0.0, m.getMatPosition("fixed").z, 0.0);
        assertEquals(0.0, m.getMatPosition("light").x, 0.0);
        assertEquals(0.0, m.getMatPosition("light").y, 0.0);
    }

    @Test
    void realUnitGravityIsAnAccelerationInMetresPerSecondSquared() {
        int fs = 1000;
        PhysicalModel m = new PhysicalModel(fs, 60, paramSystem.REAL_UNITS);
        m.setGravity(9.81);
        m.addMass3D("a", 2, v(0, 0, 10), v(0, 0, 0));
        m.init();
        m.computeNSteps(fs);   // one second
        // discrete free fall: z(n) = z0 - g dt^2 n (n + 1) / 2, i.e. g t^2 / 2 plus half a step of g dt t
        assertEquals(10 - 9.81 / (fs * (double) fs) * fs * (fs + 1) / 2.0, m.getMatPosition("a").z, 1e-9);
        assertEquals(10 - 9.81 / 2, m.getMatPosition("a").z, 9.81 / fs);
        assertEquals(-9.81, m.getMatVelocity("a").z, 9.81 / fs);
    }

    @Test
    void directionSelectsTheFallAxisAndChangesApplyToExistingMasses() {
        PhysicalModel m = new PhysicalModel(1000);
        m.addMass3D("a", 1, v(0, 0, 0), v(0, 0, 0));
        m.addMass2DPlane("p", 1, v(0, 0, 5), v(0, 0, 0));
        m.addMass1D("l", 1, v(0, 0, 0), v(0, 0, 0));
        m.init();
        m.setGravityDirection(v(-2, 0, 0));   // "up" is -x: masses fall toward +x
        m.setGravity(1e-4);
        m.computeNSteps(10);
        double fall = 1e-4 * 10 * 11 / 2;
        assertEquals(fall, m.getMatPosition("a").x, 1e-15);
        assertEquals(0.0, m.getMatPosition("a").z, 0.0);
        assertEquals(fall, m.getMatPosition("p").x, 1e-15);
        assertEquals(5.0, m.getMatPosition("p").z, 0.0, "a 2D plane mass stays on its plane");
        assertEquals(0.0, m.getMatPosition("l").x, 0.0, "a 1D mass moves along z only");
        assertEquals(0.0, m.getMatPosition("l").z, 0.0);
        // switch gravity off: constant velocity from here
        m.setGravity(0);
        Vect3D v0 = m.getMatVelocity("a");
        m.computeNSteps(10);
        assertEquals(v0.x, m.getMatVelocity("a").x, 1e-12);
    }

    @Test
    void frictionDecaysVelocityGeometricallyAndDependsOnMass() {
        PhysicalModel m = new PhysicalModel(1000);
        m.addMass3D("a", 2, v(0, 0, 0), v(1000, 0, 0));   // 1 unit per step
        m.addMass3D("b", 4, v(0, 1, 0), v(1000, 0, 0));
        m.setFriction(0.02);
        m.init();
        m.computeNSteps(100);
        // displacement per step retained: (1 - f/M)
        assertEquals(Math.pow(1 - 0.02 / 2, 100) * 1000, m.getMatVelocity("a").x, 1e-9);
        assertEquals(Math.pow(1 - 0.02 / 4, 100) * 1000, m.getMatVelocity("b").x, 1e-9);
        // friction set before adding a mass applies to it as well
        m.addMass3D("c", 2, v(0, 2, 0), v(1000, 0, 0));
        m.computeNSteps(100);
        assertEquals(Math.pow(1 - 0.02 / 2, 100) * 1000, m.getMatVelocity("c").x, 1e-9);
        m.setFriction(0);
        Vect3D before = m.getMatVelocity("c");
        m.computeNSteps(10);
        assertEquals(before.x, m.getMatVelocity("c").x, 1e-9);
    }

    @Test
    void realUnitFrictionIsNewtonSecondsPerMetre() {
        int fs = 2000;
        PhysicalModel m = new PhysicalModel(fs, 60, paramSystem.REAL_UNITS);
        m.addMass3D("a", 0.5, v(0, 0, 0), v(2, 0, 0));
        m.setFriction(0.25);   // c / M = 0.5 1/s: v(t) = v0 exp(-0.5 t)
        m.init();
        m.computeNSteps(fs);
        assertEquals(2 * Math.pow(1 - 0.25 / fs / 0.5, fs), m.getMatVelocity("a").x, 1e-9);
        assertEquals(2 * Math.exp(-0.5), m.getMatVelocity("a").x, 2e-4);
    }

    /** "Normalises": the stored direction has unit length whatever the magnitude of a finite, non-zero input. */
    @Test
    void directionIsNormalisedForExtremeMagnitudes() {
        PhysicalModel m = new PhysicalModel(1000);
        m.setGravityDirection(v(1e200, 0, 1e200));
        Vect3D d = m.getGravityDirection();
        assertEquals(1.0, d.norm(), 1e-15, "huge input gave " + d);
        assertEquals(Math.sqrt(0.5), d.x, 1e-15);
        m.setGravityDirection(v(0, -3e-200, 0));   // not the zero vector
        d = m.getGravityDirection();
        assertEquals(-1.0, d.y, 1e-15, "tiny input gave " + d);
    }

    @Test
    void constructorDefaults() {
        PhysicalModel a = new PhysicalModel(1000);
        assertEquals(1000, a.getSimRate());
        assertEquals(30, a.getDisplayRate());
        assertEquals(paramSystem.ALGO_UNITS, a.getParamSystem());
        PhysicalModel b = new PhysicalModel(500, paramSystem.REAL_UNITS);
        assertEquals(30, b.getDisplayRate());
        assertEquals(paramSystem.REAL_UNITS, b.getParamSystem());
        PhysicalModel c = new PhysicalModel(500, 25);
        assertEquals(25, c.getDisplayRate());
        assertEquals(paramSystem.ALGO_UNITS, c.getParamSystem());
        assertEquals(0L, c.getStepCount());
    }

    @Test
    void drawPhysicsCarriesTheFractionalRemainder() {
        PhysicalModel m = new PhysicalModel(1000, 60);
        m.addMass3D("a", 1, v(0, 0, 0), v(0, 0, 0));
        m.init();
        long total = 0;
        for (int frame = 1; frame <= 600; frame++) {
            int n = m.draw_physics();
            assertTrue(n == 16 || n == 17, "frame " + frame + ": " + n);
            total += n;
            assertEquals((long) Math.floor(frame * 1000.0 / 60 + 1e-9), total, "after frame " + frame);
        }
        assertEquals(10000, m.getStepCount());
        m.setDisplayRate(1000);
        assertEquals(1, m.draw_physics());
        m.setDisplayRate(3000);   // slower simulation than display: some frames run no step
        int sum = 0;
        for (int i = 0; i < 30; i++) {
            sum += m.draw_physics();
        }
        assertEquals(10, sum);
    }
}
