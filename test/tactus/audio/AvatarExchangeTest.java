package tactus.audio;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLongArray;
import java.util.concurrent.atomic.AtomicReference;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;
import tactus.PhysicalModel;
import tactus.Vect3D;

/** The multirate hand-off: impulse bookkeeping, force modes, latency of a position step, no torn reads. */
class AvatarExchangeTest {

    /**
     * Whatever the two rates and however irregular the takes, average x steps spanned adds up to the sum of
     * the per-step forces: the impulse the haptic side accounts for is the one the model produced.
     */
    @ParameterizedTest
    @CsvSource({"44100, 1000", "48000, 1000", "96000, 250", "22050, 3000"})
    void impulseIsConservedAcrossTheRates(int audioRate, int hapticRate) {
        Random rnd = new Random(audioRate + hapticRate);
        AvatarExchange ex = new AvatarExchange();
        double[] out = new double[3];
        double produced = 0;
        double accounted = 0;
        double producedY = 0;
        double accountedY = 0;
        double audioTime = 0;
        double nextTake = 0;
        for (int n = 0; n < 2_000_000; n++) {
            double fx = Math.sin(n * 0.001) * 3 + rnd.nextGaussian();
            double fy = 1e-3 * rnd.nextGaussian() + 5;
            ex.addForce(fx, fy, 0);
            produced += fx / audioRate;
            producedY += fy / audioRate;
            audioTime += 1.0 / audioRate;
            if (audioTime >= nextTake) {
                long steps = ex.takeForce(out);
                accounted += out[0] * steps / audioRate;
                accountedY += out[1] * steps / audioRate;
                // jittery haptic period, and sometimes a burst: the audio runs a whole buffer between two takes
                nextTake += (1.0 + 0.5 * rnd.nextGaussian()) / hapticRate + (rnd.nextInt(20) == 0 ? 0.023 : 0);
            }
        }
        long steps = ex.takeForce(out);
        accounted += out[0] * steps / audioRate;
        accountedY += out[1] * steps / audioRate;
        assertEquals(produced, accounted, 1e-9 * (1 + Math.abs(produced)));
        assertEquals(producedY, accountedY, 1e-9 * producedY);
        assertEquals(5, out[1], 0.01, "the average is the force itself, independent of both rates");
    }

    @Test
    void averageHoldsAndSumEmptiesWhenNoStepRan() {
        AvatarExchange avg = new AvatarExchange();
        AvatarExchange sum = new AvatarExchange(AvatarExchange.ForceMode.SUM);
        double[] out = new double[3];
        for (int i = 0; i < 10; i++) {
            avg.addForce(2, -4, 6);
            sum.addForce(2, -4, 6);
        }
        assertEquals(10, avg.takeForce(out));
        assertEquals(2, out[0], 0);
        assertEquals(-4, out[1], 0);
        assertEquals(0, avg.takeForce(out), "no step since");
        assertEquals(6, out[2], 0, "AVERAGE repeats the last average");
        assertEquals(10, sum.takeForce(out));
        assertEquals(20, out[0], 0);
        assertEquals(-40, out[1], 0);
        assertEquals(0, sum.takeForce(out));
        assertEquals(0, out[0], 0, "SUM of no step is zero");
        assertFalse(new AvatarExchange().readPosition(out), "nothing published yet");
    }

    /**
     * A step in the device position reaches the audio at the first model step after it is published, then
     * the avatar follows its EWMA exactly: after j steps it has covered 1 - (1 - w)^j of the step (w = 1/s).
     */
    @ParameterizedTest(name = "block of {0}")
    @ValueSource(ints = {1, PhyUGen.DEFAULT_BLOCK_SIZE})
    void aPositionStepReachesTheAudioAtTheNextStepThroughTheEwma(int block) {
        int smoothing = 30;
        PhysicalModel pm = new PhysicalModel(44100);
        pm.addHapticInput3D("avatar", new Vect3D(0, 0, 0), smoothing);
        pm.init();
        PhyUGen u = new PhyUGen(pm);
        u.setBlockSize(block);
        u.setDcBlockerEnabled(false);
        u.listenToMass("avatar", SteppedModel.X, 1, 0);
        AvatarExchange ex = new AvatarExchange();
        u.attachAvatar("avatar", ex);
        u.setSampleRate(44100);
        float[] frame = new float[1];
        int before = 100;
        for (int i = 0; i < before; i++) {
            u.tick(frame);
            assertEquals(0, frame[0], 0f);
        }
        ex.publishPosition(1, 0, 0);
        // the samples of the block in progress were computed before the publish: the step is seen at the next block
        int boundary = (before + block - 1) / block * block;
        for (int i = before; i < boundary; i++) {
            u.tick(frame);
            assertEquals(0, frame[0], 0f, "sample " + i + ", computed before the publish");
        }
        double w = 1.0 / smoothing;
        for (int j = 1; j <= 200; j++) {
            u.tick(frame);
            assertEquals(1 - Math.pow(1 - w, j), frame[0], 1e-6, "sample " + j + " after the step");
        }
    }

    /**
     * The same with real threads: the haptic thread publishes steps at random moments while the audio
     * thread runs; the audio step that first sees a new position lies between the audio step counts read
     * just before and just after the publish, plus one (the step in progress). No wall-clock assertions. The audio loop fences after each step so its
     * step counter is never seen late (that would be a measurement artefact, not latency).
     *
     * <p>"Not seen yet" is -1, not 0: on a loaded machine the audio thread may not have run a single step
     * before round 1 is published, and then sees it at step 0 (with 0 as the mark, the main thread waited for
     * ever; the 50 ms case makes that happen on every run). Every wait is bounded: a round not seen within
     * {@link #ROUND_WAIT_NANOS} fails the test by name.
     */
    @ParameterizedTest(name = "audio thread starts {0} ms late")
    @ValueSource(ints = {0, 50})
    @Timeout(60)
    void withRealThreadsTheNewPositionIsSeenWithinOneStep(int audioStartDelayMs) throws Exception {
        AvatarExchange ex = new AvatarExchange();
        int rounds = 300;
        AtomicLongArray seenAt = new AtomicLongArray(rounds + 1);
        for (int r = 0; r <= rounds; r++) {
            seenAt.set(r, NOT_SEEN);
        }
        long[] before = new long[rounds + 1];
        long[] after = new long[rounds + 1];
        AtomicReference<Throwable> failure = new AtomicReference<>();
        AtomicBoolean stop = new AtomicBoolean();
        Thread audio = new Thread(() -> {
            try {
                // a late start is what a loaded machine does: round 1 is then published before step 0 and seen there
                Thread.sleep(audioStartDelayMs);
                double[] p = new double[3];
                long step = 0;
                int expected = 1;
                while (expected <= rounds && !stop.get()) {
                    // one "model step": read the target, then report the force of this step
                    if (ex.readPosition(p) && (int) p[0] == expected) {
                        seenAt.set(expected, step);
                        expected++;
                    }
                    ex.addForce(0, 0, 0);
                    // the step counter must be visible before the next read of the position, or the haptic
                    // thread's "after" count could lag the audio thread's real progress by its store buffer
                    java.lang.invoke.VarHandle.fullFence();
                    step++;
                }
            } catch (Throwable t) {
                failure.set(t);
            }
        }, "audio");
        audio.setDaemon(true);
        audio.start();
        try {
            Random rnd = new Random(7);
            for (int r = 1; r <= rounds; r++) {
                Thread.sleep(0, rnd.nextInt(500_000));
                before[r] = ex.audioSteps();
                ex.publishPosition(r, 0, 0);
                after[r] = ex.audioSteps();
                long deadline = System.nanoTime() + ROUND_WAIT_NANOS;
                while (seenAt.get(r) == NOT_SEEN && audio.isAlive() && System.nanoTime() < deadline) {
                    Thread.onSpinWait();
                }
                assertNotEquals(NOT_SEEN, seenAt.get(r), "round " + r + " was never seen by the audio thread"
                        + (audio.isAlive() ? " within " + ROUND_WAIT_NANOS / 1_000_000_000L + " s" : " (it died)"));
            }
        } finally {
            stop.set(true);
            audio.join(10_000);
        }
        assertNull(failure.get(), "the audio thread threw");
        assertFalse(audio.isAlive(), "the audio thread did not end");
        for (int r = 1; r <= rounds; r++) {
            long seen = seenAt.get(r);
            assertTrue(seen >= before[r] && seen <= after[r] + 1, "round " + r + ": published between steps "
                    + before[r] + " and " + after[r] + ", seen at step " + seen);
        }
    }

    /** Mark of a round the audio thread has not seen yet (0 is a real step number). */
    private static final long NOT_SEEN = -1;
    /** The longest the publisher waits for one round to be seen; far beyond any scheduling delay, ns. */
    private static final long ROUND_WAIT_NANOS = 20_000_000_000L;

    /**
     * Three threads for three seconds: a haptic writer publishes positions (k, 2k, -3k) and takes forces; the
     * audio thread reads positions and adds forces (1, a, 2a); a display thread peeks positions. Every read
     * must be one whole write: y = 2x and z = -3x, x never going back, and every take satisfying
     * sum_x = steps, sum_z = 2 sum_y (exact in double: the values are small integers).
     */
    @Test
    void threeThreadsNeverSeeTornValues() throws Exception {
        AvatarExchange ex = new AvatarExchange(AvatarExchange.ForceMode.SUM);
        long end = System.nanoTime() + 3_000_000_000L;
        AtomicReference<String> torn = new AtomicReference<>();
        long[] counts = new long[4];
        Thread audio = new Thread(() -> {
            double[] p = new double[3];
            double lastX = 0;
            long n = 0;
            while (System.nanoTime() < end && torn.get() == null) {
                for (int i = 0; i < 1000; i++, n++) {
                    if (ex.readPosition(p)) {
                        if (p[1] != 2 * p[0] || p[2] != -3 * p[0] || p[0] < lastX) {
                            torn.compareAndSet(null, "audio read " + p[0] + ", " + p[1] + ", " + p[2]);
                        }
                        lastX = p[0];
                    }
                    double a = n % 7;
                    ex.addForce(1, a, 2 * a);
                }
            }
            counts[0] = n;
        }, "audio");
        Thread display = new Thread(() -> {
            double[] p = new double[3];
            long reads = 0;
            while (System.nanoTime() < end && torn.get() == null) {
                if (ex.peekPosition(p) && (p[1] != 2 * p[0] || p[2] != -3 * p[0])) {
                    torn.compareAndSet(null, "display read " + p[0] + ", " + p[1] + ", " + p[2]);
                }
                reads++;
            }
            counts[1] = reads;
        }, "display");
        audio.start();
        display.start();
        double[] f = new double[3];
        long k = 0;
        long takes = 0;
        long stepsTaken = 0;
        while (System.nanoTime() < end && torn.get() == null) {
            k++;
            ex.publishPosition(k, 2 * k, -3 * k);
            long steps = ex.takeForce(f);
            stepsTaken += steps;
            if (f[0] != steps || f[2] != 2 * f[1]) {
                torn.compareAndSet(null, "haptic took " + f[0] + ", " + f[1] + ", " + f[2] + " over " + steps + " steps");
            }
            takes++;
        }
        audio.join();
        display.join();
        stepsTaken += ex.takeForce(f);
        assertEquals(null, torn.get());
        assertEquals(counts[0], stepsTaken, "every step's force was taken exactly once");
        assertTrue(k > 1000 && takes > 1000 && counts[0] > 100_000 && counts[1] > 1000,
                "enough overlap: " + k + " publishes, " + counts[0] + " audio steps, " + counts[1] + " display reads");
    }
}
