package tactus.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;
import tactus.PhysicalModel;
import tactus.Vect3D;
import tactus.paramSystem;

/**
 * PlaneContact3D: with q the mass coordinate on the plane's axis and t = q - pos - l0, the contact adds
 * -K t - Z (q(n) - q(n-1)) to that axis only while t < 0, pushing the mass back to the positive side. It is
 * one-sided: above pos + l0 nothing acts, below it pushes however deep the mass is.
 */
class PlaneContactTest {

    private static double axis(Vect3D v, int a) {
        return a == 0 ? v.x : a == 1 ? v.y : v.z;
    }

    private static Vect3D along(int a, double q, double other) {
        return new Vect3D(a == 0 ? q : other, a == 1 ? q : other, a == 2 ? q : other);
    }

    // Above the plane: nothing, on every axis.
    @Test
    void noForceAbove() {
        for (int a = 0; a < 3; a++) {
            PhysicalModel pm = new PhysicalModel(1000, 30);
            pm.addMass3D("m", 1, along(a, 1.15, 0.7), new Vect3D(0, 0, 0));
            pm.addPlaneContact("p", 0.1, 0.5, 0.2, a, 1.0, "m");
            pm.init();
            pm.computeNSteps(10);
            assertEquals(0.0, pm.getMatForce("m").norm(), 0.0, "axis " + a);
            assertEquals(1.15, axis(pm.getMatPosition("m"), a), 0.0, "axis " + a);
        }
    }

    // Below the plane at rest (REAL_UNITS): t = 0.9 - 1.0 - 0.1 = -0.2 m, K = 500 N/m gives +100 N on the plane
    // axis and nothing on the other two; deeper below, -K t grows linearly (one-sided, no second face).
    @Test
    void restoringForceBelowOnEachAxis() {
        for (int a = 0; a < 3; a++) {
            for (double q : new double[] {0.9, -3.0}) {
                PhysicalModel pm = new PhysicalModel(1000, 30, paramSystem.REAL_UNITS);
                pm.addMass3D("m", 1, along(a, q, 0.7), new Vect3D(0, 0, 0));
                pm.addPlaneContact("p", 0.1, 500, 7, a, 1.0, "m");
                pm.init();
                pm.computeStep();
                Vect3D f = pm.getMatForce("m");
                double expected = -500 * (q - 1.0 - 0.1);
                for (int b = 0; b < 3; b++) {
                    assertEquals(b == a ? expected : 0.0, axis(f, b), 1e-9 * Math.abs(expected),
                            "plane axis " + a + ", q=" + q + ", force component " + b);
                }
            }
        }
    }

    // The damping term uses the mass's own displacement over the step: moving at dq per step below the plane,
    // after step 1 q = q0 + dq and F = -K (q - pos - l0) - Z dq.
    @Test
    void dampingUsesTheMassVelocity() {
        for (int a = 0; a < 3; a++) {
            double k = 0.05;
            double z = 0.3;
            PhysicalModel pm = new PhysicalModel(1000, 30);
            Vect3D vel = along(a, -4, 0);   // -0.004 per step into the plane
            pm.addMass3D("m", 1, along(a, 0.95, 0.2), vel);
            pm.addPlaneContact("p", 0.1, k, z, a, 1.0, "m");
            pm.init();
            pm.computeStep();
            double q = 0.95 - 0.004;
            assertEquals(q, axis(pm.getMatPosition("m"), a), 1e-15);
            assertEquals(-k * (q - 1.1) - z * (-0.004), axis(pm.getMatForce("m"), a), 1e-15, "axis " + a);
        }
    }

    // An undamped mass dropped under gravity onto a z plane stays above pos + l0 - (max penetration):
    // potential energy M g h must be absorbed by K e^2 / 2, so e <= sqrt(2 M g h / K) (+ discrete slack).
    @Test
    void keepsAFallingMassOnTheFloor() {
        PhysicalModel pm = new PhysicalModel(1000, 30, paramSystem.REAL_UNITS);
        pm.setGravity(9.81);
        pm.addMass3D("m", 0.1, new Vect3D(0, 0, 0.5), new Vect3D(0, 0, 0));
        pm.addPlaneContact("floor", 0.0, 1e4, 0, 2, 0.0, "m");
        pm.init();
        double minZ = 1;
        for (int n = 0; n < 3000; n++) {
            pm.computeStep();
            minZ = Math.min(minZ, pm.getMatPosition("m").z);
        }
        double e = Math.sqrt(2 * 0.1 * 9.81 * 0.5 / 1e4);
        assertEquals(true, minZ < 0, "the mass reaches the floor");
        assertEquals(true, minZ > -1.1 * e, "penetration " + (-minZ) + " exceeds the energy bound " + e);
    }
}
