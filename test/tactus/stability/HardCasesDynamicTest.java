package tactus.stability;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
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
 * Hard cases that change while they run: negative damping feeding energy in, topology edits on an oscillating
 * mesh, parameters ramped to the edges of the stable region (and a ramp that crosses it under THROW), and a
 * haptic avatar driven by a noisy target.
 */
class HardCasesDynamicTest {

    // ------------------------------------------------------------------ negative damping

    // A SpringDamper3D with Z < 0 (the linear caricature of a bowed string: friction that feeds energy in),
    // K/M 0.01, Z/M -2e-4, rest length 1, 44.1 kHz. Verdict: lambda ignores negative damping (0.01, stable), the
    // report says hasNegativeDamping() and names the link; the WARN line (also printed under THROW, which does
    // not throw for it) says "negative damping" with the link and its Z. Behaviour: every step multiplies the
    // amplitude by sqrt(1 - Z/M) = sqrt(1.0002), e^1 per 10^4 steps (checked to 1% while the swing is below the
    // rest length); once the mass swings through the anchor the growth continues at a similar rate, and the
    // guard reports the divergence (|x| > 1e12) close to the linear prediction 2 ln(1e14) / ln(1.0002) = 3.2e5
    // steps (within 10%), through the listener, once.
    @Test
    @DisplayName("negative damping: flagged as such, grows e^1 per 10^4 steps, caught by the guard near 3.2e5 steps")
    void negativeDamping() {
        PhysicalModel pm = new PhysicalModel(44100);
        pm.addGround3D("nut", new Vect3D());
        pm.addMass3D("bowed", 1, new Vect3D(1.01, 0, 0), new Vect3D());
        pm.addSpringDamper3D("bow", 1.0, 0.01, -2e-4, "nut", "bowed");
        String err = StabilityFixtures.captureStdErr(pm::init).trim();
        assertEquals("Tactus: negative damping: SpringDamper3D \"bow\": Z = -0.0002000 < 0 feeds energy in; "
                + "oscillations are sustained or grow (fine if intended, e.g. bowing)", err);
        StabilityReport r = pm.getStabilityReport();
        assertTrue(r.hasNegativeDamping());
        assertTrue(r.isStable());
        assertEquals(0.01, r.lambda(), 1e-12);

        PhysicalModel strict = new PhysicalModel(44100);
        strict.setStabilityPolicy(StabilityPolicy.THROW);
        strict.addGround3D("nut", new Vect3D());
        strict.addMass3D("bowed", 1, new Vect3D(1.01, 0, 0), new Vect3D());
        strict.addSpringDamper3D("bow", 1.0, 0.01, -2e-4, "nut", "bowed");
        assertEquals(err, StabilityFixtures.captureStdErr(strict::init).trim(), "THROW warns, does not throw");

        List<DivergenceException> events = new ArrayList<>();
        pm.setDivergenceListener(events::add);
        double previous = 0;
        int checked = 0;
        while (events.isEmpty() && pm.getStepCount() < 1_000_000) {
            double max = 0;
            for (int i = 0; i < 10_000 && events.isEmpty(); i++) {
                pm.computeStep();
                max = Math.max(max, Math.abs(pm.getMatPosition("bowed").x - 1));
            }
            if (previous > 0 && max < 0.5) {
                assertEquals(Math.E, max / previous, 0.01 * Math.E, "growth per 10^4 steps");
                checked++;
            }
            previous = max;
        }
        assertTrue(checked >= 2, "linear growth windows checked: " + checked);
        assertEquals(1, events.size());
        assertEquals("bowed", events.get(0).getMassName());
        double predicted = 2 * Math.log(1e12 / 0.01) / Math.log(1.0002);
        long at = events.get(0).getStep();
        System.out.printf(Locale.ROOT, "[stability] negative damping: diverged at step %d, linear prediction %.0f%n",
                at, predicted);
        assertEquals(predicted, at, 0.1 * predicted);
        assertTrue(pm.isDiverged());
    }

    // ------------------------------------------------------------------ topology changes

    /** An 8 x 8 Mass3D mesh "m_i_j" (spacing 1) with SpringDamper3D "h_/v_..." (l0 0.8: under tension), ring fixed. */
    private static PhysicalModel mesh(long seed) {
        PhysicalModel pm = new PhysicalModel(1000);
        SplittableRandom rnd = new SplittableRandom(seed);
        int n = 8;
        for (int i = -1; i <= n; i++) {
            for (int j = -1; j <= n; j++) {
                boolean border = i < 0 || j < 0 || i == n || j == n;
                if (border) {
                    pm.addGround3D("m_" + i + "_" + j, new Vect3D(i, j, 0));
                } else {
                    pm.addMass3D("m_" + i + "_" + j, 1.0, new Vect3D(i, j, 0), new Vect3D(10 * (2 * rnd.nextDouble() - 1),
                            10 * (2 * rnd.nextDouble() - 1), 10 * (2 * rnd.nextDouble() - 1)));
                }
            }
        }
        for (int i = -1; i <= n; i++) {
            for (int j = -1; j <= n; j++) {
                if (i < n && j >= 0 && j < n) {
                    pm.addSpringDamper3D("h_" + i + "_" + j, 0.8, 0.2, 0.001, "m_" + i + "_" + j, "m_" + (i + 1) + "_" + j);
                }
                if (j < n && i >= 0 && i < n) {
                    pm.addSpringDamper3D("v_" + i + "_" + j, 0.8, 0.2, 0.001, "m_" + i + "_" + j, "m_" + i + "_" + (j + 1));
                }
            }
        }
        return pm;
    }

    // An 8 x 8 mesh under tension, shaken (random velocities 0.01 per step), edited every 2 x 10^4 steps while it
    // vibrates: remove a link, remove a mass with its links, turn masses into fixed points, tear a whole row of
    // links, and add a spring between two masses at their current distance (so it stores no energy). Each edit
    // keeps the live state of every other mass exactly (no jump across the recompile). Removing links or masses
    // and fixing masses only take energy out and a spring added at its current length puts none in, so the
    // naive energy stays within the linear factor (1 + sqrt(lambda)/2) / (1 - sqrt(lambda)/2) of E0 (lambda
    // being the largest analyser value along the way); nothing is printed (no warning) and all stays finite.
    @Test
    @DisplayName("topology changes while oscillating (remove links/masses, changeToFixedPoint, tear, weld): finite, energy bounded")
    void topologyChangesWhileOscillating() {
        PhysicalModel pm = mesh(8);
        pm.setStabilityPolicy(StabilityPolicy.THROW);
        pm.init();
        double e0 = pm.getTotalEnergy();
        double[] lambdaMax = {pm.getStabilityReport().lambda()};
        double[] eMax = {e0};
        List<Runnable> edits = List.of(
            () -> pm.removeLink("h_3_3"),
            () -> pm.removeMatAndConnectedLinks("m_5_2"),
            () -> pm.changeToFixedPoint("m_2_6"),
            () -> {
                for (int i = -1; i < 8; i++) {
                    pm.removeLink("h_" + i + "_4");
                }
            },
            () -> pm.addSpringDamper3D("weld", pm.getMatPosition("m_1_1").dist(pm.getMatPosition("m_6_6")), 0.1,
                    0.001, "m_1_1", "m_6_6"),
            () -> {
                pm.changeToFixedPoint("m_0_0");
                pm.changeToFixedPoint("m_7_7");
                pm.removeMatAndConnectedLinks("m_4_4");
            });
        String printed = StabilityFixtures.captureStdErr(() -> {
            for (Runnable edit : edits) {
                for (int b = 0; b < 20; b++) {
                    pm.computeNSteps(1000);
                    StabilityFixtures.assertFiniteState(pm, "mesh");
                    eMax[0] = Math.max(eMax[0], pm.getTotalEnergy());
                }
                Vect3D watch = pm.getMatPosition("m_3_1");
                Vect3D watchVel = pm.getMatVelocity("m_3_1");
                edit.run();
                assertEquals(0.0, watch.dist(pm.getMatPosition("m_3_1")), 0.0, "state carried over");
                assertEquals(0.0, watchVel.dist(pm.getMatVelocity("m_3_1")), 0.0, "velocity carried over");
                lambdaMax[0] = Math.max(lambdaMax[0], pm.getStabilityReport().lambda());
                for (int b = 0; b < 20; b++) {
                    pm.computeNSteps(1000);
                    eMax[0] = Math.max(eMax[0], pm.getTotalEnergy());
                }
            }
        });
        double eEnd = pm.getTotalEnergy();
        assertEquals("", printed);
        StabilityFixtures.assertFiniteState(pm, "mesh after edits");
        double bound = StabilityFixtures.naiveEnergyFactor(lambdaMax[0]);
        System.out.printf(Locale.ROOT, "[stability] mesh with topology edits: E0 %.4e, max %.4e, end %.4e, lambda max "
                + "%.3f, bound %.2f E0%n", e0, eMax[0], eEnd, lambdaMax[0], bound);
        assertTrue(eMax[0] <= bound * e0, "energy " + eMax[0] + " vs " + e0);
        assertEquals(100 - 2, pm.getNumberOfMats(), "36 ring points + 64 masses, 2 removed");
    }

    // ------------------------------------------------------------------ parameter ramps

    /** Six Mass1D beads between two Ground1D on SpringDamper1D (damping z), in subsets "beads" and "springs". */
    private static PhysicalModel beads(double k, double z) {
        PhysicalModel pm = new PhysicalModel(1000);
        pm.addGround1D("left", new Vect3D());
        pm.addGround1D("right", new Vect3D());
        pm.createMatSubset("beads");
        pm.createLinkSubset("springs");
        SplittableRandom rnd = new SplittableRandom(31);
        for (int i = 0; i < 6; i++) {
            pm.addMass1D("b" + i, 1.0, new Vect3D(i, 0, 0.01 * (2 * rnd.nextDouble() - 1)), new Vect3D());
            pm.addMatToSubset("b" + i, "beads");
        }
        for (int i = 0; i <= 6; i++) {
            pm.addSpringDamper1D("k" + i, 0, k, z, i == 0 ? "left" : "b" + (i - 1), i == 6 ? "right" : "b" + i);
            pm.addLinkToSubset("k" + i, "springs");
        }
        return pm;
    }

    /** Discrete frequency (rad/step) of the top mode at lambda: 2 asin(sqrt(lambda)/2). */
    private static double omega(double lambda) {
        return 2 * Math.asin(Math.sqrt(lambda) / 2);
    }

    // Parameters swept to the edges while the beads ring (link Z 1e-5), through subsets, one change every 100 steps:
    // stiffness up to 0.98 of the chain's limit and down to 1e-12 (nearly free beads), masses down until lambda is
    // 0.98 x 4, damping to 0 and then to 0.98 of the single-mass limit 2M - K/2 (an Osc1D "reed"). All stays
    // finite. Energy: a slow stiffening pumps energy in like a tightened string (adiabatically E / omega is kept),
    // so the bound is E0 times omega_max / omega_min times the naive-energy factor at lambda_max, asserted at every
    // change; the measured maximum is printed.
    @Test
    @DisplayName("parameter ramps to the extremes (K to 0.98 of the limit and to 1e-12, M down, Z to 0 and near 2M): finite, bounded")
    void parameterRamps() {
        double z = 1e-5;
        PhysicalModel pm = beads(0.01, z);
        pm.init();
        double lambda0 = pm.getStabilityReport().lambda();
        double c = lambda0 / (0.01 + 2 * z); // lambda = c (K + 2Z) for this chain, c = 2 + 2cos(pi/7)
        double kLimit = 4 / c - 2 * z;
        double e0 = pm.getTotalEnergy();
        double eMax = e0;
        double lambdaMax = 0;
        // K: 0.01 -> 0.98 kLimit -> 1e-12 -> 0.5 kLimit, geometric, 200 changes per leg
        double[][] legs = {{0.01, 0.98 * kLimit}, {0.98 * kLimit, 1e-12}, {1e-12, 0.5 * kLimit}};
        for (double[] leg : legs) {
            for (int s = 1; s <= 200; s++) {
                double k = leg[0] * Math.pow(leg[1] / leg[0], s / 200.0);
                pm.changeStiffnessParamOfSubset(k, "springs");
                pm.computeNSteps(100);
                double lambda = pm.getStabilityReport().lambda();
                assertTrue(lambda < 4, "lambda " + lambda);
                lambdaMax = Math.max(lambdaMax, lambda);
                eMax = Math.max(eMax, pm.getTotalEnergy());
            }
            pm.computeNSteps(20_000);
            StabilityFixtures.assertFiniteState(pm, "K ramp");
        }
        // M: down until lambda = 0.98 x 4 (lambda is ~2 at M = 1 now)
        double mEnd = pm.getStabilityReport().lambda() / (0.98 * 4);
        for (int s = 1; s <= 200; s++) {
            pm.changeMassParamOfSubset(Math.pow(mEnd, s / 200.0), "beads");
            pm.computeNSteps(100);
            eMax = Math.max(eMax, pm.getTotalEnergy());
        }
        assertEquals(0.98 * 4, pm.getStabilityReport().lambda(), 1e-6);
        pm.computeNSteps(20_000);
        StabilityFixtures.assertFiniteState(pm, "M ramp");
        double bound = StabilityFixtures.naiveEnergyFactor(0.98 * 4) * omega(0.98 * 4) / omega(lambda0);
        System.out.printf(Locale.ROOT, "[stability] ramps: max E/E0 = %.2f (bound %.0f)%n", eMax / e0, bound);
        assertTrue(eMax <= bound * e0, "energy " + eMax / e0 + " x E0");

        // Z on an oscillator: to 0, then to 0.98 (2M - K/2); lambda = (K + 2Z)/M reaches 0.98 x 4 + 0.02 K/M.
        PhysicalModel reed = new PhysicalModel(1000);
        reed.addOsc1D("reed", 1.0, 0.01, 0.05, new Vect3D(), new Vect3D(0, 0, 10));
        reed.init();
        Map<String, Double> rest = Map.of("reed", 0.0);
        double g0 = StabilityFixtures.lyapunov1D(reed, rest);
        for (double[] leg : new double[][] {{0.05, 0}, {0, 0.98 * (2 - 0.01 / 2)}}) {
            for (int s = 1; s <= 100; s++) {
                reed.setMatDamping("reed", leg[0] + (leg[1] - leg[0]) * s / 100.0);
                reed.computeNSteps(100);
                StabilityFixtures.assertFiniteState(reed, "Z ramp");
                // lowering Z raises G by ¼ ΔZ v² at the change (at most ¼ 0.05 v² in all, 1.3% of ½ M v²);
                // between changes G does not grow
                double now = StabilityFixtures.lyapunov1D(reed, rest);
                assertTrue(now <= 1.02 * g0, "G grew: " + now + " from " + g0);
            }
        }
        assertEquals(0.98 * 4 + 0.0002, reed.getStabilityReport().lambda(), 1e-9);
    }

    // Under THROW a ramp that would cross the limit is refused at the first offending change, and undone: the
    // subset ramp leaves every spring at its last accepted value; a single spring ramped alone is refused once
    // its own contribution pushes lambda over 4; a mass ramped down is refused at its limit; an oscillator's
    // damping ramped up is refused near 2M - K/2. After each refusal the model runs on, stable and finite.
    @Test
    @DisplayName("a ramp that crosses the limit under THROW is refused and undone (parameters unchanged), then runs on")
    void rampCrossingTheLimitUnderThrow() {
        PhysicalModel pm = beads(0.01, 1e-3);
        pm.setStabilityPolicy(StabilityPolicy.THROW);
        pm.init();
        double kLimit = 4 / (pm.getStabilityReport().lambda() / (0.01 + 2e-3)) - 2e-3;
        double accepted = 0;
        UnstableModelException refused = null;
        for (int s = 0; s <= 20 && refused == null; s++) {
            double k = kLimit * (0.955 + 0.01 * s);
            try {
                pm.changeStiffnessParamOfSubset(k, "springs");
                accepted = k;
                pm.computeNSteps(50);
            } catch (UnstableModelException e) {
                refused = e;
            }
        }
        assertTrue(refused != null, "never refused");
        assertTrue(accepted < kLimit && accepted > 0.98 * kLimit, "last accepted " + accepted / kLimit);
        assertFalse(refused.getReport().isStable());
        for (int i = 0; i <= 6; i++) {
            assertEquals(accepted, pm.getLinkStiffness("k" + i), 0.0, "k" + i + " restored");
        }
        assertTrue(pm.getStabilityReport().isStable());

        // one spring to ground alone: lambda ~ its K/M once it dominates
        pm.changeStiffnessParamOfSubset(0.3 * kLimit, "springs");
        double single = pm.getLinkStiffness("k0");
        for (double k = single; k < 10; k *= 1.05) {
            final double kk = k;
            try {
                pm.setLinkStiffness("k0", kk);
                single = kk;
            } catch (UnstableModelException e) {
                break;
            }
        }
        assertEquals(single, pm.getLinkStiffness("k0"), 0.0);
        assertTrue(single < 4, "k0 stopped at " + single);
        double finalSingle = single;
        assertThrows(UnstableModelException.class, () -> pm.setLinkStiffness("k0", finalSingle * 1.05));
        assertEquals(single, pm.getLinkStiffness("k0"), 0.0);

        // a mass ramped down (k0 back to the others' value first)
        pm.setLinkStiffness("k0", 0.3 * kLimit);
        double m = 1.0;
        for (int s = 0; s < 200; s++) {
            try {
                pm.setMatMass("b0", m * 0.97);
                m *= 0.97;
            } catch (UnstableModelException e) {
                break;
            }
        }
        assertEquals(m, pm.getMatMass("b0"), 0.0);
        assertTrue(m < 1 && pm.getStabilityReport().isStable(), "b0 stopped at " + m);
        double lastMass = m;
        assertThrows(UnstableModelException.class, () -> pm.setMatMass("b0", lastMass * 0.97));
        assertEquals(lastMass, pm.getMatMass("b0"), 0.0);
        pm.computeNSteps(10_000);
        StabilityFixtures.assertFiniteState(pm, "after refusals");

        // an oscillator's damping ramped up toward 2M - K/2 = 1.995
        PhysicalModel reed = new PhysicalModel(1000);
        reed.setStabilityPolicy(StabilityPolicy.THROW);
        reed.addOsc1D("reed", 1.0, 0.01, 0.05, new Vect3D(), new Vect3D(0, 0, 10));
        reed.init();
        double z = 0.05;
        for (int s = 0; s < 300; s++) {
            try {
                reed.setMatDamping("reed", z + 0.01);
                z += 0.01;
            } catch (UnstableModelException e) {
                break;
            }
        }
        assertEquals(z, reed.getMatDamping("reed"), 0.0);
        assertTrue(z > 1.98 && z < 1.995, "Z stopped at " + z);
        reed.computeNSteps(10_000);
        StabilityFixtures.assertFiniteState(reed, "reed after refusal");
    }

    // ------------------------------------------------------------------ haptic input with a noisy target

    // The HeavyMassChain of the paper (10 Mass3D of mass 50, SpringDamper3D l0 0.1, K 0.003, Z 0.05) held by a
    // HapticInput3D (EWMA smoothing 10) at 1 kHz, whose target jumps to a random point of [-1, 1]^3 every 5 s and
    // jitters by ±0.05 on every axis at every step (a noisy encoder). Over 2 x 10^5 steps: the avatar stays within
    // the targets' bounding box (a convex average), the forces read back are finite, and the model's energy never
    // exceeds E0 plus the absolute work done by the avatar, sum |½ (F(n-1) + F(n)) · Δx_avatar(n)|.
    @Test
    @DisplayName("haptic input driven by a noisy target: finite, avatar inside the target hull, energy <= E0 + |work|")
    void hapticNoisyTarget() {
        PhysicalModel pm = new PhysicalModel(1000);
        pm.addHapticInput3D("avatar", new Vect3D(), 10);
        for (int i = 0; i < 10; i++) {
            pm.addMass3D("m" + i, 50, new Vect3D(0.1 * (i + 1), 0, 0), new Vect3D());
        }
        for (int i = 0; i < 9; i++) {
            pm.addSpringDamper3D("k" + i, 0.1, 0.003, 0.05, "m" + i, "m" + (i + 1));
        }
        pm.addSpringDamper3D("grip", 0.1, 0.003, 0.05, "avatar", "m0");
        assertEquals("", StabilityFixtures.captureStdErr(pm::init));
        SplittableRandom rnd = new SplittableRandom(5);
        double e0 = pm.getTotalEnergy();
        double work = 0;
        double worst = 0;
        double excess = Double.NEGATIVE_INFINITY;
        Vect3D prev = pm.getMatPosition("avatar");
        Vect3D force = new Vect3D();
        Vect3D base = new Vect3D();
        for (int n = 0; n < 200_000; n++) {
            if (n % 5000 == 0) {
                base.set(2 * rnd.nextDouble() - 1, 2 * rnd.nextDouble() - 1, 2 * rnd.nextDouble() - 1);
            }
            pm.setHapticPosition("avatar", new Vect3D(base.x + 0.05 * (2 * rnd.nextDouble() - 1),
                    base.y + 0.05 * (2 * rnd.nextDouble() - 1), base.z + 0.05 * (2 * rnd.nextDouble() - 1)));
            pm.computeStep();
            Vect3D p = pm.getMatPosition("avatar");
            Vect3D f = pm.getHapticForce("avatar");
            assertTrue(f.isFinite());
            assertTrue(Math.abs(p.x) <= 1.05 && Math.abs(p.y) <= 1.05 && Math.abs(p.z) <= 1.05, "avatar " + p);
            work += Math.abs(0.5 * ((force.x + f.x) * (p.x - prev.x) + (force.y + f.y) * (p.y - prev.y)
                    + (force.z + f.z) * (p.z - prev.z)));
            force = f;
            prev = p;
            double e = pm.getTotalEnergy();
            excess = Math.max(excess, e - e0 - work);
            if (work > 0) {
                worst = Math.max(worst, (e - e0) / work);
            }
        }
        StabilityFixtures.assertFiniteState(pm, "haptic chain");
        System.out.printf(Locale.ROOT, "[stability] haptic noisy target: |work| %.3e, max (E - E0)/|work| = %.3f%n",
                work, worst);
        assertTrue(excess <= 0, "energy above E0 + |work| by " + excess);
    }
}
