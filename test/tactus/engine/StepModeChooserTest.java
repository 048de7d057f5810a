package tactus.engine;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * The engine steps a big plan on one thread where the parallel split does not pay, on the parallel stepper where
 * it does, and probes again as the load changes; the results are the same bit for bit either way. Times come from
 * a scripted clock: each mode's step costs what the test says.
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class StepModeChooserTest {
    /** A clock that advances by the cost of the mode the chooser last asked for, per step. */
    private static final class ScriptedClock implements java.util.function.LongSupplier {
        long now;

        @Override
        public long getAsLong() {
            return now;
        }
    }

    @Test
    void theChooserKeepsTheFasterModeAndProbesTheOtherAgainLater() {
        ScriptedClock c = new ScriptedClock();
        StepModeChooser m = new StepModeChooser(c);
        long parallelCost = 7_000;   // ns per step: parallel is 7 times slower, as on a loaded machine
        long serialCost = 1_000;
        int parallelRuns = 0;
        long steps = 0;
        while (steps < 3 * StepModeChooser.REPROBE_STEPS) {
            boolean par = m.parallelNext();
            int chunk = m.probing() ? 1 : 100;
            long t0 = m.now();
            c.now += chunk * (par ? parallelCost : serialCost);
            m.record(par, chunk, m.now() - t0);
            steps += chunk;
            parallelRuns += par ? 1 : 0;
        }
        assertTrue(parallelRuns >= 2 && parallelRuns <= 4, "one probe step each " + StepModeChooser.REPROBE_STEPS
                + " steps, no more: " + parallelRuns);
        assertEquals(parallelRuns, m.parallelSteps(), "every parallel run was a one-step probe");
        // the load goes: parallel becomes twice as fast; after the next probe the chooser keeps it
        parallelCost = 500;
        long before = m.parallelSteps();
        for (int i = 0; i < 200; i++) {
            boolean par = m.parallelNext();
            int chunk = m.probing() ? 1 : 100;
            long t0 = m.now();
            c.now += chunk * (par ? parallelCost : serialCost);
            m.record(par, chunk, m.now() - t0);
        }
        assertTrue(m.parallelSteps() - before > 100 * 100, "parallel is chosen once it pays: "
                + (m.parallelSteps() - before));
    }

    @Test
    void nearlyEqualModesKeepOneThreadAndAClearGainPicksTheParallelMode() {
        for (long parallelCost : new long[] {950, 1000, 1050, 850, 500}) {
            ScriptedClock c = new ScriptedClock();
            StepModeChooser m = new StepModeChooser(c);
            long serialCost = 1_000;
            long parallelChunks = 0;
            long chunks = 0;
            for (int i = 0; i < 40; i++) {
                boolean par = m.parallelNext();
                boolean probe = m.probing();
                int chunk = probe ? 1 : 100;
                long t0 = m.now();
                c.now += chunk * (par ? parallelCost : serialCost);
                m.record(par, chunk, m.now() - t0);
                if (!probe) {
                    chunks++;
                    parallelChunks += par ? 1 : 0;
                }
            }
            boolean pays = parallelCost <= 0.9 * serialCost;
            assertEquals(pays ? chunks : 0, parallelChunks, "parallel at " + parallelCost + " ns per step against "
                    + serialCost + " on one thread");
        }
    }

    private static Engine chain(int n, int threads) {
        Engine e = new Engine();
        int prev = -1;
        for (int i = 0; i < n; i++) {
            int id = e.addMass(MassKind.MASS3D, 1, i, 0, 0, 0, i % 5 == 0 ? 0.01 : 0, 0);
            if (prev >= 0) {
                e.addLink(LinkKind.SPRING_DAMPER3D, prev, id, 0.1, 0.01, 1);
            }
            prev = id;
        }
        e.setParallelThreshold(0);
        if (threads > 1) {
            e.setThreads(threads);
        }
        return e;
    }

    @Test
    void theEngineProbesBothModesAndGivesTheSameResultsAsOneThread() {
        int n = 5000;
        try (Engine one = chain(n, 1); Engine two = chain(n, 2)) {
            long[] t = {0};
            two.setModeClock(() -> t[0] += 1000);
            int total = 0;
            for (int b = 0; b < 20; b++) {
                total += two.step(50);
                one.step(50);
            }
            assertEquals(1000, total);
            long[] modes = two.stepsByMode();
            assertEquals(1000, modes[0] + modes[1]);
            assertTrue(modes[0] >= 1 && modes[1] >= 1, "both modes ran: " + modes[0] + " parallel, " + modes[1] + " serial");
            double[] a = new double[3];
            double[] b = new double[3];
            int moving = 0;
            for (int id = 0; id < n; id++) {
                one.position(id, a);
                two.position(id, b);
                assertArrayEquals(a, b, 0, "mass " + id);
                moving += a[1] != 0 ? 1 : 0;
            }
            assertTrue(moving > n / 10, "the chain moves: " + moving);
        }
    }
}
