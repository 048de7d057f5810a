package tactus.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import tactus.Osc3D;
import tactus.PhysicalModel;
import tactus.Vect3D;

/**
 * Parameter changes in the middle of a run take effect at once, whichever route they take (handle, name,
 * subset). The reference implementation kept stale precomputed coefficients in three places (oscillator
 * stiffness set by index, oscillator friction given at creation, subset stiffness of oscillators); these
 * tests pin the correct behaviour.
 *
 * <p>Theory: an Osc3D coordinate Y = X - rest obeys Y(n+1) = (2 - (K + Z + f)/M) Y(n) - (1 - (Z + f)/M) Y(n-1)
 * with the coefficients in force during step n+1 (the oscillator's spring and damper are part of its mass
 * update). A free Mass3D with friction f obeys D(n+1) = (1 - f/M) D(n) for its displacement per step.
 */
class ParameterChangeTest {
    private static final double M = 1.5;
    private static final double K1 = 0.05 * M;
    private static final double K2 = 0.6 * M;
    private static final int N0 = 537;

    private static PhysicalModel oscModel(double k, double z) {
        PhysicalModel pm = new PhysicalModel(1000, 30);
        pm.addOsc3D("o", M, k, z, new Vect3D(0, 0, 0), new Vect3D(0, 0, 100));
        pm.init();
        return pm;
    }

    /** Residual of one step against the oscillator recurrence with coefficients (k, z), relative to |Y|. */
    private static void assertOscStep(String what, double k, double z, double yPrev, double y, double yNext) {
        double expected = (2 - (k + z) / M) * y - (1 - z / M) * yPrev;
        assertEquals(expected, yNext, 1e-14 * (Math.abs(y) + Math.abs(yPrev)), what);
    }

    // K1 -> K2 through each public route: the very next step uses K2, and the period becomes that of K2/M.
    @Test
    void oscStiffnessChangeAppliesAtTheNextStepThroughEveryRoute() {
        String[] routes = {"handle", "setMatStiffness", "changeStiffnessParamOfSubset", "changeParamOfSubset",
                           "setMatStiffnessAt"};
        for (String route : routes) {
            PhysicalModel pm = oscModel(K1, 0);
            pm.createMatSubset("oscs");
            pm.addMatToSubset("o", "oscs");
            double[] before = Signals.record(pm, "o", 2, 0, N0);
            switch (route) {
                case "handle":
                    ((Osc3D) pm.getMass("o")).setStiffness(K2);
                    break;
                case "setMatStiffness":
                    pm.setMatStiffness("o", K2);
                    break;
                case "changeStiffnessParamOfSubset":
                    pm.changeStiffnessParamOfSubset(K2, "oscs");
                    break;
                case "changeParamOfSubset":
                    pm.changeParamOfSubset(K2, "oscs", "stiffness");
                    break;
                default:
                    pm.setMatStiffnessAt(0, K2);
            }
            assertEquals(K2, pm.getMatStiffness("o"), 0.0, route);
            double[] after = Signals.record(pm, "o", 2, 0, 20000);
            assertOscStep(route + ": first step after the change", K2, 0, before[N0 - 1], before[N0], after[1]);
            assertTrue(Signals.relErr(Signals.fittedPeriod(after, 1, after.length - 1),
                    Signals.discretePeriod(K2 / M)) < 1e-9, route + ": period after the change");
        }
    }

    // Internal damping and mass changes apply at the next step too.
    @Test
    void oscDampingAndMassChangesApplyAtTheNextStep() {
        PhysicalModel pm = oscModel(K1, 0);
        double[] y = Signals.record(pm, "o", 2, 0, N0);
        pm.setMatDamping("o", 0.01 * M);
        double[] y2 = Signals.record(pm, "o", 2, 0, 3);
        assertOscStep("after setMatDamping", K1, 0.01 * M, y[N0 - 1], y[N0], y2[1]);
        assertOscStep("after setMatDamping, step 2", K1, 0.01 * M, y2[0], y2[1], y2[2]);
        double newMass = 2 * M;
        pm.setMatMass("o", newMass);
        double[] y3 = Signals.record(pm, "o", 2, 0, 2);
        double expected = (2 - (K1 + 0.01 * M) / newMass) * y3[0] - (1 - 0.01 * M / newMass) * y2[2];
        assertEquals(expected, y3[1], 1e-14 * Math.abs(y3[0]), "after setMatMass");
    }

    // Friction given before the oscillator is created is part of its damping from the first step
    // (the reference implementation ignored it until setFriction was called again).
    @Test
    void frictionSetBeforeCreationActsOnAnOscillator() {
        double f = 0.002;
        PhysicalModel pm = new PhysicalModel(1000, 30);
        pm.setFriction(f);
        pm.addOsc3D("o", M, K1, 0.001, new Vect3D(0, 0, 0), new Vect3D(0, 0, 100));
        pm.init();
        double[] y = Signals.record(pm, "o", 2, 0, 3000);
        // Y(-1) = -0.1, Y(0) = 0
        assertOscStep("step 1", K1, 0.001 + f, -0.1, 0, y[1]);
        double[] ab = Signals.fitAr2(y, 1, y.length - 1);
        assertEquals(1 - (0.001 + f) / M, ab[1], 1e-12, "pole radius^2 = 1 - (Z + f)/M");
    }

    // setFriction mid-run (0 -> f switches kernels, f -> f2 does not) reaches oscillators at the next step.
    @Test
    void frictionChangeMidRunActsOnAnOscillatorAtTheNextStep() {
        PhysicalModel pm = oscModel(K1, 0.001);
        double[] y = Signals.record(pm, "o", 2, 0, N0);
        pm.setFriction(0.003);
        double[] y2 = Signals.record(pm, "o", 2, 0, 400);
        assertOscStep("0 -> 0.003", K1, 0.004, y[N0 - 1], y[N0], y2[1]);
        pm.setFriction(0.0005);
        double[] y3 = Signals.record(pm, "o", 2, 0, 2);
        assertOscStep("0.003 -> 0.0005", K1, 0.0015, y2[399], y2[400], y3[1]);
        pm.setFriction(0);
        double[] y4 = Signals.record(pm, "o", 2, 0, 2);
        assertOscStep("0.0005 -> 0", K1, 0.001, y3[1], y3[2], y4[1]);
    }

    // setFriction mid-run on Mass3D, Mass2DPlane and Mass1D: the displacement decays by 1 - f/M per step at once.
    @Test
    void frictionChangeMidRunActsOnFreeMasses() {
        PhysicalModel pm = new PhysicalModel(1000, 30);
        pm.addMass3D("m3", M, new Vect3D(0, 0, 0), new Vect3D(0, 0, 3));
        pm.addMass2DPlane("m2", M, new Vect3D(0, 0, 0), new Vect3D(0, 3, 0));
        pm.addMass1D("m1", M, new Vect3D(0, 0, 0), new Vect3D(0, 0, 3));
        pm.init();
        pm.computeNSteps(10);
        double[] fs = {0.01, 0.04, 0};
        double d = 0.003;
        for (double f : fs) {
            pm.setFriction(f);
            for (int n = 0; n < 5; n++) {
                pm.computeStep();
                d *= 1 - f / M;
                assertEquals(d, pm.getMatVelocity("m3").z / 1000, 1e-15, "Mass3D, f=" + f);
                assertEquals(d, pm.getMatVelocity("m2").y / 1000, 1e-15, "Mass2DPlane, f=" + f);
                assertEquals(d, pm.getMatVelocity("m1").z / 1000, 1e-15, "Mass1D, f=" + f);
            }
        }
    }

    // A link stiffness change (by name or link subset) changes the period of a mass on a spring. The force
    // buffer of the step in progress was computed before the change, so the recurrence with the new K is
    // checked from the second step after it.
    @Test
    void linkStiffnessChangeThroughNameAndSubset() {
        for (boolean subset : new boolean[] {false, true}) {
            PhysicalModel pm = new PhysicalModel(1000, 30);
            pm.addGround3D("g", new Vect3D(0, 0, 0));
            pm.addMass3D("m", M, new Vect3D(0, 0, 1.2), new Vect3D(0, 0, 0));
            pm.addSpring3D("s", 1.0, K1, "m", "g");
            pm.createLinkSubset("springs");
            pm.addLinkToSubset("s", "springs");
            pm.init();
            pm.computeNSteps(N0);
            if (subset) {
                pm.changeStiffnessParamOfSubset(K2, "springs");
            } else {
                pm.setLinkStiffness("s", K2);
            }
            double[] y = Signals.record(pm, "m", 2, 1.0, 20000);
            for (int n = 2; n < 50; n++) {
                assertOscStep("link recurrence at step " + n, K2, 0, y[n - 1], y[n], y[n + 1]);
            }
            assertTrue(Signals.relErr(Signals.fittedPeriod(y, 2, y.length - 1), Signals.discretePeriod(K2 / M))
                    < 1e-9);
        }
    }

    // Setting an oscillator's velocity keeps its position and must keep its anchor: afterwards it oscillates
    // about the original rest point with Y(n0+1) = (2 - K/M) Y(n0) - (Y(n0) - v/fs).
    @Test
    void setVelocityKeepsTheOscillatorAnchor() {
        PhysicalModel pm = oscModel(K1, 0);
        double[] y = Signals.record(pm, "o", 2, 0, 300);
        assertTrue(Math.abs(y[300]) > 0.1, "the oscillator is away from its rest point");
        ((Osc3D) pm.getMass("o")).setVelocity(new Vect3D(0, 0, 50));
        assertEquals(y[300], pm.getMatPosition("o").z, 0.0, "setVelocity keeps the position");
        double[] after = Signals.record(pm, "o", 2, 0, 2000);
        double r = K1 / M;
        double w = Math.acos(1 - r / 2);
        double y0 = y[300];
        double y1 = (2 - r) * y0 - (y0 - 0.05);
        double b = (y1 - y0 * Math.cos(w)) / Math.sin(w);
        for (int j = 0; j <= 2000; j++) {
            assertEquals(y0 * Math.cos(w * j) + b * Math.sin(w * j), after[j], 1e-9,
                    "oscillation about the original anchor, step " + j + " after setVelocity");
        }
    }
}
