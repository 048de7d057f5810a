package tactus.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import tactus.PhysicalModel;
import tactus.Vect3D;
import tactus.paramSystem;

/**
 * Free fall and air friction in REAL_UNITS against the discrete solution of the scheme.
 *
 * <p>With gravity g (m/s^2) along minus the gravity direction, a = g / fs^2 per step^2 and the update
 * X(n+1) = 2X(n) - X(n-1) - a. The per-step displacement D(n) = X(n) - X(n-1) then obeys D(n+1) = D(n) - a
 * with D(0) = v0 / fs (the initial condition X(-1) = X0 - v0 / fs), so
 * X(n) = X0 + sum_{k=1..n} D(k) = X0 + v0 n / fs - a n (n + 1) / 2.
 * At t = n / fs this is X0 + v0 t - g t^2 / 2 - g t / (2 fs): the continuous parabola plus an offset that is
 * exactly first order in 1/fs.
 *
 * <p>Round-off: the scheme carries the velocity as X(n) - X(n-1), so a rounding error d_k made on X(k) stays in
 * every later displacement and moves X(n) by (n - k) d_k. With |d_k| <= ulp(max |X|) the position error after n
 * steps is bounded by n^2 ulp(max |X|) / 2; the tolerances below use n^2 ulp(max |X|).
 *
 * <p>With air friction f (N·s/m) and mass M the update is D(n+1) = (1 - f/(M fs)) D(n) - a, whose fixed point
 * D* = -a M fs / f gives the velocity D* fs = -g M / f: the continuous terminal velocity, at any rate.
 */
class FreeFallTest {
    private static final double G = 9.81;

    /** Worst-case round-off on a position after n steps, see the class comment. */
    private static double roundOff(int n, double maxAbsPosition) {
        return (double) n * n * Math.ulp(maxAbsPosition);
    }

    // x(n) = x0 + v0 n/fs - g/fs^2 n(n+1)/2 on the gravity axis, straight lines on the others.
    @Test
    void positionMatchesTheDiscreteSolutionEveryStep() {
        int fs = 1000;
        PhysicalModel pm = new PhysicalModel(fs, 30, paramSystem.REAL_UNITS);
        pm.setGravity(G);
        double[] x0 = {0.25, -1.5, 2.0};
        double[] v0 = {0.5, -1.0, 3.0};
        pm.addMass3D("m", 0.3, new Vect3D(x0[0], x0[1], x0[2]), new Vect3D(v0[0], v0[1], v0[2]));
        pm.init();
        double a = G / ((double) fs * fs);
        Vect3D p = new Vect3D();
        int steps = 1000;
        double tol = roundOff(steps, 3.0);   // |X| stays below 3 m over this second
        for (int n = 1; n <= steps; n++) {
            pm.computeStep();
            pm.getMatPosition("m", p);
            assertEquals(x0[0] + v0[0] * n / fs, p.x, tol, "x at step " + n);
            assertEquals(x0[1] + v0[1] * n / fs, p.y, tol, "y at step " + n);
            assertEquals(x0[2] + v0[2] * n / fs - a * n * (n + 1) / 2.0, p.z, tol, "z at step " + n);
        }
        // the other common convention, X(n) = X0 + v0 t - a n(n-1)/2, differs by a n = 9.8e-3 m: far outside tol
        assertTrue(a * steps > 1e6 * tol);
        // velocity over the last step: D(n) fs = v0 - g n / fs
        assertEquals(v0[2] - G * steps / fs, pm.getMatVelocity("m").z, 2 * tol * fs);
    }

    // The gap to the continuous parabola at t = 1 s is g t / (2 fs): first order, halving as fs doubles.
    @Test
    void approachesTheContinuousParabolaAtFirstOrder() {
        double t = 1.0;
        double previousGap = Double.NaN;
        for (int fs : new int[] {250, 500, 1000, 2000, 4000}) {
            PhysicalModel pm = new PhysicalModel(fs, 30, paramSystem.REAL_UNITS);
            pm.setGravity(G);
            pm.addMass3D("m", 1, new Vect3D(0, 0, 0), new Vect3D(0, 0, 0));
            pm.init();
            int n = (int) (t * fs);
            pm.computeNSteps(n);
            double continuous = -0.5 * G * t * t;
            double gap = continuous - pm.getMatPosition("m").z;
            double tol = roundOff(n, 5.0);
            assertEquals(G * t / (2 * fs), gap, tol, "gap to the parabola at fs=" + fs);
            if (!Double.isNaN(previousGap)) {
                assertEquals(0.5, gap / previousGap, 4 * tol / gap, "first-order convergence at fs=" + fs);
            }
            previousGap = gap;
        }
    }

    // Masses accelerate along minus the (normalised) gravity direction.
    @Test
    void fallsAlongMinusTheGravityDirection() {
        int fs = 1000;
        PhysicalModel pm = new PhysicalModel(fs, 30, paramSystem.REAL_UNITS);
        pm.setGravity(G);
        pm.setGravityDirection(new Vect3D(3, 0, 4));
        pm.addMass3D("m", 2, new Vect3D(0, 0, 0), new Vect3D(0, 0, 0));
        pm.init();
        int n = 500;
        pm.computeNSteps(n);
        double fall = G / ((double) fs * fs) * n * (n + 1) / 2.0;
        Vect3D p = pm.getMatPosition("m");
        assertEquals(-0.6 * fall, p.x, roundOff(n, fall));
        assertEquals(0.0, p.y, 0.0);
        assertEquals(-0.8 * fall, p.z, roundOff(n, fall));
    }

    // Terminal velocity -g M / f, approached geometrically: v(n) = v* (1 - rho^n) from rest, rho = 1 - f/(M fs).
    @Test
    void airFrictionGivesTerminalVelocityGmOverF() {
        for (int fs : new int[] {1000, 44100}) {
            double m = 0.5;
            double f = 2.0;
            PhysicalModel pm = new PhysicalModel(fs, 30, paramSystem.REAL_UNITS);
            pm.setGravity(G);
            pm.setFriction(f);
            pm.addMass3D("m", m, new Vect3D(0, 0, 0), new Vect3D(0, 0, 0));
            pm.init();
            double vInf = -G * m / f;
            double rho = 1 - f / (m * fs);
            int done = 0;
            for (int n : new int[] {1, 10, 100, 1000, 5000}) {
                pm.computeNSteps(n - done);
                done = n;
                double v = pm.getMatVelocity("m").z;
                assertTrue(Signals.relErr(v, vInf * (1 - Math.pow(rho, n))) < 1e-9,
                        "fs=" + fs + " step " + n + ": v=" + v + " expected " + vInf * (1 - Math.pow(rho, n)));
            }
            // 25 time constants M/f = 0.25 s later the velocity has converged to -g M / f (rho^n < 1e-10). A
            // rounding error on X(k) perturbs the displacement, and that perturbation decays by rho per step, so
            // the velocity error is at most ulp(max |X|) fs / (1 - rho).
            int steps = (int) (25 * 0.25 * fs);
            pm.computeNSteps(steps - done);
            double maxX = Math.abs(vInf) * 25 * 0.25;
            double tol = Math.abs(vInf) * 1e-10 + Math.ulp(maxX) * fs / (1 - rho);
            assertEquals(vInf, pm.getMatVelocity("m").z, tol, "terminal velocity at fs=" + fs);
        }
    }

    // An Osc3D under gravity settles where its spring balances the weight: M g / K below its rest point, in
    // metres, at any rate (the per-step equilibrium Y = -(g/fs^2) / (K/(M fs^2)) does not depend on fs).
    @Test
    void oscillatorSagsByMgOverK() {
        for (int fs : new int[] {1000, 8000}) {
            PhysicalModel pm = new PhysicalModel(fs, 30, paramSystem.REAL_UNITS);
            pm.setGravity(G);
            pm.addOsc3D("o", 0.2, 50, 2, new Vect3D(0, 0, 1), new Vect3D(0, 0, 0));
            pm.init();
            pm.computeNSteps(5 * fs);   // decay time 2 M / Z = 0.2 s: 25 time constants
            assertEquals(1 - 0.2 * G / 50, pm.getMatPosition("o").z, 1e-10, "fs=" + fs);
            assertEquals(0.0, pm.getMatVelocity("o").z, 1e-8);
        }
    }
}
