package tactus;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicReference;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Defect 9 of issue 15: in locked mode a running ParamController ramp made a stepping batch keep the model's lock
 * for the whole batch (a setter waited 3.1-3.6 s instead of 7 ms), where an unramped batch lets a waiting thread in
 * between two slices. Here a long ramped batch (computeNSteps, or one long draw_physics frame) runs on one thread
 * and another thread makes several changes once the batch is under way: each change (and a step count read after
 * it) must return while the batch is still running, and the last change must be in effect at the end. Ordering and
 * progress are asserted, never a duration.
 */
class RampSlicesTest {
    private static final int MASSES = 300;

    @ParameterizedTest(name = "{0}, {1} changes")
    @CsvSource({"computeNSteps, 4", "draw_physics, 2"})
    @Timeout(120)
    void changesMadeDuringARampedBatchReturnBeforeTheBatchEnds(String call, int changes) throws Exception {
        int steps = 24_000;
        PhysicalModel m = rampedChain();
        m.getParamController("k").triggerRamp(0.2f); // a 100 s ramp: it runs through the whole batch
        AtomicBoolean batchDone = new AtomicBoolean();
        AtomicReference<Throwable> error = new AtomicReference<>();
        if (call.equals("draw_physics")) {
            m.setDisplayRate(44100 / steps + 1); // one frame of about 22,000 steps
        }
        Thread stepper = new Thread(() -> {
            try {
                if (call.equals("draw_physics")) {
                    m.draw_physics();
                } else {
                    m.computeNSteps(steps);
                }
            } catch (Throwable t) {
                error.set(t);
            } finally {
                batchDone.set(true);
            }
        }, "stepper");
        stepper.start();
        // wait until the batch is under way: the step count is read between two of its slices (the snapshot is no
        // longer a progress signal: inside one draw_physics frame it is published at the end of the frame)
        while (m.getStepCount() <= 0 && !batchDone.get()) {
            Thread.sleep(1);
        }
        assertFalse(batchDone.get(), "the batch ended before any change could be made (make it longer, or the "
                + "batch kept the lock throughout)");
        long[] stepsWhenReturned = new long[changes];
        for (int c = 0; c < changes; c++) {
            m.setLinkStiffness("extra", 0.05 + 0.01 * c);
            stepsWhenReturned[c] = m.getStepCount(); // lets this thread in between two slices as well
        }
        stepper.join();
        assertNull(error.get());
        long total = m.getStepCount();
        assertTrue(total >= 20_000, "the batch ran " + total + " steps");
        for (int c = 0; c < changes; c++) {
            assertTrue(stepsWhenReturned[c] < total, "change " + c + " waited for the whole ramped batch ("
                    + stepsWhenReturned[c] + " of " + total + " steps run when it returned)");
        }
        assertTrue(m.getParamController("k").isRamping(), "the ramp must have run through the whole batch");
        assertEquals(0.05 + 0.01 * (changes - 1), m.getLinkStiffness("extra"), 1e-15);
    }

    /** A chain of springs in a ramped subset, and one spring outside it that the changes address. */
    private static PhysicalModel rampedChain() {
        PhysicalModel m = new PhysicalModel(44100, 60);
        m.setStabilityPolicy(StabilityPolicy.OFF);
        m.addGround3D("g0", new Vect3D(0, 0, 0));
        m.createLinkSubset("springs");
        String prev = "g0";
        for (int i = 1; i <= MASSES; i++) {
            m.addMass3D("m" + i, 1, new Vect3D(i, 0, 0), new Vect3D());
            m.addSpringDamper3D("s" + i, 1, 0.1, 0.001, prev, "m" + i);
            m.addLinkToSubset("s" + i, "springs");
            prev = "m" + i;
        }
        m.addSpring3D("extra", 1, 0.01, "g0", "m1");
        m.addParamController("k", "springs", "stiffness", 100f);
        m.init();
        return m;
    }
}
