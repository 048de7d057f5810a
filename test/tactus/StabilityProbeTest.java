package tactus;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.util.Locale;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.locks.LockSupport;
import java.util.function.DoubleSupplier;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * Defect 6 of issue 15: the stiffness limit in a stability message was found by writing K * 1.01 into the live
 * engine, analysing, and writing back the K read before, from whichever thread asked (describeStability() on the
 * drawing thread, the WARN helper thread), so a realtime owner could step with the probe value and a ramp's last
 * value could be overwritten by the stale one. Here a watcher reads the culprit's coefficient from the engine while
 * another thread asks for the message over and over: it must never see another value. The limit in the message
 * must still be right (a single oscillator's is exact), and a ramp run by a realtime owner must end at its target.
 */
class StabilityProbeTest {
    private static final int DESCRIPTIONS = 150;

    @Test
    @Timeout(60)
    void describingAnUnstableSpringNeverWritesItsStiffness() throws Exception {
        PhysicalModel m = unstableChain();
        int id = m.core.dir.linkId("describe", culprit(m));
        double k = m.core.engine.linkStiffness(id);
        long changes = watchWhile(() -> m.core.engine.linkStiffness(id), k, () -> {
            for (int i = 0; i < DESCRIPTIONS; i++) {
                String d = m.describeStability();
                assertTrue(d.contains("SpringDamper3D \"s") && d.contains("K = 1.200"), d);
            }
        });
        assertEquals(0, changes, "another thread saw the spring's stiffness change while the stability was described");
    }

    @Test
    @Timeout(60)
    void describingAnUnstableOscillatorNeverWritesItsStiffnessAndGivesItsExactLimit() throws Exception {
        PhysicalModel m = new PhysicalModel(44100, 60);
        m.setStabilityPolicy(StabilityPolicy.OFF);
        double mass = 2, z = 0.1;
        m.addOsc3D("o", mass, 9.5, z, new Vect3D(), new Vect3D());
        m.init();
        m.setStabilityPolicy(StabilityPolicy.WARN);
        int id = m.core.dir.massId("describe", "o");
        double k = m.core.engine.oscStiffness(id);
        // one mass: lambda = (K + 2Z) / M, so lambda reaches 4 at K = 4M - 2Z exactly
        String expected = String.format(Locale.ROOT, "%.4g", 4 * mass - 2 * z);
        long changes = watchWhile(() -> m.core.engine.oscStiffness(id), k, () -> {
            for (int i = 0; i < 10 * DESCRIPTIONS; i++) { // one mass: each analysis is quick
                String d = m.describeStability();
                assertTrue(d.contains("is above its limit of about " + expected), d);
            }
        });
        assertEquals(0, changes, "another thread saw the oscillator's stiffness change while the stability was described");
    }

    @Test
    @Timeout(60)
    void theWarnHelperThreadNeverWritesTheCulpritsStiffness() throws Exception {
        PrintStream err = System.err;
        System.setErr(new PrintStream(new ByteArrayOutputStream()));
        try {
            PhysicalModel m = unstableChain();
            int id = m.core.dir.linkId("describe", culprit(m));
            double k = m.core.engine.linkStiffness(id);
            m.beginRealtimeStepping();
            AtomicBoolean stop = new AtomicBoolean();
            Thread audio = new Thread(() -> {
                while (!stop.get()) {
                    m.computeNSteps(16);
                    LockSupport.parkNanos(200_000);
                }
            }, "audio");
            audio.start();
            try {
                // each setter under WARN makes the helper thread analyse (and describe) the unstable model
                long changes = watchWhile(() -> m.core.engine.linkStiffness(id), k, () -> {
                    for (int i = 0; i < 40; i++) {
                        m.setLinkDamping("s5", 0.001 * (i % 2));
                        LockSupport.parkNanos(2_000_000);
                    }
                });
                assertEquals(0, changes, "the stability helper thread changed the culprit's stiffness");
            } finally {
                stop.set(true);
                audio.join();
                m.endRealtimeStepping();
            }
        } finally {
            System.setErr(err);
        }
    }

    @Test
    @Timeout(60)
    void aRampRunByTheOwnerEndsAtItsTargetWhileAnotherThreadDescribesTheStability() throws Exception {
        PrintStream err = System.err;
        System.setErr(new PrintStream(new ByteArrayOutputStream()));
        try {
            for (int run = 0; run < 6; run++) {
                PhysicalModel m = unstableChain();
                m.createLinkSubset("springs");
                for (int i = 1; i <= 101; i++) {
                    m.addLinkToSubset("s" + i, "springs");
                }
                m.addParamController("k", "springs", "stiffness", 0.02f);
                m.getParamController("k").init(1.2f);
                m.beginRealtimeStepping();
                AtomicBoolean stop = new AtomicBoolean();
                Thread audio = new Thread(() -> {
                    while (!stop.get()) {
                        m.computeNSteps(64);
                        LockSupport.parkNanos(300_000);
                    }
                }, "audio");
                AtomicBoolean stopDraw = new AtomicBoolean();
                Thread draw = new Thread(() -> {
                    while (!stopDraw.get()) {
                        m.describeStability();
                    }
                }, "draw");
                audio.start();
                draw.start();
                m.getParamController("k").triggerRamp(1.3f);
                while (m.getParamController("k").isRamping()) {
                    Thread.sleep(5);
                }
                Thread.sleep(20);
                stopDraw.set(true);
                draw.join();
                stop.set(true);
                audio.join();
                m.endRealtimeStepping();
                for (int i = 1; i <= 101; i++) {
                    assertEquals((double) 1.3f, m.getLinkStiffness("s" + i), "run " + run + ": spring s" + i
                            + " missed the ramp's final value");
                }
            }
        } finally {
            System.setErr(err);
        }
    }

    /** @return the name of the spring the stability message names. */
    private static String culprit(PhysicalModel m) {
        java.util.regex.Matcher c = java.util.regex.Pattern.compile("SpringDamper3D \"(s\\d+)\"")
                .matcher(m.describeStability());
        assertTrue(c.find(), m.describeStability());
        return c.group(1);
    }

    /**
     * Runs {@code body} on this thread while a watcher thread reads {@code value} in a loop.
     *
     * @return how many times the watcher read something other than {@code expected}
     */
    private static long watchWhile(DoubleSupplier value, double expected, Runnable body) throws Exception {
        AtomicBoolean done = new AtomicBoolean();
        AtomicLong changes = new AtomicLong();
        AtomicLong reads = new AtomicLong();
        Thread watcher = new Thread(() -> {
            while (!done.get()) {
                if (Double.doubleToRawLongBits(value.getAsDouble()) != Double.doubleToRawLongBits(expected)) {
                    changes.incrementAndGet();
                }
                reads.incrementAndGet();
            }
        }, "watcher");
        watcher.start();
        while (reads.get() == 0) {
            Thread.onSpinWait(); // the watcher reads from before the first call on
        }
        try {
            body.run();
        } finally {
            done.set(true);
            watcher.join();
        }
        assertFalse(reads.get() == 0, "the watcher never read");
        return changes.get();
    }

    /** A chain of 100 masses at rest between two fixed points, with springs too stiff for the rate (WARN). */
    private static PhysicalModel unstableChain() {
        PhysicalModel m = new PhysicalModel(44100, 60);
        m.setDivergenceListener(e -> { });
        PrintStream err = System.err;
        System.setErr(new PrintStream(new ByteArrayOutputStream()));
        try {
            m.addGround3D("g0", new Vect3D(0, 0, 0));
            String prev = "g0";
            for (int i = 1; i <= 101; i++) {
                String mass = i <= 100 ? "m" + i : "g1";
                if (i <= 100) {
                    m.addMass3D(mass, 1, new Vect3D(i, 0, 0), new Vect3D());
                } else {
                    m.addGround3D(mass, new Vect3D(i, 0, 0));
                }
                m.addSpringDamper3D("s" + i, 1, 1.2, 0, prev, mass); // at rest: no force, no motion
                prev = mass;
            }
            m.init(); // WARN: unstable, a warning, kept
        } finally {
            System.setErr(err);
        }
        assertTrue(m.describeStability().contains("unstable"), m.describeStability());
        return m;
    }
}
