package tactus.engine;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;

import org.junit.jupiter.api.Test;

/**
 * An analysis with an assumed coefficient ({@link StabilityAnalyzer.Assumption}) must give bit for bit the report
 * of the same scene with that coefficient really written, for every place a stiffness enters the analysis (a link
 * of the permanent network, a contact, an oscillator's own spring), and must leave the analysed plan untouched.
 * The stability messages find a stiffness limit this way instead of writing the probe value into the engine.
 */
class AnalysisAssumptionTest {
    private static final double PROBE = 1.37;

    /** A chain with a spring, an oscillator and a contact, each stiff enough to matter; returns its ids. */
    private static int[] build(Engine e, double springK, double oscK, double contactK) {
        int g = e.addMass(MassKind.GROUND3D, 0, 0, 0, 0, 0, 0, 0);
        int a = e.addMass(MassKind.MASS3D, 1.5, 1, 0, 0, 0, 0, 0);
        int o = e.addMass(MassKind.OSC3D, 0.8, 2, 0, 0, 0, 0, 0);
        e.setOscillator(o, oscK, 0.01);
        int b = e.addMass(MassKind.MASS3D, 0.6, 3, 0, 0, 0, 0, 0);
        int s = e.addLink(LinkKind.SPRING_DAMPER3D, g, a, springK, 0.02, 1);
        e.addLink(LinkKind.SPRING3D, a, o, 0.3, 0, 1);
        int c = e.addLink(LinkKind.CONTACT3D, o, b, contactK, 0.005, 1);
        e.addLink(LinkKind.SPRING3D, b, g, 0.2, 0, 3);
        return new int[] {s, o, c};
    }

    private static double[] summary(StabilityReport r) {
        return new double[] {r.lambda(), r.lambdaContacts(), r.culpritLink(), r.culpritMass(), r.culpritGroup()};
    }

    @Test
    void anAssumedStiffnessGivesTheReportOfTheSceneWithThatStiffnessWritten() {
        double springK = 0.9, oscK = 0.7, contactK = 0.4;
        Engine live = new Engine();
        int[] ids = build(live, springK, oscK, contactK);
        StepPlan p = live.plan();
        double[] before = summary(StabilityAnalyzer.analyze(p));

        String[] what = {"spring", "oscillator", "contact"};
        StabilityAnalyzer.Assumption[] assumed = {
            StabilityAnalyzer.Assumption.linkStiffness(ids[0], springK * PROBE),
            StabilityAnalyzer.Assumption.oscillatorStiffness(ids[1], oscK * PROBE),
            StabilityAnalyzer.Assumption.linkStiffness(ids[2], contactK * PROBE),
        };
        for (int w = 0; w < 3; w++) {
            Engine written = new Engine();
            build(written, w == 0 ? springK * PROBE : springK, w == 1 ? oscK * PROBE : oscK,
                    w == 2 ? contactK * PROBE : contactK);
            double[] expected = summary(StabilityAnalyzer.analyze(written.plan()));
            double[] got = summary(StabilityAnalyzer.analyze(p, StabilityAnalyzer.DEFAULT_MAX_CONTACTS, assumed[w]));
            assertArrayEquals(expected, got, 0.0, what[w]);
            assertNotEquals(before[0] + before[1], got[0] + got[1], what[w] + ": the assumption changed nothing");
        }
        // the live scene was only read
        assertArrayEquals(before, summary(StabilityAnalyzer.analyze(p)), 0.0);
        assertEquals(springK, live.linkStiffness(ids[0]), 0.0);
        assertEquals(oscK, live.oscStiffness(ids[1]), 0.0);
        assertEquals(contactK, live.linkStiffness(ids[2]), 0.0);
    }
}
