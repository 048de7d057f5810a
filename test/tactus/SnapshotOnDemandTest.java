package tactus;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import tactus.internal.snapshot.SnapshotWriter;

/**
 * The render snapshot costs only what is read: a model nobody reads copies nothing, a reader of masses only causes
 * no walk over the interactions, interaction ends are walked once per topology, and the stepping thread publishes at
 * most once per display frame of simulated time. Counted with the writer's package-private counters.
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class SnapshotOnDemandTest {
    private static final int RATE = 1000;
    private static final int FPS = 50;   // a display frame is 20 steps

    /** A chain of n masses between two fixed points, springs between neighbours, one contact, plucked. */
    static PhysicalModel chain(int n) {
        PhysicalModel m = new PhysicalModel(RATE, FPS);
        m.addGround3D("g0", new Vect3D(0, 0, 0));
        for (int i = 0; i < n; i++) {
            m.addMass3D("m" + i, 1, new Vect3D(i + 1, i == n / 2 ? 0.3 : 0, 0), new Vect3D());
        }
        m.addGround3D("g1", new Vect3D(n + 1, 0, 0));
        for (int i = 0; i <= n; i++) {
            m.addSpringDamper3D("s" + i, 1, 0.05, 0.001, i == 0 ? "g0" : "m" + (i - 1), i == n ? "g1" : "m" + i);
        }
        m.addContact3D("c", 0.5, 0.05, 0.001, "m0", "m2");
        m.init();
        return m;
    }

    private static SnapshotWriter writer(PhysicalModel m) {
        return m.core.snapshots;
    }

    /**
     * Runs {@code body} on a new thread of that name (a thread that becomes the model's owner), waits for it (at most
     * 50 s) and fails with its exception, if it threw one.
     */
    static void onThread(String name, Body body) throws InterruptedException {
        AtomicReference<Throwable> error = new AtomicReference<>();
        Thread t = new Thread(() -> {
            try {
                body.run();
            } catch (Throwable e) {
                error.set(e);
            }
        }, name);
        t.start();
        t.join(50_000);
        assertFalse(t.isAlive(), name + " still runs after 50 s");
        assertEquals(null, error.get());
    }

    /** What {@link #onThread} runs; it may throw (the exception fails the test). */
    interface Body {
        void run() throws Exception;
    }

    @Test
    void aModelNobodyReadsCopiesNothingWhateverSteppingAndEditingItSees() {
        PhysicalModel m = chain(40);
        m.computeNSteps(3000);
        for (int i = 0; i < 300; i++) {
            m.computeStep();
        }
        for (int i = 0; i < 30; i++) {
            m.draw_physics();
        }
        m.addMass3D("extra", 1, new Vect3D(5, 5, 0), new Vect3D());
        m.addSpring3D("toExtra", 1, 0.01, "m3", "extra");
        m.removeLink("s7");
        m.removeMatAndConnectedLinks("m30");
        m.computeNSteps(500);
        SnapshotWriter w = writer(m);
        assertEquals(0, w.publishes, "publications of a model nobody reads");
        assertEquals(0, w.massesCopied, "masses copied for nobody");
        assertEquals(0, w.linksCopied, "interactions copied for nobody");

        ModelSnapshot s = m.getSnapshot();   // the first read publishes the current state and topology
        assertEquals(1, w.publishes);
        assertEquals(m.getStepCount(), s.getStep());
        SnapshotContentTest.assertSameAsModel(m, s);
    }

    @Test
    @Timeout(value = 30, unit = TimeUnit.SECONDS)
    void aRealtimeModelNobodyReadsCopiesNothingWhileItSteps() throws Exception {
        PhysicalModel m = chain(40);
        m.beginRealtimeStepping();
        SnapshotWriter w = writer(m);
        long before = w.publishes;
        onThread("owner", () -> {
            for (int i = 0; i < 200; i++) {
                m.computeNSteps(64);
            }
            for (int i = 0; i < 1000; i++) {
                m.computeStep();
            }
        });
        assertEquals(before, w.publishes, "publications while nobody reads");
        m.endRealtimeStepping();
    }

    @Test
    void aReaderOfMassesOnlyCausesNoWalkOverTheInteractions() {
        PhysicalModel m = chain(30);
        ModelSnapshot s = m.getSnapshot();
        assertTrue(s.hasLinks(), "interactions are copied by default");
        s.requestLinks(false);
        SnapshotWriter w = writer(m);
        long links = w.linksCopied;
        long walks = w.linkWalks;
        long masses = w.massesCopied;
        for (int frame = 0; frame < 40; frame++) {
            m.draw_physics();
            s = m.getSnapshot();
            assertFalse(s.hasLinks());
            assertEquals(0, s.getNumberOfLinks());
            assertEquals(m.getMatPosAt(5).y, s.y(5), 0.0);
        }
        m.addSpring3D("late", 1, 0.01, "m1", "m9");   // a topology change while only masses are read
        m.draw_physics();
        s = m.getSnapshot();
        assertEquals(links, w.linksCopied, "no interaction copied for a reader of masses");
        assertEquals(walks, w.linkWalks, "no walk over interaction ends for a reader of masses");
        assertTrue(w.massesCopied >= masses + 40L * m.getNumberOfMats(), "masses are still copied");
        ModelSnapshot last = s;
        IllegalStateException e = assertThrows(IllegalStateException.class, () -> last.getLinkElongation(0));
        assertTrue(e.getMessage().contains("requestLinks"), e.getMessage());

        s.requestLinks(true);   // asked late: the next read carries them, matching the model
        s = m.getSnapshot();
        assertTrue(s.hasLinks());
        SnapshotContentTest.assertSameAsModel(m, s);
    }

    @Test
    void interactionEndsAreWalkedOncePerTopology() {
        PhysicalModel m = chain(30);
        SnapshotWriter w = writer(m);
        m.getSnapshot();
        assertEquals(1, w.linkWalks);
        for (int frame = 0; frame < 50; frame++) {
            m.draw_physics();
            SnapshotContentTest.assertSameAsModel(m, m.getSnapshot());
        }
        assertEquals(1, w.linkWalks, "ends and types come from the cache while the topology stays");
        assertTrue(w.linksCopied <= 3L * m.getNumberOfLinks(),
                "unchanged length parameters are copied once per buffer at most: " + w.linksCopied);
        m.removeLink("s4");
        m.draw_physics();
        SnapshotContentTest.assertSameAsModel(m, m.getSnapshot());
        assertEquals(2, w.linkWalks, "walked again after a topology change, once");
        for (int frame = 0; frame < 10; frame++) {
            m.draw_physics();
            m.getSnapshot();
        }
        assertEquals(2, w.linkWalks);
    }

    /**
     * A realtime owner stepping one step per call, read after every call: one publication per display frame of
     * simulated time (the old writer published every half frame).
     */
    @Test
    @Timeout(value = 30, unit = TimeUnit.SECONDS)
    void theOwnerPublishesAtMostOncePerDisplayFrame() throws Exception {
        PhysicalModel m = chain(20);
        m.getSnapshot();
        m.beginRealtimeStepping();
        SnapshotWriter w = writer(m);
        long before = w.publishes;
        int frames = 100;
        onThread("owner", () -> {
            for (int i = 0; i < frames * RATE / FPS; i++) {
                m.computeStep();
                m.getSnapshot();
            }
        });
        long published = w.publishes - before;
        assertTrue(published <= frames, published + " publications in " + frames + " display frames");
        assertTrue(published >= frames - 1, "a reader reading every step gets every frame: " + published);
        m.endRealtimeStepping();
    }

    /** A locked-mode reader that stops reading stops the copies a few frames later; reading again resumes them. */
    @Test
    void aReaderThatStopsStopsTheCopiesAndResumesThem() {
        PhysicalModel m = chain(20);
        SnapshotWriter w = writer(m);
        m.getSnapshot();
        long after = w.publishes;
        m.computeNSteps(RATE * 10);   // ten seconds, 500 frames, nobody reading
        assertTrue(w.publishes - after <= SnapshotWriter.KEEP_FRAMES,
                (w.publishes - after) + " publications while nobody read");
        ModelSnapshot s = m.getSnapshot();
        assertEquals(m.getStepCount(), s.getStep(), "the read after the gap is fresh (locked mode, lock free)");
        SnapshotContentTest.assertSameAsModel(m, s);
    }

    /**
     * Stepping with a reader allocates nothing: one thread steps one step per call and reads every position and
     * elongation once per display frame, in locked mode (the reader publishes) and in realtime mode (the owner
     * publishes). Measured per round of 20,000 steps, after a warm-up round.
     */
    @Test
    void steppingAndReadingAllocateNothing() throws Exception {
        com.sun.management.ThreadMXBean mx =
                (com.sun.management.ThreadMXBean) java.lang.management.ManagementFactory.getThreadMXBean();
        for (boolean realtime : new boolean[] {false, true}) {
            PhysicalModel m = chain(40);
            if (realtime) {
                m.beginRealtimeStepping();
            }
            long[] bytes = new long[6];
            double[] sink = new double[1];
            onThread("stepper and reader", () -> {
                long id = Thread.currentThread().getId();
                for (int round = 0; round < bytes.length; round++) {
                    long a0 = mx.getThreadAllocatedBytes(id);
                    for (int k = 1; k <= 20_000; k++) {
                        m.computeStep();
                        if (k % (RATE / FPS) == 0) {
                            ModelSnapshot s = m.getSnapshot();
                            for (int i = 0; i < s.getNumberOfMats(); i++) {
                                sink[0] += s.x(i);
                            }
                            for (int l = 0; l < s.getNumberOfLinks(); l++) {
                                sink[0] += s.getLinkElongation(l);
                            }
                        }
                    }
                    bytes[round] = mx.getThreadAllocatedBytes(id) - a0;
                }
            });
            assertTrue(writer(m).publishes >= 4000 / (RATE / FPS), "it did publish: " + writer(m).publishes);
            boolean someRoundClean = false;
            for (int round = 2; round < bytes.length; round++) {
                // one object per step would be 320 KB a round; what the JIT may still do (a deoptimisation
                // materialising an eliminated object, a few kilobytes once) stays far below that
                assertTrue(bytes[round] < 10_000, (realtime ? "realtime" : "locked") + ": bytes allocated in round "
                        + round + " of " + java.util.Arrays.toString(bytes));
                someRoundClean |= bytes[round] == 0;
            }
            assertTrue(someRoundClean, "no round without allocation: " + java.util.Arrays.toString(bytes));
            if (realtime) {
                m.endRealtimeStepping();
            }
        }
    }
}
