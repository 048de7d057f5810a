package tactus;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicReference;
import java.util.concurrent.locks.LockSupport;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.api.Test;

/**
 * What a snapshot holds equals what the model's own getters say (positions, types, interaction ends, types and
 * elongations, bit for bit) after init, steps, topology changes, a late request for interactions and a long gap
 * between reads; and a concurrent reader never sees a torn or stale-forever copy, in locked and realtime mode, for
 * several batch sizes and reading rates.
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class SnapshotContentTest {
    private static final int RATE = 1024;
    private static final double V = 1.0 / RATE;   // one unit per second: 2^-10 per step, exact in binary

    /** Asserts that the snapshot shows the model's current step exactly (the caller is the only thread using it). */
    static void assertSameAsModel(PhysicalModel m, ModelSnapshot s) {
        assertEquals(m.getStepCount(), s.getStep(), "step");
        assertEquals(m.getNumberOfMats(), s.getNumberOfMats(), "masses");
        for (int i = 0; i < s.getNumberOfMats(); i++) {
            Vect3D p = m.getMatPosAt(i);
            assertEquals(p.x, s.x(i), 0.0, "x of mass " + i);
            assertEquals(p.y, s.y(i), 0.0, "y of mass " + i);
            assertEquals(p.z, s.z(i), 0.0, "z of mass " + i);
            assertEquals(m.getMatTypeAt(i), s.getMatType(i), "type of mass " + i);
        }
        if (!s.hasLinks()) {
            return;
        }
        assertEquals(m.getNumberOfLinks(), s.getNumberOfLinks(), "interactions");
        for (int l = 0; l < s.getNumberOfLinks(); l++) {
            assertEquals(m.getLinkMat1IdxAt(l), s.getLinkMat1Idx(l), "first end of link " + l);
            boolean plane = m.getLinkTypeAt(l) == linkModuleType.PlaneContact3D;   // the snapshot repeats its mass
            assertEquals(plane ? m.getLinkMat1IdxAt(l) : m.getLinkMat2IdxAt(l), s.getLinkMat2Idx(l),
                    "second end of link " + l);
            assertEquals(m.getLinkTypeAt(l), s.getLinkType(l), "type of link " + l);
            assertEquals(m.getLinkElongationAt(l), s.getLinkElongation(l), 0.0, "elongation of link " + l);
        }
    }

    /** Every kind of distance: 3D springs and contacts, a 1D spring, plane contacts on each axis, fixed points. */
    private static PhysicalModel mixed() {
        PhysicalModel m = new PhysicalModel(1000, 50);
        m.addGround3D("g", new Vect3D(0, 0, 0));
        for (int i = 0; i < 6; i++) {
            m.addMass3D("m" + i, 1, new Vect3D(i + 1, 0.1 * i, -0.05 * i), new Vect3D(0.5, -0.3 * i, 0.2));
        }
        m.addMass1D("a", 1, new Vect3D(0, 0, 0.2), new Vect3D(0, 0, 1));
        m.addMass1D("b", 1, new Vect3D(0, 0, 1.5), new Vect3D());
        m.addSpringDamper1D("one", 1, 0.01, 0.001, "a", "b");
        m.addSpring3D("s0", 1, 0.02, "g", "m0");
        for (int i = 1; i < 6; i++) {
            m.addSpringDamper3D("s" + i, 1, 0.02, 0.001, "m" + (i - 1), "m" + i);
        }
        m.addContact3D("touch", 0.8, 0.05, 0.001, "m1", "m3");
        for (int axis = 0; axis < 3; axis++) {
            m.addPlaneContact("plane" + axis, 0.1, 0.05, 0.001, axis, 0.25 * axis - 0.2, "m" + (2 + axis));
        }
        m.init();
        return m;
    }

    @Test
    void afterInitStepsAndTopologyChangesTheCopyIsTheModel() {
        PhysicalModel m = mixed();
        assertSameAsModel(m, m.getSnapshot());
        for (int frame = 0; frame < 20; frame++) {
            m.draw_physics();
            assertSameAsModel(m, m.getSnapshot());
        }
        m.computeNSteps(37);
        assertSameAsModel(m, m.getSnapshot());
        m.addMass3D("new", 2, new Vect3D(3, 3, 3), new Vect3D());
        assertSameAsModel(m, m.getSnapshot());
        m.addContact3D("newTouch", 1, 0.01, 0.001, "new", "m4");
        assertSameAsModel(m, m.getSnapshot());
        m.computeNSteps(11);
        m.removeLink("s2");
        assertSameAsModel(m, m.getSnapshot());
        m.removeMatAndConnectedLinks("m0");
        assertSameAsModel(m, m.getSnapshot());
        m.changeToFixedPoint("m3");
        assertSameAsModel(m, m.getSnapshot());
        for (int frame = 0; frame < 4; frame++) {   // every buffer sees the new length parameters and plane
            m.setLinkDRest("s4", 1.1 + 0.1 * frame);
            ((PlaneContact3D) m.getInteraction("plane1")).setPlanePosition(0.3 + 0.01 * frame);
            assertSameAsModel(m, m.getSnapshot());
            m.computeStep();
            assertSameAsModel(m, m.getSnapshot());
        }
        m.computeStep();
        assertSameAsModel(m, m.getSnapshot());
    }

    @Test
    void aModelReadOnlyAfterEditsShowsTheEditsAtTheFirstRead() {
        PhysicalModel m = mixed();
        m.computeNSteps(100);
        m.removeMatAndConnectedLinks("m2");
        m.addMass3D("late", 1, new Vect3D(-1, 0, 0), new Vect3D());
        m.addSpring3D("lateSpring", 1, 0.01, "late", "g");
        m.computeNSteps(5);
        assertSameAsModel(m, m.getSnapshot());
    }

    @Test
    void aLongGapBetweenReadsGivesAFreshCopy() {
        PhysicalModel m = mixed();
        assertSameAsModel(m, m.getSnapshot());
        m.computeNSteps(20_000);
        assertSameAsModel(m, m.getSnapshot());
        for (int i = 0; i < 3000; i++) {
            m.computeStep();
        }
        assertSameAsModel(m, m.getSnapshot());
    }


    /** Checks one copy of the drifting model: one step's state, exactly, with the link's elongation of that step. */
    private static void checkDrifting(ModelSnapshot s, int n) {
        long step = s.getStep();
        double drift = step * V;
        assertEquals(n + 1, s.getNumberOfMats());
        for (int i = 0; i < n; i++) {
            if (s.x(i) != i + drift || s.y(i) != -i) {
                throw new AssertionError("torn snapshot at step " + step + ": mass " + i + " at " + s.x(i));
            }
        }
        if (s.hasLinks()) {
            double dx = drift - 0;
            double dy = 0 - 5.0;
            double expected = Math.sqrt(dx * dx + dy * dy + 0.0) - 1;
            assertEquals(expected, s.getLinkElongation(0), 0.0, "elongation at step " + step);
            assertEquals(0, s.getLinkMat1Idx(0));
            assertEquals(n, s.getLinkMat2Idx(0));
        }
    }

    /**
     * A stepping thread (locked mode, or the realtime owner) runs batches of a given size; a reader thread reads at a
     * given pause: every copy is one step's state, copies go forward, and after the stepping stops the reader's
     * copy reaches the last step (never stale for ever). In realtime mode the first read after a pause may be the
     * copy of the pause's start; the next one, after the owner stepped, is fresh.
     */
    @ParameterizedTest
    @CsvSource({"false, 1, 0", "false, 7, 200", "false, 300, 2000", "true, 1, 0", "true, 16, 500",
            "true, 333, 3000"})
    void aConcurrentReaderSeesWholeFreshCopies(boolean realtime, int batch, long pauseMicros) throws Exception {
        int n = 48;
        PhysicalModel m = SnapshotTest.drifting(n);
        if (realtime) {
            m.beginRealtimeStepping();
        }
        AtomicBoolean stop = new AtomicBoolean();
        AtomicLong stepped = new AtomicLong();
        AtomicReference<Throwable> error = new AtomicReference<>();
        Thread stepper = new Thread(() -> {
            try {
                long deadline = System.nanoTime() + 1_500_000_000L;
                while (!stop.get() && System.nanoTime() < deadline) {
                    m.computeNSteps(batch);
                    stepped.addAndGet(batch);
                }
            } catch (Throwable t) {
                error.compareAndSet(null, t);
            }
        }, "stepper");
        AtomicLong reads = new AtomicLong();
        Thread reader = new Thread(() -> {
            try {
                long last = -1;
                while (!stop.get() || reads.get() == 0) {
                    ModelSnapshot s = m.getSnapshot();
                    assertTrue(s.getStep() >= last, "copies go forward");
                    last = s.getStep();
                    if (last >= 0) {
                        checkDrifting(s, n);
                    }
                    if ((reads.incrementAndGet() & 63) == 0) {
                        s.requestLinks((reads.get() & 64) == 0);   // change what is read now and then
                    }
                    if (pauseMicros > 0) {
                        LockSupport.parkNanos(pauseMicros * 1000);
                    }
                }
            } catch (Throwable t) {
                error.compareAndSet(null, t);
                stop.set(true);
            }
        }, "reader");
        stepper.start();
        reader.start();
        stepper.join(20_000);
        stop.set(true);
        reader.join(20_000);
        assertNull(error.get(), () -> "failed: " + error.get());
        assertTrue(reads.get() > 0);
        long last = stepped.get();
        if (realtime) {
            // the first read may be an older copy; the owner's next frame of steps publishes for it
            ModelSnapshot first = m.getSnapshot();
            checkDrifting(first, n);
            Thread owner = new Thread(() -> m.computeNSteps(RATE / 64));
            owner.start();
            owner.join(10_000);
            last += RATE / 64;
        }
        ModelSnapshot s = m.getSnapshot();
        checkDrifting(s, n);
        assertEquals(last, s.getStep(), "after the stepping stopped, the read shows the last step");
        if (realtime) {
            m.endRealtimeStepping();
        }
    }

    /** In realtime mode, a topology change made by another thread is in the copy when the change returns. */
    @Test
    void inRealtimeModeAnEditIsPublishedBeforeItReturns() throws Exception {
        PhysicalModel m = mixed();
        m.beginRealtimeStepping();
        AtomicBoolean stop = new AtomicBoolean();
        Thread owner = new Thread(() -> {
            while (!stop.get()) {
                m.computeNSteps(8);
                LockSupport.parkNanos(200_000);
            }
        }, "owner");
        owner.start();
        try {
            ModelSnapshot s = m.getSnapshot();
            int links = s.getNumberOfLinks();
            int masses = s.getNumberOfMats();
            m.addMass3D("added", 1, new Vect3D(9, 9, 9), new Vect3D());
            m.addSpring3D("addedSpring", 1, 0.01, "added", "g");
            s = m.getSnapshot();
            assertEquals(masses + 1, s.getNumberOfMats());
            assertEquals(links + 1, s.getNumberOfLinks());
            assertEquals(masses, s.getLinkMat1Idx(links), "the new spring's first end is the new mass");
            assertEquals(0, s.getLinkMat2Idx(links));
            m.removeLink("s3");
            s = m.getSnapshot();
            assertEquals(links, s.getNumberOfLinks());
        } finally {
            stop.set(true);
            owner.join(10_000);
        }
        m.endRealtimeStepping();
        assertSameAsModel(m, m.getSnapshot());
    }
}
