package tactus.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;
import tactus.PhysicalModel;
import tactus.Vect3D;

/**
 * Rope3D and Bubble3D: the spring-damper force (-K (d - l) - Z (d(n) - d(n-1))) u on mass 1, u = (X1 - X2)/d,
 * acting only while d > l (rope length or bubble radius). Beyond l it pulls the masses together; within l
 * nothing acts at all.
 */
class BubbleRopeTest {

    private static PhysicalModel pair(boolean rope, Vect3D pa, Vect3D va, double l, double k, double z) {
        PhysicalModel pm = new PhysicalModel(1000, 30);
        pm.addGround3D("b", new Vect3D(0, 0, 0));
        pm.addMass3D("a", 2, pa, va);
        if (rope) {
            pm.addRope3D("r", l, k, z, "a", "b");
        } else {
            pm.addBubble3D("r", l, k, z, "a", "b");
        }
        pm.init();
        return pm;
    }

    // A slack rope (and a mass inside its bubble) lets the mass fly freely: a straight line, zero force.
    @Test
    void slackRopeAndInsideBubbleExertNothing() {
        for (boolean rope : new boolean[] {true, false}) {
            // start 0.3 from b moving at 0.001 per step: after 500 steps d <= 0.3 + 0.5 * sqrt(2) < 1.2 = l
            PhysicalModel pm = pair(rope, new Vect3D(0.3, 0, 0), new Vect3D(-1, 1, 0), 1.2, 0.5, 0.1);
            for (int n = 1; n <= 500; n++) {
                pm.computeStep();
                Vect3D p = pm.getMatPosition("a");
                assertEquals(0.3 - n * 0.001, p.x, 1e-13);
                assertEquals(n * 0.001, p.y, 1e-13);
                assertEquals(0.0, pm.getMatForce("a").norm(), 0.0, (rope ? "rope" : "bubble") + " step " + n);
            }
        }
    }

    // Stretched at rest: d = 1.5 > l = 1.2 along (0, 0.6, 0.8); the force on a is -K (d - l) u, towards b.
    @Test
    void stretchedRopeAndBubblePullBack() {
        for (boolean rope : new boolean[] {true, false}) {
            double k = 0.4;
            PhysicalModel pm = pair(rope, new Vect3D(0, 0.9, 1.2), new Vect3D(0, 0, 0), 1.2, k, 0.1);
            pm.computeStep();
            Vect3D f = pm.getMatForce("a");
            double mag = -k * (1.5 - 1.2);
            assertEquals(0.0, f.x, 0.0);
            assertEquals(0.6 * mag, f.y, 1e-15);
            assertEquals(0.8 * mag, f.z, 1e-15);
        }
    }

    // First active step: a leaves b at 0.125 per step from d = 0.5 (exact binary fractions), so with l = 0.8
    // the link engages at step 3 (d = 0.875). The damper sees the true rate d(3) - d(2) = 0.125:
    // F = -K (0.875 - 0.8) - Z 0.125 along +z.
    @Test
    void firstActiveStepDampsTheTrueSeparationSpeed() {
        for (boolean rope : new boolean[] {true, false}) {
            double k = 0.02;
            double z = 0.03;
            PhysicalModel pm = pair(rope, new Vect3D(0, 0, 0.5), new Vect3D(0, 0, 125), 0.8, k, z);
            pm.computeNSteps(2);
            assertEquals(0.75, pm.getMatPosition("a").z, 0.0);
            assertEquals(0.0, pm.getMatForce("a").z, 0.0);
            pm.computeStep();
            assertEquals(0.875, pm.getMatPosition("a").z, 0.0);
            assertEquals(-k * 0.075 - z * 0.125, pm.getMatForce("a").z, 1e-17);
        }
    }

    // A bubble keeps a fast mass inside (up to the penetration of its soft wall): it bounces back.
    @Test
    void bubbleConfinesTheMass() {
        PhysicalModel pm = pair(false, new Vect3D(0, 0, 0.1), new Vect3D(3, 2, 10), 1.0, 0.1, 0);
        double maxD = 0;
        for (int n = 0; n < 5000; n++) {
            pm.computeStep();
            maxD = Math.max(maxD, pm.getMatPosition("a").norm());
        }
        // energy conservation bound on the wall penetration: K e^2 / 2 <= M v^2 / 2 (+ discrete slack)
        double v = Math.sqrt(9 + 4 + 100) / 1000;
        double e = v * Math.sqrt(2 / 0.1);
        assertEquals(true, maxD > 1.0, "the mass reaches the wall");
        assertEquals(true, maxD < 1.0 + 1.1 * e, "max distance " + maxD + " beyond wall bound " + (1 + e));
    }
}
