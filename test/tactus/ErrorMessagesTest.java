package tactus;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;

/**
 * The messages of the model's errors say what to do: a model stepped before init() warns once; an unstable link's
 * message names the link, its value, its limit in the model's units and the fixes; a DivergenceException names the
 * module most likely at fault.
 */
class ErrorMessagesTest {
    /** Runs {@code r} and returns what it printed on standard error. */
    static String stderrOf(Runnable r) {
        PrintStream before = System.err;
        ByteArrayOutputStream copy = new ByteArrayOutputStream();
        System.setErr(new PrintStream(copy, true, StandardCharsets.UTF_8));
        try {
            r.run();
        } finally {
            System.setErr(before);
        }
        return copy.toString(StandardCharsets.UTF_8);
    }

    private static int count(String text, String part) {
        int n = 0;
        for (int i = text.indexOf(part); i >= 0; i = text.indexOf(part, i + 1)) {
            n++;
        }
        return n;
    }

    private static PhysicalModel spring(double k, paramSystem units) {
        PhysicalModel m = new PhysicalModel(1000, 50, units);
        m.addGround3D("g", new Vect3D(0, 0, 0));
        m.addMass3D("m", 1.0, new Vect3D(0, 1, 0), new Vect3D(0, 1, 0));
        m.addSpringDamper3D("s", 1.0, k, 0.0, "g", "m");
        return m;
    }

    @Test
    void aModelSteppedBeforeInitWarnsOnceThenNeverAgain() {
        PhysicalModel m = spring(0.1, paramSystem.ALGO_UNITS);
        String err = stderrOf(() -> {
            m.computeStep();
            m.computeNSteps(10);
            m.draw_physics();
        });
        assertEquals(1, count(err, "init() was never called"), err);
        assertTrue(err.contains("Tactus: computeStep() on a model whose init() was never called: it steps, but its "
                + "stability is not checked"), err);
        assertTrue(err.contains("Call init() once the model is built"), err);
        PhysicalModel other = spring(0.1, paramSystem.ALGO_UNITS);
        assertEquals(1, count(stderrOf(() -> other.computeNSteps(5)), "computeNSteps() on a model whose init()"),
                "once per model: a second model warns too");
        PhysicalModel initialised = spring(0.1, paramSystem.ALGO_UNITS);
        initialised.init();
        assertFalse(stderrOf(() -> {
            initialised.computeStep();
            initialised.draw_physics();
        }).contains("init()"), "an initialised model does not warn");
    }

    @Test
    void anUnstableLinkNamesItsValueItsLimitAndTheFixesInModelUnits() {
        PhysicalModel m = spring(5.0, paramSystem.ALGO_UNITS);
        m.setStabilityPolicy(StabilityPolicy.THROW);
        UnstableModelException e = assertThrows(UnstableModelException.class, m::init);
        String msg = e.getMessage();
        // one mass of 1 on a ground: (K + 2Z) / M < 4, so the limit of K is 4
        assertTrue(msg.startsWith("Tactus: unstable model: SpringDamper3D \"s\": K = 5.000 is above its limit of about "
                + "4.000 (model units). Fix: lower K below 4.000, raise the masses it joins, or take more steps per frame"
                + " with K divided by the factor's square"), msg);
        assertFalse(msg.contains("M^-1"), "no matrices: " + msg);
    }

    @Test
    void inRealUnitsTheLimitIsInNewtonsPerMetreAndGrowsWithTheRate() {
        // At 1 kHz a real stiffness K (N/m) is K / fs^2 per step: the limit of 4 per step is 4e6 N/m for 1 kg.
        PhysicalModel m = spring(5e6, paramSystem.REAL_UNITS);
        String msg = m.describeStability();
        assertTrue(msg.contains("SpringDamper3D \"s\": K = 5.000e+06 is above its limit of about 4.000e+06 N/m. Fix: "
                + "lower K below 4.000e+06, raise the masses it joins, or take more steps per frame (a higher simulation"
                + " rate, setSimRate, raises the limit of K with its square)"), msg);
    }

    @Test
    void aDivergenceNamesTheLinkMostLikelyAtFault() {
        PhysicalModel m = spring(5.0, paramSystem.ALGO_UNITS);
        m.setStabilityPolicy(StabilityPolicy.OFF);
        m.init();
        DivergenceException e = assertThrows(DivergenceException.class, () -> m.computeNSteps(10_000));
        String msg = e.getMessage();
        assertTrue(msg.startsWith("Mass3D \"m\" diverged at step "), msg);
        assertTrue(msg.contains("most likely cause: SpringDamper3D \"s\": K = 5.000 is above its limit of about 4.000"
                + " (model units). Fix: lower K below 4.000"), msg);
        assertTrue(e.getSuspect().startsWith("SpringDamper3D \"s\""), e.getSuspect());
    }

    @Test
    void aDivergenceOfAStableModelSaysWhatElseToLookFor() {
        PhysicalModel m = spring(0.1, paramSystem.ALGO_UNITS);
        m.setStabilityPolicy(StabilityPolicy.OFF);
        m.init();
        m.setDivergenceLimit(100);
        m.setMatVelocity("m", new Vect3D(1e6, 0, 0));
        DivergenceException e = assertThrows(DivergenceException.class, () -> m.computeNSteps(1_000));
        String msg = e.getMessage();
        assertTrue(msg.contains("most likely cause: no module is above its stability limit (the closest is "
                + "SpringDamper3D \"s\", at 3 % of the bound), so look at what drives the mass: a large force or "
                + "velocity set from outside"), msg);
    }
}
