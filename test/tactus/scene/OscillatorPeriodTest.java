package tactus.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import tactus.PhysicalModel;
import tactus.Vect3D;

/**
 * Undamped mass-spring oscillators against the discrete theory of the explicit scheme.
 *
 * <p>With K/M = r, a linear mode obeys Y(n+1) = (2 - r) Y(n) - Y(n-1), whose solution is a pure sinusoid
 * of angular frequency omega = acos(1 - r/2) per step, i.e. a period of 2 pi / acos(1 - r/2) steps
 * (sharper than the continuous 2 pi / sqrt(r)). Two start-up conventions follow from the two-phase step:
 * <ul>
 *   <li>a spring <em>link</em> acts with one step of delay and the force buffer is empty before the first
 *       step, so Y(1) = Y(0) + D0 (free flight) and the recurrence holds from n = 1;</li>
 *   <li>an oscillator's internal spring is part of its mass update, so the recurrence holds from n = 0 with
 *       Y(-1) = Y(0) - D0.</li>
 * </ul>
 * D0 is the initial displacement per step, initVel / fs.
 */
class OscillatorPeriodTest {
    private static final int FS = 1000;
    private static final int N = 20000;
    private static final double[] RATIOS = {0.004, 0.3, 1.7, 3.5};

    /** Closed form for a link-driven mode: Y(1) = Y0 + D0, Y(2) = (2 - r) Y(1) - Y0, then sinusoid from n = 1. */
    private static double linkClosedForm(double r, double y0, double d0, int n) {
        if (n == 0) {
            return y0;
        }
        double w = Math.acos(1 - r / 2);
        double y1 = y0 + d0;
        double y2 = (2 - r) * y1 - y0;
        double b = (y2 - y1 * Math.cos(w)) / Math.sin(w);
        return y1 * Math.cos(w * (n - 1)) + b * Math.sin(w * (n - 1));
    }

    /** Closed form for an oscillator started at its rest position: Y(n) = D0 sin(omega n) / sin(omega). */
    private static double oscClosedForm(double r, double d0, int n) {
        double w = Math.acos(1 - r / 2);
        return d0 * Math.sin(w * n) / Math.sin(w);
    }

    private static void assertPeriodAndTrajectory(String what, double r, double[] y, double[] expected) {
        double period = Signals.fittedPeriod(y, 2, y.length - 1);
        double theory = Signals.discretePeriod(r);
        assertTrue(Signals.relErr(period, theory) < 1e-9,
                what + " K/M=" + r + ": period " + period + " steps, theory " + theory);
        double amp = Signals.maxAbs(expected);
        for (int n = 0; n < y.length; n++) {
            assertEquals(expected[n], y[n], 1e-9 * amp, what + " K/M=" + r + " at step " + n);
        }
    }

    // Mass3D on a Spring3D (rest length 2) to a Ground3D, moving along z: d = z stays positive, x = y = 0
    // exactly, so the force -K (z - l0) is linear and Y = z - l0 follows the link recurrence.
    @Test
    void mass3dOnSpring3dToGround() {
        for (double r : RATIOS) {
            double m = 2.5;
            PhysicalModel pm = new PhysicalModel(FS, 30);
            pm.addGround3D("g", new Vect3D(0, 0, 0));
            pm.addMass3D("m", m, new Vect3D(0, 0, 2.2), new Vect3D(0, 0, 20));
            pm.addSpring3D("s", 2.0, r * m, "m", "g");
            pm.init();
            double[] y = Signals.record(pm, "m", 2, 2.0, N);
            double[] e = new double[N + 1];
            for (int n = 0; n <= N; n++) {
                e[n] = linkClosedForm(r, 0.2, 20.0 / FS, n);
            }
            assertPeriodAndTrajectory("Mass3D+Spring3D", r, y, e);
            Vect3D p = pm.getMatPosition("m");
            assertEquals(0.0, p.x, 0.0, "no force ever acts along x");
            assertEquals(0.0, p.y, 0.0, "no force ever acts along y");
        }
    }

    // With rest length 0 a Spring3D's force is -K (X1 - X2) exactly: every coordinate is an independent
    // linear mode, so a general 3D orbit has the same discrete period on each axis.
    @Test
    void mass3dOnZeroLengthSpringIn3d() {
        double[] g = {0.5, -0.25, 1.0};
        double[] x0 = {0.9, -0.1, 1.3};
        double[] v0 = {20, -30, 50};
        for (double r : RATIOS) {
            double m = 0.75;
            PhysicalModel pm = new PhysicalModel(FS, 30);
            pm.addGround3D("g", new Vect3D(g[0], g[1], g[2]));
            pm.addMass3D("m", m, new Vect3D(x0[0], x0[1], x0[2]), new Vect3D(v0[0], v0[1], v0[2]));
            pm.addSpring3D("s", 0.0, r * m, "m", "g");
            pm.init();
            double[][] y = new double[3][N + 1];
            Vect3D p = new Vect3D();
            for (int n = 0; n <= N; n++) {
                if (n > 0) {
                    pm.computeStep();
                }
                pm.getMatPosition("m", p);
                y[0][n] = p.x - g[0];
                y[1][n] = p.y - g[1];
                y[2][n] = p.z - g[2];
            }
            for (int a = 0; a < 3; a++) {
                double[] e = new double[N + 1];
                for (int n = 0; n <= N; n++) {
                    e[n] = linkClosedForm(r, x0[a] - g[a], v0[a] / FS, n);
                }
                assertPeriodAndTrajectory("Mass3D+Spring3D(l0=0) axis " + a, r, y[a], e);
            }
        }
    }

    // Osc3D: the internal spring ties each coordinate to the initial position with no delay.
    @Test
    void osc3dAlone() {
        double[] v0 = {-40, 25, 60};
        for (double r : RATIOS) {
            double m = 1.3;
            PhysicalModel pm = new PhysicalModel(FS, 30);
            pm.addOsc3D("o", m, r * m, 0, new Vect3D(1, 2, 3), new Vect3D(v0[0], v0[1], v0[2]));
            pm.init();
            double[][] y = new double[3][N + 1];
            Vect3D p = new Vect3D();
            for (int n = 0; n <= N; n++) {
                if (n > 0) {
                    pm.computeStep();
                }
                pm.getMatPosition("o", p);
                y[0][n] = p.x - 1;
                y[1][n] = p.y - 2;
                y[2][n] = p.z - 3;
            }
            for (int a = 0; a < 3; a++) {
                double[] e = new double[N + 1];
                for (int n = 0; n <= N; n++) {
                    e[n] = oscClosedForm(r, v0[a] / FS, n);
                }
                assertPeriodAndTrajectory("Osc3D axis " + a, r, y[a], e);
            }
        }
    }

    // Osc1D: the same oscillator along z only; x and y keep their initial values whatever the velocity.
    @Test
    void osc1dAlone() {
        for (double r : RATIOS) {
            double m = 0.4;
            PhysicalModel pm = new PhysicalModel(FS, 30);
            pm.addOsc1D("o", m, r * m, 0, new Vect3D(1, 2, 3), new Vect3D(7, -9, 35));
            pm.init();
            double[] y = Signals.record(pm, "o", 2, 3.0, N);
            double[] e = new double[N + 1];
            for (int n = 0; n <= N; n++) {
                e[n] = oscClosedForm(r, 35.0 / FS, n);
            }
            assertPeriodAndTrajectory("Osc1D", r, y, e);
            Vect3D p = pm.getMatPosition("o");
            assertEquals(1.0, p.x, 0.0);
            assertEquals(2.0, p.y, 0.0);
        }
    }

    // Mass1D + Ground1D + SpringDamper1D with Z = 0: the link acts on the signed difference z1 - z2, so
    // Y = z1 - z2 - l0 follows the link recurrence (it may even change sign without any nonlinearity).
    @Test
    void mass1dOnSpringDamper1dToGround1d() {
        for (double r : RATIOS) {
            double m = 3.0;
            PhysicalModel pm = new PhysicalModel(FS, 30);
            pm.addGround1D("g", new Vect3D(0.5, 0.5, -1));
            pm.addMass1D("m", m, new Vect3D(0.5, 0.5, -0.75), new Vect3D(0, 0, -12));
            pm.addSpringDamper1D("s", 0.5, r * m, 0, "m", "g");
            pm.init();
            double[] y = Signals.record(pm, "m", 2, -1 + 0.5, N);
            double[] e = new double[N + 1];
            for (int n = 0; n <= N; n++) {
                e[n] = linkClosedForm(r, -0.75 - (-1) - 0.5, -12.0 / FS, n);
            }
            assertPeriodAndTrajectory("Mass1D+SpringDamper1D", r, y, e);
        }
    }

    // An estimator independent of the recurrence: the mean spacing of upward zero crossings over ~1000
    // periods. Linear interpolation of a crossing is off by O(omega^2) steps, so 1e-7 is a safe bound.
    @Test
    void zeroCrossingPeriodAgreesWithTheory() {
        double r = 0.004;
        PhysicalModel pm = new PhysicalModel(FS, 30);
        pm.addOsc3D("o", 1, r, 0, new Vect3D(0, 0, 0), new Vect3D(0, 0, 1000));
        pm.init();
        double[] y = Signals.record(pm, "o", 2, 0, 100000);
        double period = Signals.crossingPeriod(y);
        double theory = Signals.discretePeriod(r);
        assertTrue(Signals.relErr(period, theory) < 1e-7, "crossing period " + period + " vs " + theory);
        // and it is measurably different from the continuous period 2 pi / sqrt(K/M)
        assertTrue(Signals.relErr(period, 2 * Math.PI / Math.sqrt(r)) > 1e-4);
    }
}
