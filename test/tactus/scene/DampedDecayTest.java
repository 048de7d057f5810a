package tactus.scene;

import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import tactus.PhysicalModel;
import tactus.Vect3D;

/**
 * Damped oscillators against the pole analysis of the scheme (numerics §1.4). With k = K/M and z = Z/M a
 * mode obeys Y(n+1) = (2 - k - z) Y(n) - (1 - z) Y(n-1); its poles solve r^2 + (k + z - 2) r + (1 - z) = 0,
 * so for an oscillating mode the pole radius (per-step amplitude ratio) is rho = sqrt(1 - z) and the pole
 * angle (damped frequency per step) is theta = acos((2 - k - z) / (2 rho)).
 *
 * <p>Two measurements per case:
 * <ul>
 *   <li>rho from the envelope: for Y(n) = C rho^n cos(theta n + phi) the quadratic form
 *       Q(n) = Y(n)^2 - 2 rho cos(theta) Y(n) Y(n-1) + rho^2 Y(n-1)^2 equals rho^(2n) Q(0), so
 *       (Q(n0 + L) / Q(n0))^(1 / 2L) is the per-step amplitude ratio over L steps;</li>
 *   <li>theta from a least-squares fit of Y(n+1) = a Y(n) - b Y(n-1): theta = acos(a / (2 sqrt b)).</li>
 * </ul>
 */
class DampedDecayTest {
    private static final int FS = 1000;
    /** {K/M, Z/M}: all inside the oscillating, stable region (K + Z)^2 < 4KM and K + 2Z < 4M. */
    private static final double[][] CASES = {{0.01, 0.001}, {0.5, 0.05}, {1.5, 0.3}, {0.2, 0.0005}};

    private static int lengthFor(double z) {
        // stop while the amplitude is still above ~1e-6 of its start, so round-off stays negligible
        double rho = Math.sqrt(1 - z);
        return (int) Math.min(8000, Math.log(1e-6) / Math.log(rho));
    }

    private static void assertPoles(String what, double k, double z, double[] y) {
        double rho = Math.sqrt(1 - z);
        double cosTheta = (2 - k - z) / (2 * rho);
        int n0 = 2;
        int n1 = y.length - 1;
        double a = 2 * rho * cosTheta;
        double b = rho * rho;
        double q0 = y[n0] * y[n0] - a * y[n0] * y[n0 - 1] + b * y[n0 - 1] * y[n0 - 1];
        double q1 = y[n1] * y[n1] - a * y[n1] * y[n1 - 1] + b * y[n1 - 1] * y[n1 - 1];
        double measuredRho = Math.pow(q1 / q0, 1.0 / (2 * (n1 - n0)));
        assertTrue(Signals.relErr(measuredRho, rho) < 1e-9,
                what + " k=" + k + " z=" + z + ": amplitude ratio per step " + measuredRho + ", theory " + rho);
        double[] fit = Signals.fitAr2(y, n0, n1);
        double theta = Math.acos(fit[0] / (2 * Math.sqrt(fit[1])));
        assertTrue(Signals.relErr(theta, Math.acos(cosTheta)) < 1e-9,
                what + " k=" + k + " z=" + z + ": damped frequency " + theta + " rad/step, theory "
                        + Math.acos(cosTheta));
        assertTrue(Signals.relErr(Math.sqrt(fit[1]), rho) < 1e-9, what + ": fitted pole radius");
    }

    // Osc3D with internal damping Z: the damper is in the mass update, so the recurrence holds from step 0.
    @Test
    void osc3dPoleRadiusAndAngle() {
        for (double[] c : CASES) {
            double m = 0.8;
            PhysicalModel pm = new PhysicalModel(FS, 30);
            pm.addOsc3D("o", m, c[0] * m, c[1] * m, new Vect3D(-1, 4, 2), new Vect3D(30, -50, 80));
            pm.init();
            int n = lengthFor(c[1]);
            double[] yx = new double[n + 1];
            double[] yz = new double[n + 1];
            Vect3D p = new Vect3D();
            for (int i = 0; i <= n; i++) {
                if (i > 0) {
                    pm.computeStep();
                }
                pm.getMatPosition("o", p);
                yx[i] = p.x + 1;
                yz[i] = p.z - 2;
            }
            assertPoles("Osc3D x", c[0], c[1], yx);
            assertPoles("Osc3D z", c[0], c[1], yz);
        }
    }

    // Mass3D hanging on a SpringDamper3D to a Ground3D along z (d > 0 throughout): the radial damper sees
    // d(n) - d(n-1) = Y(n) - Y(n-1), so the same characteristic polynomial holds (from step 1 on).
    @Test
    void springDamper3dToGroundPoleRadiusAndAngle() {
        for (double[] c : CASES) {
            double m = 1.7;
            PhysicalModel pm = new PhysicalModel(FS, 30);
            pm.addGround3D("g", new Vect3D(0, 0, 0));
            pm.addMass3D("m", m, new Vect3D(0, 0, 2.3), new Vect3D(0, 0, 0));
            pm.addSpringDamper3D("s", 2.0, c[0] * m, c[1] * m, "m", "g");
            pm.init();
            double[] y = Signals.record(pm, "m", 2, 2.0, lengthFor(c[1]));
            assertPoles("SpringDamper3D", c[0], c[1], y);
        }
    }

    // The same through SpringDamper1D on Mass1D / Ground1D.
    @Test
    void springDamper1dToGround1dPoleRadiusAndAngle() {
        for (double[] c : CASES) {
            double m = 0.6;
            PhysicalModel pm = new PhysicalModel(FS, 30);
            pm.addGround1D("g", new Vect3D(0, 0, 1));
            pm.addMass1D("m", m, new Vect3D(0, 0, 1.1), new Vect3D(0, 0, 0));
            pm.addSpringDamper1D("s", 0.3, c[0] * m, c[1] * m, "m", "g");
            pm.init();
            double[] y = Signals.record(pm, "m", 2, 1.3, lengthFor(c[1]));
            assertPoles("SpringDamper1D", c[0], c[1], y);
        }
    }
}
