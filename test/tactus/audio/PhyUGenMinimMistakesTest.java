package tactus.audio;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ddf.minim.AudioListener;
import ddf.minim.AudioOutput;
import ddf.minim.Minim;
import ddf.minim.UGen;
import ddf.minim.ugens.Oscil;
import ddf.minim.ugens.Waves;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import tactus.PhysicalModel;
import tactus.Vect3D;

/**
 * Sketch mistakes while a PhyUGen plays through Minim's real audio thread (the project's virtual output on a machine
 * with no sound card, LineOut's silent output otherwise): a divergence under the default WARN policy with no listener,
 * removing a listened mass, clearModel(), removing the attached avatar, a DivergenceListener that throws. Minim's
 * output loop has no catch, so before the fix each of these killed the output thread and silenced every UGen on it.
 * For each: the output thread keeps delivering buffers, a sine patched next to the PhyUGen keeps sounding, the PhyUGen
 * says what happened (its state, and one line on standard error), and it sounds again once the model is fixed.
 */
class PhyUGenMinimMistakesTest {
    @TempDir
    Path dir;

    /**
     * Counts the buffers the output delivers and the loudest sample since the last reset (the audio thread clears
     * them when it sees a new epoch, so a reset is never lost to a concurrent update).
     */
    static final class OutputProbe implements AudioListener {
        private volatile int epoch;
        private volatile int seen;
        private volatile long buffers;
        private volatile float peak;

        /** @return false if the audio thread did not come by within 5 s (it is dead, or stuck). */
        boolean reset() throws InterruptedException {
            epoch++;
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(5);
            while (seen != epoch && System.nanoTime() < deadline) {
                Thread.sleep(1);
            }
            return seen == epoch;
        }

        private void take(float[] s) {
            if (seen != epoch) {
                buffers = 0;
                peak = 0;
                seen = epoch;
            }
            float p = peak;
            for (float v : s) {
                p = Float.isNaN(v) ? Float.POSITIVE_INFINITY : Math.max(p, Math.abs(v));
            }
            peak = p;
        }

        @Override
        public void samples(float[] s) {
            take(s);
            buffers++;
        }

        @Override
        public void samples(float[] l, float[] r) {
            take(l);
            take(r);
            buffers++;
        }
    }

    /** Passes its input through and keeps the loudest sample of each channel since the last reset (as the probe). */
    static final class Tap extends UGen {
        final UGenInput in = new UGenInput(InputType.AUDIO);
        private volatile int epoch;
        private volatile int seen;
        volatile float left;
        volatile float right;

        /** @return false if the audio thread did not come by within 5 s (it is dead, or stuck). */
        boolean reset() throws InterruptedException {
            epoch++;
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(5);
            while (seen != epoch && System.nanoTime() < deadline) {
                Thread.sleep(1);
            }
            return seen == epoch;
        }

        @Override
        protected void uGenerate(float[] channels) {
            if (seen != epoch) {
                left = 0;
                right = 0;
                seen = epoch;
            }
            float[] v = in.getLastValues();
            for (int c = 0; c < channels.length; c++) {
                channels[c] = v[Math.min(c, v.length - 1)];
            }
            left = Math.max(left, Math.abs(channels[0]));
            right = Math.max(right, Math.abs(channels[channels.length - 1]));
        }
    }

    /** A chain of ten masses between two grounds, m3 plucked in y. */
    static PhysicalModel chain(PhysicalModel m) {
        m.addGround3D("g0", new Vect3D(0, 0, 0));
        String prev = "g0";
        for (int i = 1; i <= 10; i++) {
            m.addMass3D("m" + i, 1, new Vect3D(i, i == 3 ? 0.05 : 0, 0), new Vect3D());
            m.addSpringDamper3D("s" + i, 1, 0.01, 0.00001, prev, "m" + i);
            prev = "m" + i;
        }
        m.addGround3D("g1", new Vect3D(11, 0, 0));
        m.addSpringDamper3D("s11", 1, 0.01, 0.00001, prev, "g1");
        return m;
    }

    private static void await(String what, BooleanSupplier condition) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
        while (!condition.getAsBoolean()) {
            assertTrue(System.nanoTime() < deadline, "timed out waiting for: " + what);
            Thread.sleep(10);
        }
    }

    /** Puts the chain back at rest with m3 plucked again, and clears the divergence. */
    private static void repairDivergence(PhysicalModel m) {
        m.setLinkStiffness("s3", 0.01);
        for (int i = 1; i <= 10; i++) {
            m.setMatPosition("m" + i, new Vect3D(i, i == 3 ? 0.05 : 0, 0));
        }
        m.clearDivergence();
    }

    @ParameterizedTest
    @ValueSource(strings = {"diverge", "removeListened", "clearModel", "removeAvatar", "listenerThrows"})
    @Timeout(value = 40, unit = TimeUnit.SECONDS)
    void theOutputThreadSurvivesAndThePhyUGenRecovers(String mistake) throws Exception {
        StderrCapture err = StderrCapture.start();
        Thread.UncaughtExceptionHandler before = Thread.getDefaultUncaughtExceptionHandler();
        Throwable[] uncaught = new Throwable[1];
        Thread.setDefaultUncaughtExceptionHandler((t, e) -> uncaught[0] = e);
        Minim minim = new Minim(new HeadlessLineOutTest.Files(dir.toFile()));
        try {
            AudioOutput out = LineOut.open(minim, Minim.STEREO, 512, 44100f);
            PhysicalModel m = chain(new PhysicalModel(44100, 60));
            AvatarExchange ex = null;
            if (mistake.equals("removeAvatar")) {
                m.addHapticInput3D("av", new Vect3D(3, 1, 0), 30);
                m.addContact3D("c", 0.5, 0.01, 0, "av", "m3");
            }
            if (mistake.equals("listenerThrows")) {
                m.setDivergenceListener(e -> {
                    throw new IllegalStateException("bug in my listener");
                });
            }
            m.init();
            PhyUGen ugen = new PhyUGen(m);
            ugen.setDcBlockerEnabled(false);
            ListeningPoint p3 = ugen.listenToMass("m3", SteppedModel.Y, 10, -1);   // left
            ListeningPoint p5 = ugen.listenToMass("m5", SteppedModel.Y, 10, 1);    // right
            if (mistake.equals("removeAvatar")) {
                ex = new AvatarExchange();
                ugen.attachAvatar("av", ex);
                ex.publishPosition(3, 0.3, 0);   // within the contact's reach of m3
            }
            Tap tap = new Tap();
            ugen.patch(tap).patch(out);
            new Oscil(440, 0.5f, Waves.SINE).patch(out);
            OutputProbe probe = new OutputProbe();
            out.addListener(probe);
            await("the model steps", () -> m.getStepCount() > 8192);
            if (ex != null) {
                double[] f = new double[3];
                AvatarExchange e = ex;
                await("the avatar feels the string", () -> e.takeForce(f) > 0 && f[1] != 0);
            }

            switch (mistake) {
                case "diverge":
                case "listenerThrows":
                    m.setLinkStiffness("s3", 5.0);   // WARN: a warning, and the change is kept
                    break;
                case "removeListened":
                    m.removeMatAndConnectedLinks("m3");
                    break;
                case "clearModel":
                    m.clearModel();
                    break;
                default:
                    m.removeMatAndConnectedLinks("av");
                    break;
            }
            Thread.sleep(200);
            assertTrue(probe.reset() && tap.reset(), "the output thread still runs the graph after the mistake");
            await("10 output buffers after the mistake (the output thread is alive)", () -> probe.buffers >= 10);
            assertTrue(probe.peak >= 0.45f && probe.peak < Float.POSITIVE_INFINITY,
                    "the sine next to the PhyUGen keeps sounding, and no NaN: peak " + probe.peak);
            assertEquals(null, uncaught[0], "an exception escaped a thread");
            FaultReporter.awaitPrinted(5000);
            String said = err.text();

            switch (mistake) {
                case "diverge":
                case "listenerThrows":
                    assertTrue(ugen.isSilenced(), "a diverged model is silent");
                    assertEquals(0f, tap.left + tap.right, "the PhyUGen writes 0 while the model is frozen");
                    assertNotNull(ugen.getLastError());
                    assertEquals(1, count(said, "is silent"), said);
                    assertTrue(said.contains(mistake.equals("diverge") ? "clearDivergence()" : "bug in my listener"),
                            said);
                    repairDivergence(m);
                    await("the PhyUGen sounds again", () -> !ugen.isSilenced());
                    break;
                case "removeListened":
                    assertTrue(p3.isSilent() && !p5.isSilent(), "only the removed mass's point is silent");
                    assertEquals(0f, tap.left, 1e-9f, "the point on the removed mass outputs 0 (m5 is panned right)");
                    assertTrue(tap.right > 1e-3, "the point on m5 keeps sounding: " + tap.right);
                    assertEquals(1, count(said, "listening point"), said);
                    m.addMass3D("m3", 1, new Vect3D(3, 0.05, 0), new Vect3D());
                    m.addSpringDamper3D("s3", 1, 0.01, 0.00001, "m2", "m3");
                    m.addSpringDamper3D("s4", 1, 0.01, 0.00001, "m3", "m4");
                    await("the point on m3 sounds again", () -> !p3.isSilent());
                    break;
                case "clearModel":
                    assertTrue(p3.isSilent() && p5.isSilent(), "no point can be read in a cleared model");
                    assertEquals(0f, tap.left + tap.right, "a cleared model is silent");
                    assertEquals(2, count(said, "listening point"), said);
                    chain(m).init();
                    await("both points sound again", () -> !p3.isSilent() && !p5.isSilent());
                    break;
                default:
                    assertTrue(ugen.isAvatarLost(), "the avatar is lost");
                    assertTrue(tap.left > 1e-3 && tap.right > 1e-3, "the model keeps sounding: " + tap.left);
                    double[] f = new double[3];
                    AvatarExchange e = ex;
                    await("the exchange reports steps with zero force", () -> e.takeForce(f) > 0 && f[0] == 0 && f[1] == 0);
                    assertEquals(1, count(said, "avatar \"av\""), said);
                    m.addHapticInput3D("av", new Vect3D(3, 1, 0), 30);
                    m.addContact3D("c", 0.5, 0.01, 0, "av", "m3");
                    await("the avatar is driven again", () -> !ugen.isAvatarLost());
                    await("the exchange feels the string again", () -> e.takeForce(f) > 0 && f[1] != 0);
                    break;
            }
            // it sounds again: the model steps and both points reach the output
            assertTrue(tap.reset(), "the output thread still runs the graph");
            long s0 = m.getStepCount();
            await("the PhyUGen is heard again", () -> tap.left > 1e-4 && tap.right > 1e-4);
            await("the model steps on", () -> m.getStepCount() > s0 + 4096);
            assertFalse(ugen.isSilenced());
            FaultReporter.awaitPrinted(5000);
            assertTrue(count(err.text(), "again") >= 1, "the recovery is said: " + err.text());
            assertEquals(null, uncaught[0], "an exception escaped a thread");
        } finally {
            minim.stop();
            Thread.setDefaultUncaughtExceptionHandler(before);
            err.stop();
        }
    }

    static int count(String text, String part) {
        int n = 0;
        for (int i = text.indexOf(part); i >= 0; i = text.indexOf(part, i + 1)) {
            n++;
        }
        return n;
    }
}
