package tactus;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import processing.core.PVector;

/**
 * The user code of the paper's Figure 4, transcribed to Java: one mass between two grounds, held by two
 * spring-dampers, launched along z, stepped from a 60 Hz draw loop at 300 Hz.
 *
 * <p>Chosen values: m = 1, dist = 1.5, so both springs (rest length 1) are stretched by 0.5 at the start.
 * Equilibrium on x: K1 (d1 - 1) = K2 (d2 - 1) with d1 = dist - x, d2 = dist + x, hence
 * x_eq = (K1 - K2)(dist - 1) / (K1 + K2) = -0.1.
 */
class Figure4Test {
    static final int SIM_RATE = 300;
    static final int DISP_RATE = 60;
    static final double M = 1;
    static final double DIST = 1.5;
    static final double L0 = 1;
    static final double K1 = 0.1;
    static final double Z1 = 0.01;
    static final double K2 = 0.15;
    static final double Z2 = 0.01;
    static final double X_EQ = (K1 - K2) * (DIST - L0) / (K1 + K2);

    PhysicalModel mdl;

    /** The paper's setup(), verbatim apart from Java syntax. */
    @BeforeEach
    void setup() {
        int simRate = 300;
        int dispRate = 60;
        double m = M;
        double dist = DIST;
        mdl = new PhysicalModel(simRate, dispRate, paramSystem.ALGO_UNITS);
        mdl.addMass3D("mass", m, new Vect3D(0., 0., 0.), new Vect3D(0., 0., 1.));
        mdl.addGround3D("ground1", new Vect3D(dist, 0., 0.));
        mdl.addGround3D("ground2", new Vect3D(-dist, 0., 0.));
        mdl.addSpringDamper3D("spring1", 1., 0.1, 0.01, "mass", "ground1");
        mdl.addSpringDamper3D("spring2", 1., 0.15, 0.01, "mass", "ground2");
        mdl.init();
    }

    /**
     * The paper's model, launched without its z velocity so that it moves along x only (y and z stay exactly
     * 0), is simulated to rest: the radial damping (Z1 + Z2)/M = 0.02 per step shrinks the deviation by e per
     * 100 steps, so after 6,000 steps it is below 1e-25 and only round-off is left. The rest position must be
     * the closed-form equilibrium x_eq = (K1 - K2)(dist - l0)/(K1 + K2), where both springs pull equally hard,
     * and the force left on the mass must vanish.
     */
    @Test
    void equilibriumIsDerivedCorrectly() {
        mdl.setMatVelocity("mass", new Vect3D(0, 0, 0));
        double start = mdl.getMatPosition("mass").x;
        assertEquals(0.0, start, 0.0);
        mdl.computeNSteps(6000);
        Vect3D rest = mdl.getMatPosition("mass");
        double xEq = (K1 - K2) * (DIST - L0) / (K1 + K2);
        assertEquals(xEq, rest.x, 1e-14, "rest position on x");
        assertEquals(0.0, rest.y, 0.0);
        assertEquals(0.0, rest.z, 0.0);
        assertEquals(0.0, mdl.getMatVelocity("mass").norm(), 1e-12, "at rest");
        assertEquals(0.0, mdl.getMatForce("mass").x, 1e-15, "no net force at rest");
        // at rest both springs pull equally hard, each along its own elongation
        assertEquals(K1 * (mdl.getLinkDistance("spring1") - L0), K2 * (mdl.getLinkDistance("spring2") - L0), 1e-15);
        assertEquals(DIST - xEq, mdl.getLinkDistance("spring1"), 1e-14);
    }

    /**
     * An independent implementation of the scheme for this one scene: the mass phase
     * X(n+1) = 2X(n) - X(n-1) + F/M, then each spring-damper adds f u with
     * f = -K (d - l0) - Z (d - d_prev), u = (X - G)/d, d_prev starting at the distance at init.
     */
    static final class Reference {
        double[] x = {0, 0, 0};
        double[] xr = {0, 0, -1.0 / SIM_RATE};
        double[] f = {0, 0, 0};
        double[][] ground = {{DIST, 0, 0}, {-DIST, 0, 0}};
        double[] k = {K1, K2};
        double[] z = {Z1, Z2};
        double[] dPrev = {DIST, DIST};

        void step() {
            for (int i = 0; i < 3; i++) {
                double next = x[i] + (x[i] - xr[i]) + f[i] / M;
                xr[i] = x[i];
                x[i] = next;
                f[i] = 0;
            }
            for (int s = 0; s < 2; s++) {
                double dx = x[0] - ground[s][0];
                double dy = x[1] - ground[s][1];
                double dz = x[2] - ground[s][2];
                double d = Math.sqrt(dx * dx + dy * dy + dz * dz);
                double fs = -k[s] * (d - L0) - z[s] * (d - dPrev[s]);
                dPrev[s] = d;
                f[0] += fs * dx / d;
                f[1] += fs * dy / d;
                f[2] += fs * dz / d;
            }
        }
    }

    @Test
    void drawLoopRunsFiveStepsPerFrameAndMatchesTheScheme() {
        Reference ref = new Reference();
        for (int frame = 1; frame <= 600; frame++) {
            // the paper's draw()
            int n = mdl.draw_physics();
            PVector pos = mdl.getMatPVector("mass");

            assertEquals(SIM_RATE / DISP_RATE, n, "steps in frame " + frame);
            assertEquals(5L * frame, mdl.getStepCount());
            assertTrue(Float.isFinite(pos.x) && Float.isFinite(pos.y) && Float.isFinite(pos.z), "frame " + frame);
            for (int i = 0; i < 5; i++) {
                ref.step();
            }
            Vect3D p = mdl.getMatPosition("mass");
            assertEquals(ref.x[0], p.x, 1e-12, "x at frame " + frame);
            assertEquals(0.0, p.y, 0.0, "y at frame " + frame);
            assertEquals(ref.x[2], p.z, 1e-12, "z at frame " + frame);
            assertEquals((float) p.x, pos.x, 0.0f);
            assertEquals((float) p.z, pos.z, 0.0f);
        }
        // the grounds never moved
        assertEquals(DIST, mdl.getMatPosition("ground1").x, 0.0);
        assertEquals(-DIST, mdl.getMatPosition("ground2").x, 0.0);
        assertEquals(0.0, mdl.getMatVelocity("ground1").norm(), 0.0);
    }

    @Test
    void firstStepsFollowTheInitialVelocity() {
        // step 1: no force has been computed yet, so the mass moves by exactly v / simRate
        mdl.computeStep();
        Vect3D p1 = mdl.getMatPosition("mass");
        assertEquals(1.0 / 300, p1.z, 0.0);
        assertEquals(0.0, p1.x, 0.0);
        assertEquals(0.0, p1.y, 0.0);
        assertEquals(1.0, mdl.getMatVelocity("mass").z, 1e-12);

        // the interaction phase of step 1 computed the forces at z1 = 1/300 (mass still at x = 0)
        double z1 = 1.0 / 300;
        double d = Math.sqrt(DIST * DIST + z1 * z1);
        double f1 = -K1 * (d - L0) - Z1 * (d - DIST);
        double f2 = -K2 * (d - L0) - Z2 * (d - DIST);
        double fx = f1 * (-DIST) / d + f2 * DIST / d;
        double fz = (f1 + f2) * z1 / d;
        Vect3D force = mdl.getMatForce("mass");
        assertEquals(fx, force.x, 1e-15);
        assertEquals(fz, force.z, 1e-15);
        assertEquals(-0.025, fx, 1e-5);   // K1 0.5 - K2 0.5: the stiffer spring2 pulls toward -x
        assertTrue(fz < 0, "the stretched springs pull the mass back toward z = 0");

        // step 2 applies them: z2 = 2 z1 - z0 + fz / m = 2/300 + fz, x2 = fx
        mdl.computeStep();
        Vect3D p2 = mdl.getMatPosition("mass");
        assertEquals(2.0 / 300 + fz / M, p2.z, 1e-15);
        assertEquals(fx / M, p2.x, 1e-15);
        // over the first frame z rises but lags n / 300: the stretched springs give a transverse
        // stiffness (K1 + K2)(1 - l0 / dist) = 0.25 / 3 per step^2, so z ~ A sin(w n) with w ~ 0.29 rad/step
        mdl.computeNSteps(3);
        double kt0 = (K1 + K2) * (1 - L0 / DIST);
        double w0 = Math.acos(1 - kt0 / (2 * M));
        double z5 = mdl.getMatPosition("mass").z;
        assertTrue(z5 > 0 && z5 < 5.0 / 300, "z5 = " + z5);
        assertEquals((1.0 / 300) * Math.sin(5 * w0) / Math.sin(w0), z5, 0.02 * z5);
    }

    @Test
    void xSettlesAtTheEquilibriumWithDampedDecay() {
        double[] windowPeak = new double[6];   // peak |x - x_eq| over successive 20-frame (100-step) windows
        double lastPeak = 0;
        for (int frame = 0; frame < 600; frame++) {
            mdl.draw_physics();
            double dev = Math.abs(mdl.getMatPVector("mass").x - X_EQ);
            if (frame / 20 < windowPeak.length) {
                windowPeak[frame / 20] = Math.max(windowPeak[frame / 20], dev);
            }
            if (frame >= 500) {
                lastPeak = Math.max(lastPeak, Math.abs(mdl.getMatPosition("mass").x - X_EQ));
            }
        }
        assertTrue(windowPeak[0] > 0.05, "starts 0.1 away from equilibrium: " + windowPeak[0]);
        // radial damping Z1 + Z2 = 0.02 on M = 1: envelope exp(-0.01 n), a factor e per 100 steps
        for (int w = 1; w < windowPeak.length; w++) {
            double ratio = windowPeak[w] / windowPeak[w - 1];
            assertEquals(Math.exp(-1), ratio, 0.12, "decay over window " + w);
        }
        // after 2500 steps only the second-order coupling to the transverse z motion is left
        assertEquals(0.0, lastPeak, 1e-4);
        assertEquals(X_EQ, mdl.getMatPosition("mass").x, 1e-4);
    }

    @Test
    void zKeepsOscillatingAtTheTransverseFrequencyBecauseDampingIsRadialOnly() {
        // transverse stiffness at equilibrium: sum K_i (1 - l0 / d_i)
        double d1 = DIST - X_EQ;
        double d2 = DIST + X_EQ;
        double kt = K1 * (1 - L0 / d1) + K2 * (1 - L0 / d2);
        double omega = Math.acos(1 - kt / (2 * M));   // discrete angular frequency per step
        double amplitude = (1.0 / SIM_RATE) / Math.sin(omega);
        mdl.computeNSteps(1500);   // let x settle
        int crossings = 0;
        double peak = 0;
        double prev = mdl.getMatPosition("mass").z;
        int steps = 1500;
        for (int n = 0; n < steps; n++) {
            mdl.computeStep();
            double zz = mdl.getMatPosition("mass").z;
            if ((prev < 0) != (zz < 0)) {
                crossings++;
            }
            peak = Math.max(peak, Math.abs(zz));
            prev = zz;
        }
        double expectedCrossings = steps * omega / Math.PI;
        assertEquals(expectedCrossings, crossings, 2.0, "zero crossings of z, omega = " + omega);
        // barely damped: still within a few percent of the launch amplitude
        assertEquals(amplitude, peak, 0.08 * amplitude);
        assertTrue(Double.isFinite(mdl.getTotalEnergy()));
    }
}
