package tactus;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.atomic.AtomicReference;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * Minimal reproductions of the facade defects found by random API sequences (issue #10 §1 item 10, and
 * {@link ApiSequenceFuzzTest}): each is a few calls with the expected behaviour. Those that fail on the code
 * they were written against are disabled with the defect named; enable each one with its fix.
 */
class FacadeRegressionTest {

    /** A model with one free mass "a" that has diverged (a position beyond the limit, caught by the guard). */
    private static PhysicalModel diverged() {
        PhysicalModel m = new PhysicalModel(1000);
        m.addMass3D("a", 1, new Vect3D(), new Vect3D());
        m.addMass3D("b", 1, new Vect3D(1, 0, 0), new Vect3D());
        m.init();
        m.setMatPosition("a", new Vect3D(1e13, 0, 0));
        assertThrows(DivergenceException.class, () -> m.computeNSteps(64));
        assertTrue(m.isDiverged());
        return m;
    }

    // Expected: once the diverged mass is gone, nothing is diverged any more (the divergence belonged to that mass;
    // isDiverged() must not report a mass that no longer exists) and stepping works.
    // Actual: computeStep, computeNSteps and draw_physics throw IllegalArgumentException "no live mass with id 0"
    // from Engine.checkMass (the guard still points at the removed mass).
    @Test
    void steppingAfterRemovingTheDivergedMassWorks() {
        PhysicalModel m = diverged();
        m.removeMatAndConnectedLinks("a");
        assertFalse(m.isDiverged(), "the diverged mass is gone");
        long before = m.getStepCount();
        m.computeStep();
        m.computeNSteps(3);
        assertEquals(1000 / 30, m.draw_physics(), "first frame at 1 kHz / 30 fps");
        assertEquals(before + 1 + 3 + 1000 / 30, m.getStepCount());
    }

    // Expected: after clearModel() the model is empty and usable: rebuild it and it steps.
    // Actual: the first step throws IllegalArgumentException "no live mass with id 0" from Engine.checkMass.
    @Test
    void clearModelAfterADivergenceGivesAUsableModel() {
        PhysicalModel m = diverged();
        m.clearModel();
        assertFalse(m.isDiverged());
        m.addMass3D("c", 1, new Vect3D(), new Vect3D(0, 0, 1000));   // 1 unit per step along z
        m.computeStep();
        assertEquals(1.0, m.getMatPosition("c").z, 0.0);
    }

    // The same with a divergence listener: expected the rebuilt model moves; actual it stays frozen without a word.
    @Test
    void clearModelAfterADivergenceWithAListenerGivesAMovingModel() {
        PhysicalModel m = new PhysicalModel(1000);
        int[] events = new int[1];
        m.setDivergenceListener(e -> events[0]++);
        m.addMass3D("a", 1, new Vect3D(), new Vect3D());
        m.init();
        m.setMatPosition("a", new Vect3D(1e13, 0, 0));
        m.computeNSteps(64);
        assertEquals(1, events[0]);
        m.clearModel();
        m.addMass3D("c", 1, new Vect3D(), new Vect3D(0, 0, 1000));
        m.computeNSteps(2);
        assertEquals(2.0, m.getMatPosition("c").z, 0.0, "the rebuilt model moves");
        assertEquals(1, events[0]);
    }

    // Expected: under THROW a setSimRate that would make the model unstable is rejected and leaves the model
    // exactly as it was (same rate, same K and Z bit for bit, same state).
    // Actual: the undo re-applies the rate change backwards, so K (and Z) come back rescaled twice, off by
    // round-off (for example K = 4.258132062946079E7 comes back as 4.258132062946078E7).
    @Test
    void rejectedSetSimRateLeavesTheModelIdentical() {
        for (int i = 0; i < 10; i++) {
            PhysicalModel m = new PhysicalModel(44100, 60, paramSystem.REAL_UNITS);
            // stable at 44.1 kHz (K/M/fs^2 ~ 0.01), far beyond the bound at 300 Hz
            m.addOsc3D("o", 2.0675724149034 + i / 7.0, 4.258132062946079E7 * (1 + i / 13.0), 181.39028598489858 + i,
                    new Vect3D(0.4, -0.7, -0.5), new Vect3D(0, 0, -0.25));
            m.init();
            m.computeNSteps(5);
            m.setStabilityPolicy(StabilityPolicy.THROW);
            String before = ModelState.of(m);
            assertThrows(UnstableModelException.class, () -> m.setSimRate(300));
            assertEquals(before, ModelState.of(m), "case " + i);
        }
    }

    // Expected: a thread count no machine can run is rejected with an IllegalArgumentException that names the
    // value, and the model keeps its thread count. Actual: NegativeArraySizeException from ParallelStepper.
    // (Counts in the hundreds of thousands also start that many threads before failing; not run here.)
    @Test
    void absurdThreadCountIsRejectedClearly() {
        PhysicalModel m = new PhysicalModel(1000);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> m.setThreads(Integer.MAX_VALUE));
        assertTrue(e.getMessage().contains(String.valueOf(Integer.MAX_VALUE)), e.getMessage());
        assertEquals(1, m.getThreads());
    }

    /** Two masses "a" (origin) and "b" (1, 0, 0) in subset "s" with a contact group of threshold thr, or an explicit Contact3D. */
    private static PhysicalModel pair(boolean group, double thr) {
        PhysicalModel m = new PhysicalModel(1000);
        m.addMass3D("a", 1, new Vect3D(0, 0, 0), new Vect3D());
        m.addMass3D("b", 1, new Vect3D(1, 0, 0), new Vect3D());
        if (group) {
            m.createMatSubset("s");
            m.addMatToSubset("a", "s");
            m.addMatToSubset("b", "s");
            m.addContactGroup("s", thr, 0.1, 0.0);
        } else {
            m.addContact3D("c", thr, 0.1, 0.0, "a", "b");
        }
        m.init();
        return m;
    }

    // Expected: with one member far away on every axis no contact is engaged: the potential energy is 0.
    // Actual: IllegalArgumentException "fromIndex(0) > toIndex(-1299088447)" from Arrays.fill in
    // ContactGroupKernel.rebuildDense (the dense grid's cell count overflows). With the member at 1e6 on every
    // axis the same call allocates until OutOfMemoryError (not run here).
    @Test
    void contactGroupEnergyWithAFarMemberIsZero() {
        PhysicalModel m = pair(true, 0.01);
        m.setMatPosition("b", new Vect3D(1e9, 1e9, 1e9));
        assertEquals(0.0, m.getPotentialEnergy(), 0.0);
        m.computeStep();
        assertEquals(0.0, m.getPotentialEnergy(), 0.0);
    }

    // Expected: the same with the far member at 1e6 on every axis: energy 0, and a step runs. Actual: the dense
    // grid over the members' bounding box asks for ~10^23 cells: OutOfMemoryError from
    // ContactGroupKernel.rebuildDense (one oversized array request, so the JVM survives it). The random sequences
    // reach it through divergence, gravity or a rate change that sends one member far away.
    @Test
    void contactGroupWithAFarMemberNeedsLittleMemory() {
        PhysicalModel m = pair(true, 0.01);
        m.setMatPosition("b", new Vect3D(1e6, 1e6, 1e6));
        try {
            assertEquals(0.0, m.getPotentialEnergy(), 0.0);
            m.computeNSteps(10);
        } catch (OutOfMemoryError e) {
            // caught here: JUnit treats an escaping OutOfMemoryError as fatal and aborts the whole run
            throw new AssertionError("a two-member contact group ran out of memory: " + e.getMessage());
        }
        assertEquals(1e6, m.getMatPosition("b").x, 0.0);
    }

    // Expected: a contact group with a tiny threshold over a unit-size scene steps normally (no pair is within
    // 1e-12, so nothing moves). Actual: computeStep throws IllegalArgumentException "fromIndex(0) >
    // toIndex(-2026690064)" from Arrays.fill in ContactGroupKernel.rebuildDense: the dense grid's cell count,
    // (extent / cell)^3 ~ 10^36, overflows. The random sequences found it with threshold Double.MIN_VALUE, where
    // it runs out of memory instead.
    @Test
    void contactGroupWithATinyThresholdSteps() {
        for (double thr : new double[] {1e-12, 1e-100, Double.MIN_VALUE}) {
            PhysicalModel m = new PhysicalModel(1000);
            m.addMass3D("a", 1, new Vect3D(0, 0, 0), new Vect3D());
            m.addMass3D("b", 1, new Vect3D(1, 1, 1), new Vect3D());
            m.createMatSubset("s");
            m.addMatToSubset("a", "s");
            m.addMatToSubset("b", "s");
            m.addContactGroup("s", thr, 0.1, 0.01);
            m.init();
            try {
                m.computeNSteps(3);
                assertEquals(0.0, m.getPotentialEnergy(), 0.0);
            } catch (OutOfMemoryError e) {
                throw new AssertionError("threshold " + thr + ": out of memory: " + e.getMessage());
            }
            assertEquals(1.0, m.getMatPosition("b").z, 0.0, "threshold " + thr);
        }
    }

    // Expected: right after setMatPosition (no step yet) a contact group stores the same energy as the same
    // explicit Contact3D: ½ K (thr - d)² = ½ 0.1 (0.5 - 0.25)² = 0.003125. Actual: the group reports 0 until the
    // next step rebuilds its neighbour list.
    @Test
    void contactGroupEnergyAfterSetMatPositionMatchesExplicitContacts() {
        PhysicalModel group = pair(true, 0.5);
        PhysicalModel explicit = pair(false, 0.5);
        group.computeNSteps(3);
        explicit.computeNSteps(3);
        group.setMatPosition("b", new Vect3D(0.25, 0, 0));
        explicit.setMatPosition("b", new Vect3D(0.25, 0, 0));
        double expected = 0.5 * 0.1 * (0.5 - 0.25) * (0.5 - 0.25);
        assertEquals(expected, explicit.getPotentialEnergy(), 1e-18);
        assertEquals(explicit.getPotentialEnergy(), group.getPotentialEnergy(), 1e-18);
    }

    // docs/modules.md (Osc3D): "Moving an oscillator with setMatPosition also moves its rest point."
    // Decided: setMatPosition moves an oscillator's mass, not its rest point (docs/modules.md now says so): the
    // oscillator is left displaced at rest and swings back. With K = 0.01, Z = 0.001, M = 1 and x(0) = x(-1) = 1,
    // the scheme gives the damped recurrence below exactly.
    @Test
    void setMatPositionDisplacesAnOscillatorFromItsRestPoint() {
        PhysicalModel m = new PhysicalModel(1000);
        m.addOsc3D("o", 1, 0.01, 0.001, new Vect3D(), new Vect3D());
        m.init();
        m.setMatPosition("o", new Vect3D(1, 0, 0));
        double prev = 1, x = 1;
        for (int n = 0; n < 100; n++) {
            double next = x + (1 - 0.001) * (x - prev) - 0.01 * x;
            prev = x;
            x = next;
        }
        m.computeNSteps(100);
        assertEquals(x, m.getMatPosition("o").x, 1e-12, "swinging around the rest point it was created at");
        assertTrue(x < 0, "it crossed its rest point at x = 0");
    }

    // An oscillator whose damping alone breaks the bound (M = 1, K = 0.1, Z = 3: (K + 2Z)/M = 6.1 > 4).
    // Expected: the stability message names "o" and does not give K a negative limit (no K can fix it: it must
    // blame Z, or say that lowering K alone cannot help). Actual: "K = 0.1000 is above its limit of about -2.000".
    @Test
    void stabilityMessageNeverGivesANegativeLimit() {
        PhysicalModel m = new PhysicalModel(1000);
        m.addOsc3D("o", 1, 0.1, 3, new Vect3D(), new Vect3D());
        m.setStabilityPolicy(StabilityPolicy.OFF);
        m.init();
        String msg = m.describeStability();
        assertTrue(msg.contains("\"o\""), msg);
        assertFalse(msg.matches(".*limit of about -.*"), msg);
        m.setStabilityPolicy(StabilityPolicy.THROW);
        UnstableModelException e = assertThrows(UnstableModelException.class, m::init);
        assertFalse(e.getMessage().matches(".*limit of about -.*"), e.getMessage());
    }

    // A reader thread calls getPosition() on a valid handle; the call has passed the handle's validity check and
    // waits for the model's lock, which this thread holds while it removes the mass. Expected: the reader gets
    // the documented IllegalStateException (a handle whose module left the model). Actual: it gets
    // IllegalArgumentException "no live mass with id 0" from Engine.checkMass.
    @Test
    @Timeout(20)
    void handleReadRacingARemovalThrowsIllegalStateException() throws Exception {
        PhysicalModel m = new PhysicalModel(1000);
        Mass h = m.addMass3D("a", 1, new Vect3D(), new Vect3D());
        m.init();
        AtomicReference<Throwable> seen = new AtomicReference<>();
        Thread reader = new Thread(() -> {
            try {
                h.getPosition();
            } catch (Throwable t) {
                seen.set(t);
            }
        }, "reader");
        m.getLock().lock();
        try {
            reader.start();
            while (reader.getState() != Thread.State.WAITING) {
                assertTrue(reader.isAlive(), "the reader must wait for the lock");
                Thread.onSpinWait();
            }
            m.removeMatAndConnectedLinks("a");
        } finally {
            m.getLock().unlock();
        }
        reader.join();
        assertTrue(seen.get() instanceof IllegalStateException, "got " + seen.get());
        assertFalse(h.isValid());
    }

    // ------------------------------------------------------------------ passing guards

    // Rejected calls under THROW that already restore the model exactly: kept so that they stay so.
    @Test
    void rejectedStiffnessUnderThrowLeavesTheModelIdentical() {
        PhysicalModel m = new PhysicalModel(44100, 60, paramSystem.REAL_UNITS);
        m.addGround3D("g", new Vect3D());
        m.addMass3D("a", 0.01, new Vect3D(0.1, 0, 0), new Vect3D());
        m.addSpringDamper3D("s", 0.05, 1000, 0.1, "g", "a");
        m.init();
        m.computeNSteps(10);
        m.setStabilityPolicy(StabilityPolicy.THROW);
        String before = ModelState.of(m);
        assertThrows(UnstableModelException.class, () -> m.setLinkStiffness("s", 1e9));
        assertEquals(before, ModelState.of(m));
    }
}
