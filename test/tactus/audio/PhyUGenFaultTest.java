package tactus.audio;

import static org.junit.jupiter.api.Assertions.assertDoesNotThrow;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.locks.Lock;
import java.util.concurrent.locks.ReentrantLock;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;
import tactus.DivergenceException;
import tactus.PhysicalModel;
import tactus.Vect3D;

/**
 * Nothing escapes PhyUGen.uGenerate, called directly the way Minim calls it (UGen.tick): what cannot be stepped or
 * read is written as 0, the rest keeps sounding, each fault is said once on standard error by the notice thread
 * (never by the audio thread, never per sample), and the PhyUGen sounds again once the model is fixed.
 */
@Timeout(value = 30, unit = TimeUnit.SECONDS)
class PhyUGenFaultTest {
    private StderrCapture err;

    @BeforeEach
    void capture() throws InterruptedException {
        FaultReporter.awaitPrinted(5000); // what earlier tests posted is not counted here
        err = StderrCapture.start();
    }

    @AfterEach
    void release() {
        err.stop();
    }

    /**
     * A stereo PhyUGen computing blocks of the given length: 1, the per-sample path, where a change shows at the next
     * sample; the default, where it shows within one block (the tests tick a whole block where they wait for it).
     */
    private static PhyUGen stereo(PhysicalModel m, int block) {
        PhyUGen u = new PhyUGen(m);
        u.setSampleRate(44100);
        u.setChannelCount(2);
        u.setBlockSize(block);
        return u;
    }

    /** Ticks n samples; returns the largest |sample| of channel c (c = -1: either channel). */
    private static float tick(PhyUGen u, int n, int c) {
        float[] f = new float[2];
        float peak = 0;
        for (int i = 0; i < n; i++) {
            u.tick(f);
            for (int k = 0; k < 2; k++) {
                if (c < 0 || c == k) {
                    peak = Float.isNaN(f[k]) ? Float.POSITIVE_INFINITY : Math.max(peak, Math.abs(f[k]));
                }
            }
        }
        return peak;
    }

    /** A stereo PhyUGen at 44.1 kHz with blocks of this length, listening to the flaky model's mass x. */
    private static PhyUGen listeningToX(FlakyModel model, int block) {
        PhyUGen u = new PhyUGen(model);
        u.setSampleRate(44100);
        u.setChannelCount(2);
        u.setBlockSize(block);
        u.listenToMass("x", SteppedModel.X, 1, 0);
        return u;
    }

    /** The least whole number of blocks of the given length that is at least n samples, in samples. */
    private static int wholeBlocks(int n, int block) {
        return (n + block - 1) / block * block;
    }

    /** @return what the notice thread printed so far (waits until every notice posted is printed). */
    private String said() throws InterruptedException {
        assertTrue(FaultReporter.awaitPrinted(5000), "the notice thread prints");
        return err.text();
    }

    private void assertPrintedOnlyByTheNoticeThread() {
        assertFalse(err.writers().contains(Thread.currentThread().getName()),
                "the audio thread printed: " + err.writers());
    }

    private static void repair(PhysicalModel m) {
        m.setLinkStiffness("s3", 0.01);
        for (int i = 1; i <= 10; i++) {
            m.setMatPosition("m" + i, new Vect3D(i, i == 3 ? 0.05 : 0, 0));
        }
        m.clearDivergence();
    }

    @ParameterizedTest
    @CsvSource({"1, 1", "3, 1", "1, 64", "3, 64"})
    void aDivergedModelUnderWarnIsWrittenAsZeroAndSoundsAgainOnceCleared(int oversampling, int block) throws Exception {
        PhysicalModel m = PhyUGenMinimMistakesTest.chain(new PhysicalModel(44100, 60));
        m.init();
        PhyUGen u = stereo(m, block);
        u.setOversampling(oversampling);
        u.listenToMass("m3", SteppedModel.Y, 10, -0.5);
        u.listenToMass("m5", SteppedModel.Y, 10, 0.5);
        assertTrue(tick(u, 2000, -1) > 1e-3, "it sounds");
        m.setLinkStiffness("s3", 5.0); // the default WARN policy keeps it: the model blows up
        int ticks = 0;
        while (!u.isSilenced() && ticks < 10_000) {
            assertDoesNotThrow(() -> tick(u, 1, -1));
            ticks++;
        }
        assertTrue(u.isSilenced(), "silenced after the divergence (" + ticks + " samples)");
        assertInstanceOf(DivergenceException.class, u.getLastError());
        tick(u, block - 1, -1);   // what the block computed before the divergence
        assertEquals(0f, tick(u, 20 * PhyUGen.RECHECK_SAMPLES, -1), "a diverged model is written as 0");
        String said = said();
        assertEquals(1, PhyUGenMinimMistakesTest.count(said, "Tactus audio: PhyUGen is silent"), said);
        assertTrue(said.contains("clearDivergence()"), said);
        repair(m);
        assertTrue(tick(u, 4000, -1) > 1e-3, "it sounds again once the divergence is cleared");
        assertFalse(u.isSilenced());
        assertEquals(1, PhyUGenMinimMistakesTest.count(said(), "sounds again"), said());
        assertPrintedOnlyByTheNoticeThread();
    }

    @ParameterizedTest
    @ValueSource(ints = {1, PhyUGen.DEFAULT_BLOCK_SIZE})
    void aThrowingListenerSilencesTheModelOnceAndItRecovers(int block) throws Exception {
        PhysicalModel m = PhyUGenMinimMistakesTest.chain(new PhysicalModel(44100, 60));
        AtomicInteger told = new AtomicInteger();
        m.setDivergenceListener(e -> {
            told.incrementAndGet();
            throw new IllegalStateException("bug in my listener");
        });
        m.init();
        PhyUGen u = stereo(m, block);
        u.listenToMass("m3", SteppedModel.Y, 10, 0);
        tick(u, 1000, -1);
        m.setLinkStiffness("s3", 5.0);
        assertDoesNotThrow(() -> tick(u, 2000, -1));
        assertTrue(u.isSilenced());
        assertEquals("bug in my listener", u.getLastError().getMessage());
        assertEquals(0f, tick(u, 10 * PhyUGen.RECHECK_SAMPLES, -1));
        assertEquals(1, told.get(), "the listener is told once");
        String said = said();
        assertEquals(1, PhyUGenMinimMistakesTest.count(said, "DivergenceListener threw"), said);
        repair(m);
        assertTrue(tick(u, 4000, -1) > 1e-3, "it sounds again");
        assertPrintedOnlyByTheNoticeThread();
    }

    @ParameterizedTest
    @ValueSource(ints = {1, PhyUGen.DEFAULT_BLOCK_SIZE})
    void aDivergenceAListenerWasToldOfIsSilencedWithinSixteenSamples(int block) throws Exception {
        PhysicalModel m = PhyUGenMinimMistakesTest.chain(new PhysicalModel(44100, 60));
        AtomicInteger told = new AtomicInteger();
        m.setDivergenceListener(e -> told.incrementAndGet());
        m.init();
        PhyUGen u = stereo(m, block);
        u.listenToMass("m3", SteppedModel.Y, 10, 0);
        tick(u, 1000, -1);
        m.setLinkStiffness("s3", 5.0);
        int ticks = 0;
        while (told.get() == 0 && ticks < 10_000) {
            tick(u, 1, -1);
            ticks++;
        }
        assertEquals(1, told.get());
        tick(u, 16, -1);
        assertTrue(u.isSilenced());
        tick(u, block, -1);   // what the block computed before the divergence
        // the DC blocker would ring on for hundreds of samples from the huge frozen positions: it is emptied
        assertEquals(0f, tick(u, 5000, -1), "a frozen model is written as 0");
        assertTrue(said().contains("its DivergenceListener was told"), said());
        m.clearDivergence(); // the unstable spring is still there: it diverges again, and is said again
        tick(u, 5000, -1);
        assertEquals(2, told.get());
        repair(m);
        assertTrue(tick(u, 4000, -1) > 1e-3, "it sounds again");
    }

    @ParameterizedTest
    @ValueSource(ints = {1, PhyUGen.DEFAULT_BLOCK_SIZE})
    void aPointWhoseMassIsRemovedOutputsZeroTheOthersKeepSoundingAndItComesBack(int block) throws Exception {
        PhysicalModel m = PhyUGenMinimMistakesTest.chain(new PhysicalModel(44100, 60));
        m.init();
        PhyUGen u = stereo(m, block);
        u.setDcBlockerEnabled(false);
        ListeningPoint p3 = u.listenToMass("m3", SteppedModel.Y, 10, -1); // left only
        ListeningPoint p5 = u.listenToMass("m5", SteppedModel.Y, 10, 1);  // right only
        tick(u, 2000, -1);
        m.removeMatAndConnectedLinks("m3");
        assertDoesNotThrow(() -> tick(u, block, -1));   // the next block boundary
        assertTrue(p3.isSilent() && !p5.isSilent());
        assertFalse(u.isSilenced(), "the model still steps");
        assertTrue(tick(u, 10 * PhyUGen.RECHECK_SAMPLES, 0) < 1e-12f, "the left point (m3) outputs 0");
        assertTrue(tick(u, 2000, 1) > 1e-3, "the right point (m5) keeps sounding");
        String said = said();
        assertEquals(1, PhyUGenMinimMistakesTest.count(said, "listening point"), said);
        assertTrue(said.contains("named \"m3\""), said);
        m.addMass3D("m3", 1, new Vect3D(3, 0.05, 0), new Vect3D());
        m.addSpringDamper3D("s3", 1, 0.01, 0.00001, "m2", "m3");
        m.addSpringDamper3D("s4", 1, 0.01, 0.00001, "m3", "m4");
        tick(u, PhyUGen.RECHECK_SAMPLES + block, -1);
        assertFalse(p3.isSilent(), "back once a mass of that name is in the model again");
        assertTrue(tick(u, 2000, 0) > 1e-3, "the left point sounds again");
        assertTrue(said().contains("sounds again"), said());
        assertPrintedOnlyByTheNoticeThread();
    }

    @ParameterizedTest
    @ValueSource(ints = {1, PhyUGen.DEFAULT_BLOCK_SIZE})
    void pointsOnARemovedInteractionOutputZeroAndComeBack(int block) throws Exception {
        PhysicalModel m = PhyUGenMinimMistakesTest.chain(new PhysicalModel(44100, 60));
        m.init();
        PhyUGen u = stereo(m, block);
        u.setMono(true);
        u.setDcBlockerEnabled(false);
        ListeningPoint e = u.listenToElongation("s4", 100, 0);
        ListeningPoint t = u.listenToTension("s4", 100, 0);
        tick(u, 2000, -1);
        m.removeLink("s4");
        assertDoesNotThrow(() -> tick(u, Math.max(10, block), -1));
        assertTrue(e.isSilent() && t.isSilent());
        assertEquals(0f, tick(u, 3 * PhyUGen.RECHECK_SAMPLES, -1));
        m.addSpringDamper3D("s4", 1, 0.01, 0.00001, "m3", "m4");
        tick(u, PhyUGen.RECHECK_SAMPLES + block, -1);
        assertFalse(e.isSilent() || t.isSilent());
        assertTrue(tick(u, 2000, -1) > 1e-4, "both sound again");
        assertEquals(2, PhyUGenMinimMistakesTest.count(said(), "outputs 0"), said());
    }

    @ParameterizedTest
    @ValueSource(ints = {1, PhyUGen.DEFAULT_BLOCK_SIZE})
    void aClearedModelIsSilentAndARebuiltOneSoundsAgain(int block) throws Exception {
        PhysicalModel m = PhyUGenMinimMistakesTest.chain(new PhysicalModel(44100, 60));
        m.init();
        PhyUGen u = stereo(m, block);
        u.setDcBlockerEnabled(false);
        ListeningPoint p3 = u.listenToMass("m3", SteppedModel.Y, 10, 0);
        tick(u, 2000, -1);
        m.clearModel();
        assertDoesNotThrow(() -> tick(u, block, -1));
        assertTrue(p3.isSilent());
        assertEquals(0f, tick(u, 3 * PhyUGen.RECHECK_SAMPLES, -1), "nothing to hear");
        PhyUGenMinimMistakesTest.chain(m).init();
        tick(u, PhyUGen.RECHECK_SAMPLES + block, -1);
        assertFalse(p3.isSilent());
        assertTrue(tick(u, 2000, -1) > 1e-3);
    }

    @ParameterizedTest
    @ValueSource(ints = {1, PhyUGen.DEFAULT_BLOCK_SIZE})
    void aRemovedAvatarGetsZeroForceTheModelSoundsOnAndTheAvatarComesBack(int block) throws Exception {
        PhysicalModel m = PhyUGenMinimMistakesTest.chain(new PhysicalModel(44100, 60));
        m.addHapticInput3D("av", new Vect3D(3, 1, 0), 30);
        m.addContact3D("c", 0.5, 0.01, 0, "av", "m3");
        m.init();
        PhyUGen u = stereo(m, block);
        u.listenToMass("m5", SteppedModel.Y, 10, 0);
        AvatarExchange ex = new AvatarExchange(AvatarExchange.ForceMode.SUM);
        u.attachAvatar("av", ex);
        ex.publishPosition(3, 0.3, 0);
        double[] f = new double[3];
        tick(u, 3000, -1);
        ex.takeForce(f);
        assertTrue(f[1] != 0, "the avatar feels the string");
        m.removeMatAndConnectedLinks("av");
        assertDoesNotThrow(() -> tick(u, block, -1));
        assertTrue(u.isAvatarLost());
        ex.takeForce(f);
        int whole = wholeBlocks(100, block);
        tick(u, whole, -1);
        assertEquals(whole, ex.takeForce(f), "the exchange still counts the steps");
        assertEquals(0.0, f[0] * f[0] + f[1] * f[1] + f[2] * f[2], "no force from an avatar that is gone");
        assertTrue(tick(u, 2000, -1) > 1e-3, "the model sounds on");
        assertEquals(1, PhyUGenMinimMistakesTest.count(said(), "avatar \"av\""), said());
        m.addHapticInput3D("av", new Vect3D(3, 1, 0), 30);
        m.addContact3D("c", 0.5, 0.01, 0, "av", "m3");
        tick(u, PhyUGen.RECHECK_SAMPLES + 3000, -1);
        assertFalse(u.isAvatarLost());
        boolean felt = false;
        for (int i = 0; i < 100 && !felt; i++) { // m3 swings in and out of the contact's reach
            tick(u, wholeBlocks(200, block), -1);
            felt = ex.takeForce(f) == wholeBlocks(200, block) && f[1] != 0;
        }
        assertTrue(felt, "the avatar is driven again and feels the string");
    }

    /** A paper-style subclass: its own uGenerate steps with stepModel() and mixes with mix(). */
    static final class OwnLoop extends PhyUGen {
        OwnLoop() {
            super(44100);
            PhyUGenMinimMistakesTest.chain(mdl);
            mdl.init();
            listenToMass("m3", SteppedModel.Y, 10, 0);
        }

        @Override
        protected void uGenerate(float[] channels) {
            stepModel();
            float v = (float) mix();
            for (int c = 0; c < channels.length; c++) {
                channels[c] = v;
            }
        }
    }

    @Test
    void stepModelAndMixNeverThrowInASubclassLoop() throws Exception {
        OwnLoop u = new OwnLoop();
        u.setSampleRate(44100);
        u.setChannelCount(2);
        assertTrue(tick(u, 2000, -1) > 1e-3);
        u.getModel().setLinkStiffness("s3", 5.0);
        assertDoesNotThrow(() -> tick(u, 3000, -1));
        assertTrue(u.isSilenced());
        assertEquals(0f, tick(u, 3000, -1), "mix() gives 0 while the model is frozen");
        repair(u.getModel());
        assertTrue(tick(u, 3000, -1) > 1e-3);
        u.getModel().removeMatAndConnectedLinks("m3");
        assertDoesNotThrow(() -> tick(u, 3000, -1));
        assertEquals(0f, tick(u, 3000, -1), "the only point is gone: mix() gives 0");
    }

    /** A model whose step throws while {@link #fail} is set; counts the calls. */
    static final class FlakyModel implements SteppedModel {
        volatile boolean fail;
        int calls;
        int steps;
        boolean badLock;
        private final Lock lock = new ReentrantLock();

        @Override
        public int stepRate() {
            return 44100;
        }

        @Override
        public void setStepRate(int stepsPerSecond) {
        }

        @Override
        public void step() {
            calls++;
            if (fail) {
                throw new IllegalStateException("flaky step");
            }
            steps++;
        }

        @Override
        public Lock sampleLock() {
            if (badLock) {
                throw new UnsupportedOperationException("no lock today");
            }
            return lock;
        }

        @Override
        public int resolveMass(String name) {
            return 0;
        }

        @Override
        public int resolveLink(String name, boolean withForce) {
            return 0;
        }

        @Override
        public int resolveAvatar(String name) {
            return 0;
        }

        @Override
        public double massPosition(int mass, int axis) {
            return Math.sin(steps * 0.05);
        }

        @Override
        public double linkElongation(int link) {
            return 0;
        }

        @Override
        public double linkTension(int link) {
            return 0;
        }

        @Override
        public void setAvatarTarget(int avatar, double x, double y, double z) {
        }

        @Override
        public void takeAvatarForce(int avatar, double[] out) {
        }
    }

    @ParameterizedTest
    @ValueSource(ints = {1, PhyUGen.DEFAULT_BLOCK_SIZE})
    void aStepThatThrowsIsRetriedAboutTwentyTimesASecondNotEverySample(int block) throws Exception {
        FlakyModel model = new FlakyModel();
        PhyUGen u = listeningToX(model, block);
        assertTrue(tick(u, wholeBlocks(1000, block), -1) > 0.01);   // the next sample begins a block
        model.fail = true;
        int before = model.calls;
        int samples = 20 * PhyUGen.RECHECK_SAMPLES;
        assertEquals(0f, tick(u, samples, -1), "silent while the steps throw");
        assertTrue(u.isSilenced());
        int tries = model.calls - before;
        // in a block, the first try that throws is made twice: in one call, then sample by sample (which finds
        // whether a point's mass left or the step threw)
        int most = block > 1 ? 22 : 21;
        assertTrue(tries >= 19 && tries <= most, "one try per " + PhyUGen.RECHECK_SAMPLES + " samples: " + tries);
        assertEquals(1, PhyUGenMinimMistakesTest.count(said(), "is silent: stepping the model threw java.lang.IllegalStateException: flaky step"),
                "said once, with its cause: " + said());
        model.fail = false;
        assertTrue(tick(u, PhyUGen.RECHECK_SAMPLES + 500, -1) > 0.01, "it sounds again once a step succeeds");
        assertFalse(u.isSilenced());
        assertTrue(said().contains("sounds again"));
        assertPrintedOnlyByTheNoticeThread();
    }

    /**
     * The retries of a failing step come every {@link PhyUGen#RECHECK_SAMPLES} samples counted from the first one,
     * whatever the block: a one-call block that fell back to one sample per pass (to find out what failed) counts
     * its samples once, not twice.
     */
    @ParameterizedTest
    @ValueSource(ints = {1, 16, PhyUGen.DEFAULT_BLOCK_SIZE, 256})
    void retriesComeEveryRecheckIntervalCountedFromTheFirstSample(int block) throws Exception {
        FlakyModel model = new FlakyModel();
        PhyUGen u = listeningToX(model, block);
        int start = 1024;   // whole blocks of every size tried
        tick(u, start, -1);
        model.fail = true;
        java.util.List<Integer> at = new java.util.ArrayList<>();
        int last = model.calls;
        int end = start + 5 * PhyUGen.RECHECK_SAMPLES;
        for (int s = start; s < end; s++) {
            tick(u, 1, -1);   // a block is computed at the tick of its first sample
            if (model.calls != last) {
                at.add(s);
                last = model.calls;
            }
        }
        assertEquals(start, at.get(0), "the first step after the failure begins throws at once: " + at);
        for (int k = 1; k < at.size(); k++) {
            int first = at.get(k);
            // the block computed at this tick holds sample first .. first + block - 1 (0-based); one of them must be
            // a sample whose 1-based number is a multiple of the interval
            assertTrue((first + block) / PhyUGen.RECHECK_SAMPLES > first / PhyUGen.RECHECK_SAMPLES,
                    "retry " + k + " in the block from sample " + first + " (block " + block + "): " + at);
        }
        assertEquals(6, at.size(), "the failure, then one retry per " + PhyUGen.RECHECK_SAMPLES + " samples: " + at);
    }

    @ParameterizedTest
    @ValueSource(ints = {1, PhyUGen.DEFAULT_BLOCK_SIZE})
    void aFailureOfThePhyUGenItselfIsWrittenAsZeroAndSaidOnce(int block) throws Exception {
        FlakyModel model = new FlakyModel();
        PhyUGen u = listeningToX(model, block);
        tick(u, wholeBlocks(100, block), -1);
        model.badLock = true;
        assertEquals(0f, assertDoesNotThrow(() -> tick(u, 5000, -1)));
        assertEquals(5000, u.getFaultCount());
        assertEquals(1, PhyUGenMinimMistakesTest.count(said(), "PhyUGen failed: java.lang.UnsupportedOperationException: no lock today"),
                said());
        model.badLock = false;
        assertTrue(tick(u, 100, -1) > 0.01);
    }
}
