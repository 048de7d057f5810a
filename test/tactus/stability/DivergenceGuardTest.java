package tactus.stability;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import tactus.DivergenceException;
import tactus.PhysicalModel;
import tactus.StabilityPolicy;
import tactus.Vect3D;

/**
 * Regression tests for five engine defects found by the hard-case work (and fixed in src/ since): the subnormal
 * flush fed energy into decaying models, forces from a diverged state survived the documented repair, a new check
 * interval waited for the old countdown, the energy of a switched-off attractor at distance 0 was NaN (dLim = 0 is now rejected), and the
 * flush skipped an axis that another module kept busy. Each comment gives the old cause; each test states the
 * correct behaviour.
 */
class DivergenceGuardTest {


    // Was: the flush zeroed each coordinate below 1e-150 on its own, X(n) and X(n-1) separately, and left the
    // force buffers (computed from the unflushed positions) in place. The next step turned those stale forces
    // into fresh motion: a damped chain started entirely below the threshold (scale 2^-500 ~ 3e-151) gained
    // ~200x its energy in 10^4 steps and kept ringing at ~1e-149 forever. Now: it must never gain energy and
    // must end exactly at rest.
    @Test
    @DisplayName("the subnormal flush never adds energy: a damped chain below 1e-150 ends exactly at rest")
    void flushNeverAddsEnergy() {
        PhysicalModel pm = StabilityFixtures.dampedChain1D(Math.scalb(1.0, -500));
        double e0 = pm.getTotalEnergy();
        assertTrue(e0 > 0);
        double prev = e0;
        for (int b = 0; b < 100; b++) {
            pm.computeNSteps(100);
            double e = pm.getTotalEnergy();
            assertTrue(e <= e0, "a damped model gained energy through the flush: " + e0 + " -> " + e);
            prev = e;
        }
        assertEquals(0.0, prev, 0.0, "at rest");
        for (int i = 0; i < pm.getNumberOfMats(); i++) {
            assertEquals(0.0, pm.getMatPosAt(i).z, 0.0);
        }
    }

    // Was: when the guard froze a model, the force buffers kept the forces of the last interaction phase,
    // computed from the exploded positions (~K x 1e12), and the documented recovery (repair positions and
    // parameters, then clearDivergence) could not clear them: the first step after the repair threw the mass
    // ~1e16 away. Now: the repaired model restarts from its repaired state.
    @Test
    @DisplayName("after clearDivergence a repaired model restarts from its repaired state (no stale forces)")
    void cleanRestartAfterRepair() {
        PhysicalModel pm = new PhysicalModel(44100);
        pm.setStabilityPolicy(StabilityPolicy.OFF);
        pm.addGround3D("anchor", new Vect3D());
        pm.addMass3D("bob", 2, new Vect3D(1.05, 0, 0), new Vect3D());
        pm.addSpringDamper3D("stiff", 1.0, 8.08, 0, "anchor", "bob");
        pm.init();
        assertThrows(DivergenceException.class, () -> {
            for (int i = 0; i < 100; i++) {
                pm.computeNSteps(64);
            }
        });
        pm.setLinkStiffness("stiff", 1.0);   // repair the parameter ...
        pm.setMatPosition("bob", new Vect3D(1.05, 0, 0));   // ... and the state: at rest, 0.05 from rest length
        pm.clearDivergence();
        long stepsAtRepair = pm.getStepCount();
        // The repaired model must restart exactly like a model freshly built in the repaired state: at rest, so
        // its first step moves nothing (no force computed yet: x stays 1.05 bit for bit), and from then on the
        // same positions, bit for bit.
        pm.computeStep();
        assertEquals(1.05, pm.getMatPosition("bob").x, 0.0, "first step after the repair, pending force "
                + pm.getMatForce("bob"));
        PhysicalModel twin = new PhysicalModel(44100);
        twin.setStabilityPolicy(StabilityPolicy.OFF);
        twin.addGround3D("anchor", new Vect3D());
        twin.addMass3D("bob", 2, new Vect3D(1.05, 0, 0), new Vect3D());
        twin.addSpringDamper3D("stiff", 1.0, 1.0, 0, "anchor", "bob");
        twin.init();
        twin.computeStep();
        for (int i = 0; i < 200; i++) {
            assertEquals(twin.getMatPosition("bob").x, pm.getMatPosition("bob").x, 0.0, "step " + i
                    + " after the repair");
            assertEquals(twin.getMatForce("bob").x, pm.getMatForce("bob").x, 0.0, "force, step " + i);
            twin.computeStep();
            pm.computeStep();
        }
        // The closed form of the scheme from rest at 1 + e: x(n) - 1 = A cos(ω (n - 1/2)) (x(0) = x(1)), cos ω = 1 - K/(2M),
        // A = e / cos(ω/2). Its peak is reached, and never exceeded (no energy from the divergence).
        double omega = Math.acos(1 - 1.0 / (2 * 2));
        double amplitude = 0.05 / Math.cos(omega / 2);
        double peak = 0;
        for (int i = 0; i < 200; i++) {
            pm.computeStep();
            double x = pm.getMatPosition("bob").x;
            assertEquals(amplitude * Math.cos(omega * (pm.getStepCount() - stepsAtRepair - 0.5)), x - 1.0, 1e-12,
                    "step " + (pm.getStepCount() - stepsAtRepair) + " after the repair");
            peak = Math.max(peak, Math.abs(x - 1.0));
        }
        assertEquals(amplitude, peak, 1e-3 * amplitude);
    }

    // Was: the countdown to the next scan was re-armed only after a scan, so setDivergenceCheckInterval(1) took
    // effect only after up to 63 more steps (or the old interval, however long), breaking "detected at most
    // interval steps after it appears". Now: the new interval applies at once.
    @Test
    @DisplayName("setDivergenceCheckInterval(1) applies at once: a position beyond the limit is caught by the next step")
    void intervalChangeAppliesAtOnce() {
        PhysicalModel pm = new PhysicalModel(1000);
        pm.addMass3D("m", 1, new Vect3D(), new Vect3D());
        pm.init();
        pm.computeNSteps(10);
        pm.setDivergenceCheckInterval(1);
        pm.setMatPosition("m", new Vect3D(1e13, 0, 0));
        DivergenceException e = assertThrows(DivergenceException.class, pm::computeStep,
                "a position beyond the limit must be caught by the next step when checking every step");
        assertEquals(11, e.getStep());
    }

    // Was: EnergyMeter added -A / max(d, dLim) for every attractor: 0/0 = NaN for an attractor switched off
    // (A = 0) with dLim = 0 between coincident masses, while the kernel itself skips d = 0. dLim = 0 is now
    // rejected (the force is unbounded as d -> 0), so the case is the closest legal one: a switched-off attractor
    // with the smallest positive limit between coincident masses. Its energy term is -0 / dLim = 0 exactly.
    @Test
    @DisplayName("getTotalEnergy() is 0 for a zero attractor with the smallest dLim between coincident masses")
    void attractorEnergyNaN() {
        PhysicalModel pm = new PhysicalModel(1000);
        pm.addMass3D("a", 1, new Vect3D(), new Vect3D());
        pm.addMass3D("b", 1, new Vect3D(), new Vect3D());
        assertThrows(IllegalArgumentException.class, () -> pm.addAttractor3D("off", 0, 0, "a", "b"));
        pm.addAttractor3D("off", Double.MIN_VALUE, 0, "a", "b");
        pm.init();
        pm.computeNSteps(10);
        assertEquals(0.0, pm.getTotalEnergy(), 0.0, "total energy");
    }

    // Was: the whole-axis flush only fired when EVERY coordinate of the axis was below 1e-150. In the paper's
    // PluckedString layout (miphysics-facts §4: a Mass2DPlane string vibrating in y around y = 0, the haptic
    // avatar parked at y = -1 with a Contact3D to every bead) the avatar kept the y axis busy, so the decaying
    // string sank into the subnormal range after ~7.5e5 steps (friction 2e-3) and every step cost ~12x more
    // (~330 -> ~4,000 ns/step on 30 beads). Now: the beads are flushed one by one.
    @Test
    @DisplayName("a decaying string is kept out of the subnormal range when the haptic avatar sits on the same axis")
    void busyAxisStillFlushed() {
        PhysicalModel pm = new PhysicalModel(44100);
        int n = 30;
        pm.setFriction(2e-3);
        pm.addGround3D("left", new Vect3D(0, 0, 0));
        pm.addGround3D("right", new Vect3D(0.1 * (n + 1), 0, 0));
        for (int i = 0; i < n; i++) {
            double shape = i < 8 ? (i + 1) / 8.0 : (n - i) / (double) (n - 8);
            pm.addMass2DPlane("str" + i, 1, new Vect3D(0.1 * (i + 1), 0.05 * shape, 0), new Vect3D());
        }
        for (int i = 0; i <= n; i++) {
            pm.addSpringDamper3D("k" + i, 0.05, 0.4, 0.01, i == 0 ? "left" : "str" + (i - 1),
                    i == n ? "right" : "str" + i);
        }
        pm.addHapticInput3D("hapticMass", new Vect3D(0, -1, 0), 30);
        for (int i = 0; i < n; i++) {
            pm.addContact3D("touch" + i, 0.5, 0.01, 0.01, "hapticMass", "str" + i);
        }
        pm.init();
        pm.computeNSteps(900_000);
        int subnormal = 0;
        for (int i = 0; i < n; i++) {
            Vect3D p = pm.getMatPosition("str" + i);
            double y = Math.abs(p.y);
            if (y != 0 && y < Double.MIN_NORMAL) {
                subnormal++;
            }
        }
        assertEquals(0, subnormal, "beads with a subnormal y after 9e5 steps (the string has decayed by 10^-308)");
    }
}
