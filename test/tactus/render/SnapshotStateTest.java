package tactus.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

import tactus.ModelSnapshot;
import tactus.PhysicalModel;
import tactus.Vect3D;
import tactus.paramSystem;

/**
 * What the renderer colours and draws arrows with: the velocities and forces in the model's snapshot. Expected
 * values come from the model's equations at the snapshot's own positions (a spring of stiffness K and length l0
 * pulls with K (d - l0)), never from a previous run.
 */
class SnapshotStateTest {
    private static final double EPS = 1e-12;

    @Test
    void aFreeMassCarriesItsVelocityInUnitsPerSecond() {
        PhysicalModel m = new PhysicalModel(1000, 50);
        m.addMass3D("m", 1, new Vect3D(0, 0, 0), new Vect3D(30, -12, 4));
        m.init();
        m.getSnapshot().requestMotion(true);
        m.computeNSteps(35);
        ModelSnapshot s = m.getSnapshot();
        assertEquals(30, s.vx(0), 1e-9);
        assertEquals(-12, s.vy(0), 1e-9);
        assertEquals(4, s.vz(0), 1e-9);
        assertEquals(Math.sqrt(900 + 144 + 16), s.speed(0), 1e-9);
    }

    @Test
    void aMassOnASpringCarriesTheSpringForceAtItsSnapshotPosition() {
        double k = 0.01;
        double l0 = 1;
        PhysicalModel m = new PhysicalModel(1000, 50);
        m.addGround3D("g", new Vect3D(0, 0, 0));
        m.addMass3D("m", 5, new Vect3D(3, 4, 0), new Vect3D());
        m.addSpring3D("s", l0, k, "g", "m");
        m.init();
        m.getSnapshot().requestMotion(true);
        for (int frame = 0; frame < 5; frame++) {
            m.computeNSteps(10 + 7 * frame);
            ModelSnapshot s = m.getSnapshot();
            double dx = s.x(1) - s.x(0);
            double dy = s.y(1) - s.y(0);
            double d = Math.hypot(dx, dy);
            double f = -k * (d - l0);   // along the unit vector from the ground to the mass
            assertEquals(f * dx / d, s.fx(1), EPS, "frame " + frame);
            assertEquals(f * dy / d, s.fy(1), EPS, "frame " + frame);
            assertEquals(0, s.fz(1), EPS);
            assertEquals(Math.abs(f), s.forceNorm(1), EPS);
            assertEquals(0, s.forceNorm(0), 0, "a fixed point has no force");
            assertEquals(0, s.speed(0), 0, "a fixed point does not move");
        }
    }

    @Test
    void inRealUnitsTheForceIsInNewtons() {
        double k = 300;   // N/m
        double l0 = 0.1;  // m
        PhysicalModel m = new PhysicalModel(1000, 50, paramSystem.REAL_UNITS);
        m.addGround3D("g", new Vect3D(0, 0, 0));
        m.addMass3D("m", 1000, new Vect3D(0, 0.3, 0), new Vect3D());   // heavy: it hardly moves in 10 steps
        m.addSpring3D("s", l0, k, "g", "m");
        m.init();
        m.getSnapshot().requestMotion(true);
        m.computeNSteps(10);
        ModelSnapshot s = m.getSnapshot();
        assertEquals(-k * (s.y(1) - l0), s.fy(1), 1e-9 * k);
    }

    @Test
    void velocitiesAndForcesOfMassesComeOnlyOnRequestButTheAvatarsForceAlways() {
        double k = 0.01;
        PhysicalModel m = new PhysicalModel(1000, 50);
        m.addGround3D("g", new Vect3D(0, 0, 0));
        m.addMass3D("m", 1, new Vect3D(5, 0, 0), new Vect3D(7, 0, 0));
        m.addHapticInput3D("hand", new Vect3D(-5, 0, 0), 1);
        m.addSpring3D("s", 1, k, "g", "m");
        m.addSpring3D("h", 1, k, "g", "hand");
        m.init();
        m.computeNSteps(10);
        ModelSnapshot s = m.getSnapshot();
        assertFalse(s.hasMotion());
        assertEquals(0, s.speed(1), 0, "no velocities unless asked");
        assertEquals(0, s.forceNorm(1), 0, "no forces unless asked");
        assertEquals(k * (s.x(0) - s.x(2) - 1), s.fx(2), 1e-12, "the avatar's force always");
        s.requestMotion(true);
        m.computeNSteps(10);
        s = m.getSnapshot();
        assertTrue(s.hasMotion());
        assertTrue(s.speed(1) > 0);
        double dx = s.x(1) - s.x(0);   // the mass swings through the fixed point: use the distance
        assertEquals(-k * (Math.abs(dx) - 1) * Math.signum(dx), s.fx(1), 1e-12);
        s.requestMotion(false);
        m.computeNSteps(10);
        s = m.getSnapshot();
        assertFalse(s.hasMotion());
        assertEquals(0, s.speed(1), 0);
    }

    @Test
    void aDrawerAsksForMotionWhileItColoursBySpeedAndStopsAfterwards() {
        PhysicalModel m = new PhysicalModel(1000, 50);
        m.addMass3D("m", 1, new Vect3D(0, 0, 0), new Vect3D(3, 0, 0));
        m.init();
        ModelDrawer d = new ModelDrawer();
        d.setColorBy(ColorBy.SPEED, ColorScale.heat(0, 10));
        Canvas c = new Canvas(50, 50);
        d.draw(m, c.begin());
        c.end();
        m.computeNSteps(10);
        assertTrue(m.getSnapshot().hasMotion());
        assertEquals(3, m.getSnapshot().speed(0), 1e-9);
        d.setColorBy(ColorBy.STRAIN, ColorScale.heat(0, 1));
        d.draw(m, c.begin());
        c.end();
        m.computeNSteps(10);
        assertFalse(m.getSnapshot().hasMotion(), "no longer needed, no longer copied");
    }

    /**
     * The avatar's force buffer sums the spring force over the steps until someone takes it; the snapshot shows
     * the force of one step, whether nobody takes it, or the haptic side takes it every few steps, at any phase
     * relative to the publications. Halfway the hand jumps closer: from the next publication on the snapshot
     * shows the new force alone, not a mean with the old one.
     */
    @Test
    void anAvatarShowsTheForceOfOneStepWhateverTakesItsForceInBetween() {
        double k = 0.002;
        for (int takeEvery : new int[] {0, 1, 3, 7, 10, 25}) {
            PhysicalModel m = new PhysicalModel(1000, 50);
            m.addGround3D("g", new Vect3D(0, 0, 0));
            m.addHapticInput3D("hand", new Vect3D(40, 0, 0), 1);
            m.addSpring3D("s", 0, k, "g", "hand");
            m.init();
            Vect3D taken = new Vect3D();
            for (int step = 1; step <= 200; step++) {
                m.computeStep();
                if (takeEvery > 0 && step % takeEvery == 0) {
                    m.getHapticForce("hand", taken);
                }
                if (step % 10 == 0) {   // 1000 / 50 / 2 steps: a publication has just happened
                    ModelSnapshot s = m.getSnapshot();
                    double expected = -k * (s.x(1) - s.x(0));
                    assertEquals(expected, s.fx(1), 1e-12, "take every " + takeEvery + ", step " + step);
                    assertEquals(0, s.fy(1), 1e-15);
                    if (step == 100) {
                        m.setHapticPosition("hand", new Vect3D(20, 0, 0));
                    }
                }
            }
        }
    }
}
