package tactus.stability;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.SplittableRandom;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import tactus.DivergenceException;
import tactus.PhysicalModel;
import tactus.StabilityPolicy;
import tactus.UnstableModelException;
import tactus.Vect3D;
import tactus.StabilityReport;

/**
 * Hard cases at the stability bound: one mass, a chain, an oscillator, a membrane and pure air friction, each
 * just inside (0.99) and just outside (1.01) the limit {@code λmax(M⁻¹(K + 2Z)) < 4}. Inside, the analyser
 * reports a positive margin and a long run keeps the scheme's energy function G (see {@link StabilityFixtures})
 * bounded; outside, the analyser flags the model before it runs (WARN line, or UnstableModelException under
 * THROW) and, forced to run under policy OFF, the divergence guard stops it with a DivergenceException naming a
 * mass. Everything is in ALGO_UNITS (per-step coefficients), so K/M and Z/M are the dimensionless numbers of
 * docs/stability.md.
 */
class HardCasesBoundsTest {
    private static final int FS = 44100;

    // ------------------------------------------------------------------ one mass on a spring-damper

    /** One Mass3D "bob" on a SpringDamper3D "stiff" (rest length 1) to a Ground3D, displaced axially by 0.05. */
    private static PhysicalModel singleMass(double kOverM, double zOverM, StabilityPolicy policy) {
        double m = 2;
        PhysicalModel pm = new PhysicalModel(FS);
        pm.setStabilityPolicy(policy);
        pm.addGround3D("anchor", new Vect3D(0, 0, 0));
        pm.addMass3D("bob", m, new Vect3D(1.05, 0, 0), new Vect3D());
        pm.addSpringDamper3D("stiff", 1.0, kOverM * m, zOverM * m, "anchor", "bob");
        return pm;
    }

    /** G = ½ (M - Z/2) v² + ½ K e(n) e(n-1) of the single-mass scene (axial motion, e = x - 1). */
    private static double singleMassG(PhysicalModel pm) {
        double m = pm.getMatMass("bob");
        double k = pm.getLinkStiffness("stiff");
        double z = pm.getLinkDamping("stiff");
        double e = pm.getMatPosition("bob").x - 1.0;
        double v = pm.getMatVelocity("bob").x / FS;
        return 0.5 * (m - z / 2) * v * v + 0.5 * k * e * (e - v);
    }

    // Undamped, K/M = 0.99 * 4: the analyser's lambda is K/M exactly (margin 0.04). The mode sits near Nyquist
    // (cos theta = 1 - K/2M = -0.98), so from rest at e = 0.05 the alternating oscillation has amplitude
    // 0.05 / cos(theta/2) ~ 0.5: ten times the initial displacement, as the discrete energy predicts. Over 10^6
    // steps (23 s of audio) the discrete energy G = H stays constant to round-off and |e| never exceeds the bound
    // sqrt(2H/K) + sqrt(2H/(M - K/4)) / 2 that H implies.
    @Test
    @DisplayName("stiff spring at 0.99 of the single-mass bound, undamped: stable verdict, 10^6 steps, H conserved")
    void singleMassJustInsideUndamped() {
        PhysicalModel pm = singleMass(0.99 * 4, 0, StabilityPolicy.WARN);
        String err = StabilityFixtures.captureStdErr(pm::init);
        assertEquals("", err, "a stable model prints nothing");
        StabilityReport r = pm.getStabilityReport();
        assertTrue(r.isStable());
        assertEquals(3.96, r.lambda(), 1e-12);
        assertEquals(0.04, r.margin(), 1e-12);
        assertTrue(r.margin() > 0);
        assertTrue(pm.describeStability().startsWith("Tactus: stable"), pm.describeStability());

        pm.computeStep(); // the first step runs on the empty force buffer: H is the scheme's invariant from here
        double h0 = singleMassG(pm);
        double m = 2;
        double k = 0.99 * 4 * m;
        double eMax = Math.sqrt(2 * h0 / k) + 0.5 * Math.sqrt(2 * h0 / (m - k / 4));
        double seenMax = 0;
        double worstDrift = 0;
        for (int block = 0; block < 1000; block++) {
            for (int i = 0; i < 1000; i++) {
                pm.computeStep();
                seenMax = Math.max(seenMax, Math.abs(pm.getMatPosition("bob").x - 1.0));
            }
            worstDrift = Math.max(worstDrift, Math.abs(singleMassG(pm) - h0) / h0);
        }
        StabilityFixtures.assertFiniteState(pm, "single mass 0.99");
        assertTrue(worstDrift < 1e-9, "discrete energy drift " + worstDrift);
        assertTrue(seenMax <= eMax * (1 + 1e-9), "amplitude " + seenMax + " above the energy bound " + eMax);
        assertTrue(seenMax > 0.4, "the near-Nyquist mode really swings ~10x the initial 0.05: " + seenMax);
        assertFalse(pm.isDiverged());
    }

    // Damped, Z/M = 0.1 and K/M = 3.76 (K/M + 2Z/M = 3.96): G is non-increasing step by step (checked every 100
    // steps to round-off), the oscillation dies out and the mass settles at the rest length.
    @Test
    @DisplayName("stiff spring-damper at 0.99 of the single-mass bound (Z/M = 0.1): G never grows, settles")
    void singleMassJustInsideDamped() {
        PhysicalModel pm = singleMass(3.76, 0.1, StabilityPolicy.WARN);
        pm.init();
        StabilityReport r = pm.getStabilityReport();
        assertEquals(3.96, r.lambda(), 1e-12);
        pm.computeStep();
        double g0 = singleMassG(pm);
        double prev = g0;
        for (int block = 0; block < 10_000; block++) {
            pm.computeNSteps(100);
            double g = singleMassG(pm);
            assertTrue(g <= prev + 1e-13 * g0, "G grew at step " + pm.getStepCount() + ": " + prev + " -> " + g);
            prev = g;
        }
        StabilityFixtures.assertFiniteState(pm, "damped single mass 0.99");
        assertEquals(1.0, pm.getMatPosition("bob").x, 1e-12);
    }

    // K/M = 1.01 * 4. Before running: the report is unstable and the WARN line printed by init() names the
    // module, its parameter "K", the value and the limit (4M = 8). Under THROW, init() throws with the same
    // message and the report attached.
    @Test
    @DisplayName("stiff spring at 1.01 of the bound: flagged before running (WARN line, THROW at init)")
    void singleMassJustOutsideIsFlagged() {
        PhysicalModel warn = singleMass(1.01 * 4, 0, StabilityPolicy.WARN);
        String err = StabilityFixtures.captureStdErr(warn::init).trim();
        assertEquals(1, err.lines().count(), "exactly one line: " + err);
        assertTrue(err.contains("SpringDamper3D \"stiff\""), err);
        assertTrue(err.contains("K = 8.080"), err);
        assertTrue(err.contains("limit of about 8.000"), err);
        StabilityReport r = warn.getStabilityReport();
        assertFalse(r.isStable());
        assertEquals(4.04, r.lambda(), 1e-12);
        assertTrue(r.margin() < 0);
        assertEquals(err, warn.describeStability());

        PhysicalModel strict = singleMass(1.01 * 4, 0, StabilityPolicy.THROW);
        UnstableModelException ex = assertThrows(UnstableModelException.class, strict::init);
        assertEquals(err, ex.getMessage());
        assertFalse(ex.getReport().isStable());

        // A stable model under THROW refuses a spring that would cross the bound, and takes it back out.
        PhysicalModel grow = singleMass(0.5, 0, StabilityPolicy.THROW);
        grow.init();
        grow.addMass3D("second", 2, new Vect3D(-1.05, 0, 0), new Vect3D());
        assertThrows(UnstableModelException.class,
                () -> grow.addSpring3D("tooStiff", 1.0, 8.1, "anchor", "second"));
        assertFalse(grow.linkExists("tooStiff"));
        grow.addSpring3D("fine", 1.0, 7.9, "anchor", "second");
        assertTrue(grow.getStabilityReport().isStable());
    }

    // Forced to run (policy OFF, nothing printed): |r| = 1 + 2 sqrt(0.01) ~ 1.2 per step, so x passes the
    // divergence limit (1e12) after about 170 steps. The guard scans every 64 steps: the DivergenceException
    // names "bob" and comes at most 64 steps after the first step with |x| > 1e12. The model is then frozen
    // (further steps throw again and do not advance) until clearDivergence(); repaired, it runs on.
    @Test
    @DisplayName("stiff spring at 1.01, policy OFF: the guard raises DivergenceException naming the mass within 64 steps")
    void singleMassJustOutsideDivergesAndIsCaught() {
        PhysicalModel pm = singleMass(1.01 * 4, 0, StabilityPolicy.OFF);
        assertEquals("", StabilityFixtures.captureStdErr(pm::init));
        pm.setMatVelocity("bob", new Vect3D(0.01 * FS, 0, 0));
        long firstBeyond = -1;
        DivergenceException caught = null;
        for (int i = 0; i < 10_000 && caught == null; i++) {
            try {
                pm.computeStep();
            } catch (DivergenceException e) {
                caught = e;
            }
            double x = Math.abs(pm.getMatPosition("bob").x);
            if (firstBeyond < 0 && !(x <= 1e12)) {
                firstBeyond = pm.getStepCount();
            }
        }
        assertTrue(caught != null, "no DivergenceException in 10^4 steps");
        assertEquals("bob", caught.getMassName());
        assertTrue(caught.getMessage().contains("\"bob\""), caught.getMessage());
        assertTrue(firstBeyond > 0 && caught.getStep() >= firstBeyond && caught.getStep() - firstBeyond <= 64,
                "beyond the limit at step " + firstBeyond + ", caught at " + caught.getStep());
        assertTrue(pm.isDiverged());
        Vect3D frozen = pm.getMatPosition("bob");
        assertTrue(Double.isFinite(frozen.x), "caught before overflow: " + frozen);
        long at = pm.getStepCount();
        assertThrows(DivergenceException.class, pm::computeStep);
        assertEquals(at, pm.getStepCount(), "a diverged model does not step");

        // Repair (a stable K, the mass back at rest 0.05 off) and restart: it rings with amplitude
        // 0.05 / cos(theta/2) = 0.053 (K/M = 0.5, cos theta = 0.75) and stays sane.
        pm.setLinkStiffness("stiff", 1.0);
        pm.setMatPosition("bob", new Vect3D(1.05, 0, 0));
        pm.clearDivergence();
        assertFalse(pm.isDiverged());
        for (int i = 0; i < 10_000; i++) {
            pm.computeStep();
            assertTrue(Math.abs(pm.getMatPosition("bob").x - 1) < 0.054, "after repair, step " + i);
        }

        // A finer guard (every step, limit 1e3, set before the model runs) fires at the very step x passes 1e3.
        PhysicalModel fine = singleMass(1.01 * 4, 0, StabilityPolicy.OFF);
        fine.setDivergenceCheckInterval(1);
        fine.setDivergenceLimit(1e3);
        fine.init();
        fine.setMatVelocity("bob", new Vect3D(0.01 * FS, 0, 0));
        long beyond = -1;
        DivergenceException again = null;
        for (int i = 0; i < 10_000 && again == null; i++) {
            try {
                fine.computeStep();
            } catch (DivergenceException e) {
                again = e;
            }
            if (beyond < 0 && Math.abs(fine.getMatPosition("bob").x) > 1e3) {
                beyond = fine.getStepCount();
            }
        }
        assertTrue(again != null);
        assertEquals(beyond, again.getStep(), "with interval 1 the guard fires at the first step beyond the limit");
    }

    // The same divergence with a listener: it is called once, stepping calls return normally, and the model
    // stays frozen (the step count stops) until cleared.
    @Test
    @DisplayName("stiff spring at 1.01 with a divergence listener: notified once, model frozen")
    void singleMassDivergenceListener() {
        PhysicalModel pm = singleMass(1.01 * 4, 0, StabilityPolicy.OFF);
        pm.init();
        List<DivergenceException> events = Collections.synchronizedList(new ArrayList<>());
        pm.setDivergenceListener(events::add);
        for (int i = 0; i < 100; i++) {
            pm.computeNSteps(100);
        }
        assertEquals(1, events.size());
        assertEquals("bob", events.get(0).getMassName());
        long at = pm.getStepCount();
        assertEquals(events.get(0).getStep(), at);
        pm.computeNSteps(1000);
        assertEquals(at, pm.getStepCount());
        assertEquals(1, events.size());
    }

    // ------------------------------------------------------------------ chain of equal masses

    /** n Mass1D "c0".."c(n-1)" in a chain of SpringDamper1D "s0".."sn" between two Ground1D, z perturbed. */
    private static PhysicalModel chain(int n, double kOverM, StabilityPolicy policy, long seed) {
        PhysicalModel pm = new PhysicalModel(FS);
        pm.setStabilityPolicy(policy);
        SplittableRandom rnd = new SplittableRandom(seed);
        pm.addGround1D("left", new Vect3D());
        pm.addGround1D("right", new Vect3D());
        for (int i = 0; i < n; i++) {
            pm.addMass1D("c" + i, 1.0, new Vect3D(i, 0, 1e-3 * (2 * rnd.nextDouble() - 1)), new Vect3D());
        }
        for (int i = 0; i <= n; i++) {
            pm.addSpringDamper1D("s" + i, 0, kOverM, 0, i == 0 ? "left" : "c" + (i - 1), i == n ? "right" : "c" + i);
        }
        return pm;
    }

    // A chain of n equal masses with fixed ends has lambda max(M^-1 K) = (K/M)(2 + 2cos(pi/(n+1))), so the
    // exact limit is K/M < 2 / (1 + cos(pi/(n+1))) = 1.0009 for n = 50, not the per-mass "2" rule.
    // At 0.99 of it: Lanczos gives lambda = 3.96 (to 1e-6), and 10^6 steps conserve H to round-off.
    @Test
    @DisplayName("chain of 50 equal masses at 0.99 of 2/(1+cos(pi/51)): verdict and 10^6 steps with H conserved")
    void chainJustInside() {
        int n = 50;
        double limit = 2 / (1 + Math.cos(Math.PI / (n + 1)));
        PhysicalModel pm = chain(n, 0.99 * limit, StabilityPolicy.WARN, 11);
        assertEquals("", StabilityFixtures.captureStdErr(pm::init));
        StabilityReport r = pm.getStabilityReport();
        assertTrue(r.isConverged());
        assertEquals(3.96, r.lambda(), 3.96e-6);
        assertTrue(r.isStable());
        // Gershgorin row sums (2 K per mobile neighbour) give the guaranteed 4 K/M: tight for a long chain
        assertEquals(4 * 0.99 * limit, r.gershgorinBound(), 1e-12);
        pm.computeStep();
        double h0 = StabilityFixtures.lyapunov1D(pm, Map.of());
        double worst = 0;
        for (int block = 0; block < 100; block++) {
            pm.computeNSteps(10_000);
            worst = Math.max(worst, Math.abs(StabilityFixtures.lyapunov1D(pm, Map.of()) - h0) / h0);
        }
        StabilityFixtures.assertFiniteState(pm, "chain 0.99");
        assertTrue(worst < 1e-9, "discrete energy drift " + worst);
    }

    // At 1.01 of the chain limit: flagged (the WARN line names one of the springs and "K"), and under OFF the
    // top mode (growth ~1.2 per step) trips the guard within a few hundred steps, naming one of the masses.
    @Test
    @DisplayName("chain of 50 equal masses at 1.01 of the chain limit: flagged, then caught by the guard")
    void chainJustOutside() {
        int n = 50;
        double limit = 2 / (1 + Math.cos(Math.PI / (n + 1)));
        PhysicalModel pm = chain(n, 1.01 * limit, StabilityPolicy.WARN, 12);
        String err = StabilityFixtures.captureStdErr(pm::init).trim();
        // lowering one spring of 51 cannot bring lambda back under 4, and the line says so
        assertTrue(err.matches("Tactus: unstable model: SpringDamper1D \"s\\d+\": K = 1\\.011 \\(model units\\) is too "
                + "high, and lowering it alone cannot make the model stable\\. Fix: lower the stiffness of the links around "
                + "it, raise the masses it joins, or take more steps per frame with K divided by the factor's square "
                + "\\(the same motion per frame, further from the limit\\) \\(stability index 4\\.040, which must stay "
                + "below 4; docs/stability\\.md\\)"), err);
        assertEquals(4.04, pm.getStabilityReport().lambda(), 4.04e-6);
        pm.setStabilityPolicy(StabilityPolicy.OFF);
        DivergenceException caught = null;
        while (caught == null && pm.getStepCount() < 5000) {
            try {
                pm.computeNSteps(100);
            } catch (DivergenceException e) {
                caught = e;
            }
        }
        assertTrue(caught != null, "not caught in 5000 steps");
        assertTrue(caught.getMassName().matches("c\\d+"), caught.getMassName());
    }

    // ------------------------------------------------------------------ non-proportional damping

    /** A 20-mass Mass1D chain (K 1, undamped) between grounds with one very lossy link (Z 0.6), all scaled by s. */
    private static PhysicalModel lossyChain(double s, StabilityPolicy policy) {
        PhysicalModel pm = new PhysicalModel(FS);
        pm.setStabilityPolicy(policy);
        SplittableRandom rnd = new SplittableRandom(21);
        pm.addGround1D("left", new Vect3D());
        pm.addGround1D("right", new Vect3D());
        for (int i = 0; i < 20; i++) {
            pm.addMass1D("c" + i, 1.0, new Vect3D(i, 0, 1e-3 * (2 * rnd.nextDouble() - 1)), new Vect3D());
        }
        for (int i = 0; i <= 20; i++) {
            pm.addSpringDamper1D(i == 10 ? "lossy" : "s" + i, 0, s, i == 10 ? 0.6 * s : 0,
                    i == 0 ? "left" : "c" + (i - 1), i == 20 ? "right" : "c" + i);
        }
        return pm;
    }

    // Non-proportional damping (numerics §1.3 advises a numerical check for "one very lossy damper in a stiff
    // mesh"): a chain whose only damper is one link with Z/K = 0.6, so the damping matrix does not share the
    // stiffness matrix's modes. The analyser's criterion is still exact: G = ½ vᵀ(M - Z/2)v + ½ XᵀK X- never grows
    // for any symmetric Z >= 0, and is a norm iff lambda max(M^-1(K + 2Z)) < 4 (StabilityFixtures). At 0.99 of
    // the analyser's bound G is non-increasing over 10^5 steps; at 1.01 the guard catches the divergence.
    @Test
    @DisplayName("one very lossy damper in a stiff chain (non-proportional damping) at 0.99 and 1.01 of the analyser bound")
    void nonProportionalDampingAtTheBound() {
        PhysicalModel unit = lossyChain(1, StabilityPolicy.OFF);
        unit.init();
        double lambda1 = unit.getStabilityReport().lambda();
        assertTrue(lambda1 > 4 && lambda1 < 6, "per unit " + lambda1);

        PhysicalModel in = lossyChain(0.99 * 4 / lambda1, StabilityPolicy.WARN);
        assertEquals("", StabilityFixtures.captureStdErr(in::init));
        assertEquals(3.96, in.getStabilityReport().lambda(), 1e-9);
        in.computeStep();
        double prev = StabilityFixtures.lyapunov1D(in, Map.of());
        double g0 = prev;
        for (int b = 0; b < 100; b++) {
            in.computeNSteps(1000);
            double g = StabilityFixtures.lyapunov1D(in, Map.of());
            assertTrue(g <= prev + 1e-12 * g0, "G grew at step " + in.getStepCount() + ": " + prev + " -> " + g);
            prev = g;
        }
        StabilityFixtures.assertFiniteState(in, "lossy chain 0.99");

        PhysicalModel out = lossyChain(1.01 * 4 / lambda1, StabilityPolicy.OFF);
        out.init();
        assertEquals(4.04, out.getStabilityReport().lambda(), 1e-9);
        DivergenceException caught = null;
        while (caught == null && out.getStepCount() < 200_000) {
            try {
                out.computeNSteps(1000);
            } catch (DivergenceException e) {
                caught = e;
            }
        }
        assertTrue(caught != null, "not caught in 2e5 steps");
        assertTrue(caught.getMassName().matches("c\\d+"), caught.getMassName());
    }

    // ------------------------------------------------------------------ Osc3D

    /** Osc3D "osc", M = 0.5, Z = 0.01 (Z/M = 0.02), moving in 3D from (1, 2, 3). */
    private static PhysicalModel osc(double kOverM, StabilityPolicy policy) {
        PhysicalModel pm = new PhysicalModel(FS);
        pm.setStabilityPolicy(policy);
        pm.addOsc3D("osc", 0.5, kOverM * 0.5, 0.01, new Vect3D(1, 2, 3), new Vect3D(100, -50, 25));
        return pm;
    }

    private static double oscG(PhysicalModel pm) {
        double m = 0.5;
        double k = pm.getMatStiffness("osc");
        double z = pm.getMatDamping("osc");
        Vect3D p = pm.getMatPosition("osc");
        Vect3D v = pm.getMatVelocity("osc").div(FS);
        double ex = p.x - 1, ey = p.y - 2, ez = p.z - 3;
        return 0.5 * (m - z / 2) * v.sqNorm() + 0.5 * k * (ex * (ex - v.x) + ey * (ey - v.y) + ez * (ez - v.z));
    }

    // K/M + 2Z/M = 0.99 * 4 with Z/M = 0.02: lambda 3.96 from the oscillator's own spring and damper; 10^6
    // steps with G non-increasing, settling back exactly onto the rest position.
    @Test
    @DisplayName("Osc3D at 0.99 of its bound: stable verdict, G never grows over 10^6 steps")
    void oscJustInside() {
        PhysicalModel pm = osc(3.92, StabilityPolicy.WARN);
        assertEquals("", StabilityFixtures.captureStdErr(pm::init));
        assertEquals(3.96, pm.getStabilityReport().lambda(), 1e-12);
        pm.computeStep();
        double g0 = oscG(pm);
        double prev = g0;
        for (int block = 0; block < 1000; block++) {
            pm.computeNSteps(1000);
            double g = oscG(pm);
            assertTrue(g <= prev + 1e-13 * g0, "G grew at step " + pm.getStepCount());
            prev = g;
        }
        StabilityFixtures.assertFiniteState(pm, "Osc3D 0.99");
        Vect3D p = pm.getMatPosition("osc");
        // settles onto a round-off fixed point a few ulps from the rest position
        assertTrue(p.dist(new Vect3D(1, 2, 3)) < 1e-13, "back at rest: " + p);
    }

    // K/M + 2Z/M = 1.01 * 4: the WARN line names the oscillator and its K = 2 against the limit 4M - 2Z = 1.98;
    // under OFF the near-Nyquist mode (r ~ -1.27) diverges and is caught.
    @Test
    @DisplayName("Osc3D at 1.01 of its bound: WARN names the oscillator's K and limit, guard catches it")
    void oscJustOutside() {
        PhysicalModel pm = osc(4.0, StabilityPolicy.WARN);
        String err = StabilityFixtures.captureStdErr(pm::init).trim();
        assertTrue(err.contains("Osc3D \"osc\": K = 2.000 is above its limit of about 1.980"), err);
        pm.setStabilityPolicy(StabilityPolicy.OFF);
        DivergenceException caught = assertThrows(DivergenceException.class, () -> {
            for (int i = 0; i < 1000; i++) {
                pm.computeNSteps(100);
            }
        });
        assertEquals("osc", caught.getMassName());
    }

    // ------------------------------------------------------------------ membrane

    /** N x N Mass1D membrane "p_i_j" (one degree of freedom each), SpringDamper1D to 4 neighbours, edges fixed. */
    private static PhysicalModel membrane(int n, double k, long seed) {
        PhysicalModel pm = new PhysicalModel(FS);
        SplittableRandom rnd = new SplittableRandom(seed);
        pm.addGround1D("frame", new Vect3D());
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++) {
                pm.addMass1D("p_" + i + "_" + j, 1.0, new Vect3D(i, j, 1e-3 * (2 * rnd.nextDouble() - 1)), new Vect3D());
            }
        }
        pm.createLinkSubset("springs");
        int[][] dirs = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++) {
                for (int[] d : dirs) {
                    int a = i + d[0], b = j + d[1];
                    boolean inside = a >= 0 && a < n && b >= 0 && b < n;
                    if (inside && (d[0] < 0 || d[1] < 0)) {
                        continue; // each interior edge once
                    }
                    String name = "k_" + i + "_" + j + "_" + d[0] + "_" + d[1];
                    pm.addSpringDamper1D(name, 0, k, 0, "p_" + i + "_" + j, inside ? "p_" + a + "_" + b : "frame");
                    pm.addLinkToSubset(name, "springs");
                }
            }
        }
        return pm;
    }

    // 20 x 20 membrane with fixed edges: the eigenvalues of M^-1 K are (K/M)(4 - 2cos(p pi/21) - 2cos(q pi/21)),
    // p, q = 1..20, so lambda max = (K/M)(4 + 4cos(pi/21)) = 7.9553 K/M and the exact limit is K/M < 0.50281
    // (the per-mass rule would allow 1). The analyser's Lanczos value matches the theory to 1e-6; at 0.99 of the
    // analyser's own bound 10^5 steps conserve H, at 1.01 the guard catches the divergence.
    @Test
    @DisplayName("20x20 membrane: Lanczos lambda vs theory, 0.99 of the analyser bound runs, 1.01 is caught")
    void membraneAtItsBound() {
        int n = 20;
        double theory = 4 + 4 * Math.cos(Math.PI / (n + 1));
        PhysicalModel unit = membrane(n, 1.0, 3);
        unit.setStabilityPolicy(StabilityPolicy.OFF);
        unit.init();
        StabilityReport r1 = unit.getStabilityReport();
        assertTrue(r1.isConverged());
        assertEquals(theory, r1.lambda(), 1e-6 * theory, "Lanczos vs theory");
        assertEquals(8.0, r1.gershgorinBound(), 1e-12, "Gershgorin: 4 neighbours x 2");
        double limit = 4 / r1.lambda();
        assertEquals(4 / theory, limit, 1e-6 * limit);

        PhysicalModel in = membrane(n, 0.99 * limit, 4);
        assertEquals("", StabilityFixtures.captureStdErr(in::init));
        assertEquals(3.96, in.getStabilityReport().lambda(), 1e-9);
        in.computeStep();
        double h0 = StabilityFixtures.lyapunov1D(in, Map.of());
        double worst = 0;
        for (int block = 0; block < 10; block++) {
            in.computeNSteps(10_000);
            worst = Math.max(worst, Math.abs(StabilityFixtures.lyapunov1D(in, Map.of()) - h0) / h0);
        }
        StabilityFixtures.assertFiniteState(in, "membrane 0.99");
        assertTrue(worst < 1e-9, "discrete energy drift " + worst);

        // Ramp the same membrane through its subset to 1.01 of the bound: WARN names one of its springs; run it.
        String err = StabilityFixtures.captureStdErr(() -> in.changeStiffnessParamOfSubset(1.01 * limit, "springs"));
        assertTrue(err.contains("SpringDamper1D \"k_") && err.contains("K = "), err);
        assertEquals(4.04, in.getStabilityReport().lambda(), 1e-9);
        DivergenceException caught = null;
        while (caught == null && in.getStepCount() < 200_000) {
            try {
                in.computeNSteps(1000);
            } catch (DivergenceException e) {
                caught = e;
            }
        }
        assertTrue(caught != null, "membrane at 1.01 not caught");
        assertTrue(caught.getMassName().startsWith("p_"), caught.getMassName());
    }

    // ------------------------------------------------------------------ air friction only

    // A free Mass3D with air friction f only: the displacement per step obeys d(n+1) = r d(n), r = 1 - f/M, so
    // x(n) = x0 + d0 r (1 - r^n) / (1 - r) exactly (to round-off). The analyser's lambda is 2f/M: f/M = 0.01
    // coasts to a stop over 10^6 steps; f/M = 1.98 (r = -0.98, lambda 3.96) rattles but decays; f/M = 2.02
    // (lambda 4.04) is flagged with the mass named ("mass ... is below its limit ... (air friction)") and diverges.
    @Test
    @DisplayName("air friction only: closed-form coasting at f/M = 0.01, rattling decay at 1.98, flagged and caught at 2.02")
    void frictionOnly() {
        for (double fOverM : new double[] {0.01, 1.98}) {
            PhysicalModel pm = new PhysicalModel(1000);
            Vect3D v0 = new Vect3D(3, -4, 12);
            pm.addMass3D("puck", 1.0, new Vect3D(), v0);
            pm.setFriction(fOverM);
            assertEquals("", StabilityFixtures.captureStdErr(pm::init));
            assertEquals(2 * fOverM, pm.getStabilityReport().lambda(), 1e-12);
            double r = 1 - fOverM;
            for (int block = 1; block <= 1000; block++) {
                pm.computeNSteps(1000);
                double n = block * 1000.0;
                double factor = r * (1 - Math.pow(r, n)) / (1 - r);
                Vect3D p = pm.getMatPosition("puck");
                // Round-off: the scheme carries the velocity as X(n) - X(n-1), quantised to ulps of X. A
                // displacement of k ulps is a fixed point of d -> r d as soon as (1 - r) k < 1/2, so friction
                // leaves a dead band (as in a fixed-point IIR filter): the puck ends up creeping by up to
                // ulp(X) M / (2f) per step forever (50 ulps here). Allowed: 1e-12 relative plus that creep.
                double creep = n / (2 * fOverM);
                assertEquals(0.003 * factor, p.x, 1e-12 * Math.abs(p.x) + creep * Math.ulp(p.x), "x, step " + n);
                assertEquals(-0.004 * factor, p.y, 1e-12 * Math.abs(p.y) + creep * Math.ulp(p.y), "y, step " + n);
                assertEquals(0.012 * factor, p.z, 1e-12 * Math.abs(p.z) + creep * Math.ulp(p.z), "z, step " + n);
            }
            StabilityFixtures.assertFiniteState(pm, "friction " + fOverM);
        }
        PhysicalModel bad = new PhysicalModel(1000);
        bad.addMass3D("puck", 1.0, new Vect3D(), new Vect3D(3, -4, 12));
        bad.setFriction(2.02);
        String err = StabilityFixtures.captureStdErr(bad::init).trim();
        assertTrue(err.contains("Mass3D \"puck\": mass = 1.000 is below its limit of about 1.010 (air friction)"), err);
        bad.setStabilityPolicy(StabilityPolicy.OFF);
        DivergenceException caught = assertThrows(DivergenceException.class, () -> {
            for (int i = 0; i < 100; i++) {
                bad.computeNSteps(1000);
            }
        });
        assertEquals("puck", caught.getMassName());
        if (caught.getStep() > 3000) {
            fail("|r| = 1.02: 0.003 * 1.02^n passes 1e12 near n = 1700, caught only at " + caught.getStep());
        }
    }
}
