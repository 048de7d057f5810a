package tactus.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;
import tactus.PhysicalModel;
import tactus.Vect3D;
import tactus.paramSystem;

/**
 * Contact3D: the spring-damper with the threshold as rest length, acting only while d < threshold. With
 * u = (X1 - X2) / d the force on mass 1 is (-K (d - thr) - Z (d(n) - d(n-1))) u and mass 2 gets the opposite:
 * since d < thr the spring part pushes the masses apart. The force computed in a step's interaction phase
 * is what getMatForce reports after that step.
 */
class ContactTest {

    // Outside the threshold nothing acts: masses drift in straight lines, bit-exactly, and report zero force.
    @Test
    void noForceOutsideTheThreshold() {
        PhysicalModel pm = new PhysicalModel(1000, 30);
        pm.addMass3D("a", 1, new Vect3D(0, 0, 1), new Vect3D(0, 0, 0));
        pm.addMass3D("b", 2, new Vect3D(0.25, 0.5, 0), new Vect3D(0, 0, 0));
        pm.addContact3D("c", 0.5, 0.1, 0.05, "a", "b");
        pm.init();
        for (int n = 0; n < 100; n++) {
            pm.computeStep();
            Vect3D f = pm.getMatForce("a");
            assertEquals(0.0, f.x, 0.0);
            assertEquals(0.0, f.y, 0.0);
            assertEquals(0.0, f.z, 0.0);
        }
        Vect3D a = pm.getMatPosition("a");
        assertEquals(1.0, a.z, 0.0, "a mass at rest outside the threshold stays put");
        assertEquals(0.0, pm.getMatForce("b").norm(), 0.0);
    }

    // Penetrating at rest (REAL_UNITS): K = 1000 N/m, thr = 0.1 m, d = 0.06 m gives |F| = K (thr - d) = 40 N,
    // directed from b to a on a, from a to b on b, reported in newtons.
    @Test
    void restoringForceInsideAtRest() {
        PhysicalModel pm = new PhysicalModel(1000, 30, paramSystem.REAL_UNITS);
        Vect3D pa = new Vect3D(0.036, 0.048, 1.0);  // 0.06 m from b, along (0.6, 0.8, 0)
        pm.addMass3D("a", 0.5, pa, new Vect3D(0, 0, 0));
        pm.addMass3D("b", 0.5, new Vect3D(0, 0, 1.0), new Vect3D(0, 0, 0));
        pm.addContact3D("c", 0.1, 1000, 3, "a", "b");
        pm.init();
        pm.computeStep();   // the first step is force-free, so the masses are still at rest when the contact acts
        Vect3D fa = pm.getMatForce("a");
        Vect3D fb = pm.getMatForce("b");
        double mag = 1000 * (0.1 - 0.06);
        assertEquals(0.6 * mag, fa.x, 1e-9);
        assertEquals(0.8 * mag, fa.y, 1e-9);
        assertEquals(0.0, fa.z, 1e-9);
        assertEquals(-fa.x, fb.x, 0.0, "equal and opposite");
        assertEquals(-fa.y, fb.y, 0.0, "equal and opposite");
        // the next step moves a away from b by F/M / fs^2 on top of its zero velocity
        pm.computeStep();
        Vect3D a1 = pm.getMatPosition("a");
        assertEquals(pa.x + 0.6 * mag / 0.5 / 1e6, a1.x, 1e-15);
        assertEquals(pa.y + 0.8 * mag / 0.5 / 1e6, a1.y, 1e-15);
    }

    // First active step: a approaches a fixed b at 0.125 units per step from z = 1 (exact binary fractions), so
    // after step n it is at 1 - n/8 and the contact (thr = 0.3) engages at step 6 with d = 0.25. The damper must
    // see the true approach rate d(6) - d(5) = 0.25 - 0.375 = -0.125, not a stale or undefined previous distance:
    // F = -K (0.25 - 0.3) - Z (0.25 - 0.375) = 0.05 K + 0.125 Z along +z.
    @Test
    void firstActiveStepDampsTheTrueApproachSpeed() {
        double k = 0.01;
        double z = 0.02;
        PhysicalModel pm = new PhysicalModel(1000, 30);
        pm.addGround3D("b", new Vect3D(0, 0, 0));
        pm.addMass3D("a", 1, new Vect3D(0, 0, 1), new Vect3D(0, 0, -125));   // -125 units/s = -0.125 per step
        pm.addContact3D("c", 0.3, k, z, "a", "b");
        pm.init();
        for (int n = 1; n <= 5; n++) {
            pm.computeStep();
            assertEquals(1 - n / 8.0, pm.getMatPosition("a").z, 0.0, "free flight before contact");
            assertEquals(0.0, pm.getMatForce("a").z, 0.0, "no force before contact, step " + n);
        }
        pm.computeStep();
        assertEquals(0.25, pm.getMatPosition("a").z, 0.0);
        assertEquals(0.05 * k + 0.125 * z, pm.getMatForce("a").z, 1e-17);
        // one step later the damper uses the contact's own previous distance: d(7) - d(6)
        pm.computeStep();
        double d7 = 0.25 - 0.125 + (0.05 * k + 0.125 * z);
        assertEquals(d7, pm.getMatPosition("a").z, 1e-16);
        assertEquals(-k * (d7 - 0.3) - z * (d7 - 0.25), pm.getMatForce("a").z, 1e-16);
    }

    // Leaving the contact switches the force off again; re-entering damps with the new approach speed.
    @Test
    void contactReleasesWhenTheMassesSeparate() {
        PhysicalModel pm = new PhysicalModel(1000, 30);
        pm.addGround3D("b", new Vect3D(0, 0, 0));
        // kinetic energy 0.5 * 0.01^2 per step^2 is far below K thr^2 / 2, so a bounces back without crossing b
        pm.addMass3D("a", 1, new Vect3D(0, 0, 0.5), new Vect3D(0, 0, -10));
        pm.addContact3D("c", 0.3, 0.05, 0, "a", "b");
        pm.init();
        boolean touched = false;
        for (int n = 0; n < 2000; n++) {
            pm.computeStep();
            double d = pm.getMatPosition("a").z;
            assertEquals(true, d > 0, "a never reaches b");
            double f = pm.getMatForce("a").z;
            if (d < 0.3) {
                touched = true;
                assertEquals(-0.05 * (d - 0.3), f, 1e-17, "inside, step " + n);
            } else {
                assertEquals(0.0, f, 0.0, "outside, step " + n);
            }
        }
        assertEquals(true, touched);
        // an undamped penalty bounce off a fixed point returns the mass: it ends outside, moving away
        assertEquals(true, pm.getMatVelocity("a").z > 0);
    }
}
