package tactus.audio;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.sound.sampled.AudioFormat;
import javax.sound.sampled.AudioInputStream;
import javax.sound.sampled.AudioSystem;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import tactus.PhysicalModel;

/**
 * The plucked string of the paper, written the paper's way (a PhyUGen subclass that builds its model in
 * the constructor), rendered offline to a 16-bit WAV, read back with javax.sound, and measured by FFT:
 * its first four partials lie within 1 cent of the discrete-time theory of {@link StringModel}, in order.
 */
class PluckedStringPitchTest {
    static final int RATE = 44100;
    static final int FFT_SIZE = 1 << 17;

    /** The paper's way: subclass, super(44100), build mdl in the constructor, listen to a mass. */
    static final class PluckedString extends PhyUGen {
        PluckedString() {
            super(RATE);
            StringModel.build(mdl, 7, 0.001);
            mdl.init();
            listenToMass(StringModel.mass(3), SteppedModel.Y, 300, 0);
        }
    }

    /**
     * A sketch's own PhyUGen as the paper's sketches write it (own mdl field, own sampleRateChanged and
     * uGenerate with computeStep, a position read and the 0.95 high-pass), with only "extends UGen" turned
     * into "extends tactus.audio.PhyUGen": it runs unchanged on top of this class.
     */
    static final class PaperSketchUGen extends PhyUGen {
        PhysicalModel mdl;
        float prevSample;
        float audioOut;

        PaperSketchUGen(int sampleRate) {
            super(sampleRate);
            this.mdl = new PhysicalModel(sampleRate, 60);
            mdl.setGravity(0);
            mdl.setFriction(0);
            StringModel.build(mdl, 7, 0.001);
            this.mdl.init();
        }

        @Override
        protected void sampleRateChanged() {
            this.mdl.setSimRate((int) sampleRate());
        }

        @Override
        protected void uGenerate(float[] channels) {
            float sample;
            synchronized (mdl.getLock()) {
                this.mdl.computeStep();
                sample = (float) (300 * this.mdl.getMatPosition(StringModel.mass(3)).y);
                audioOut = sample - prevSample + 0.95f * audioOut;
                prevSample = sample;
            }
            java.util.Arrays.fill(channels, audioOut);
        }
    }

    @TempDir
    Path dir;

    @Test
    void aSketchWrittenThePapersWayRunsOnTopOfIt() throws Exception {
        assertPartials(new PaperSketchUGen(RATE), 1, 1, "paper-sketch");
    }

    @Test
    void partialsMatchDiscreteTheoryWithinOneCent() throws Exception {
        assertPartials(new PluckedString(), 1, 1, "paper-way");
    }

    @Test
    void oversampledStringMatchesTheoryAtTheModelRate() throws Exception {
        PluckedString ugen = new PluckedString();
        ugen.setOversampling(3);
        assertEquals(3 * RATE, ugen.steppedModel().stepRate());
        // ALGO_UNITS coefficients are per step, so three steps per sample raise every partial threefold
        assertPartials(ugen, 3, 2, "oversampled");
    }

    @Test
    void theDirectWayPlaysTheSameSamples() {
        PhysicalModel pm = new PhysicalModel(RATE);
        StringModel.build(pm, 7, 0.001);
        pm.init();
        PhyUGen direct = new PhyUGen(pm);
        direct.listenToMass(StringModel.mass(3), SteppedModel.Y, 300, 0);
        float[][] a = OfflineRenderer.renderToArray(direct, RATE, 1, 0.2);
        float[][] b = OfflineRenderer.renderToArray(new PluckedString(), RATE, 1, 0.2);
        assertTrue(peak(a[0]) > 0.05, "the string sounds");
        for (int i = 0; i < a[0].length; i++) {
            assertEquals(b[0][i], a[0][i], 0f, "sample " + i);
        }
    }

    private void assertPartials(PhyUGen ugen, int k, int channels, String name) throws Exception {
        File wav = dir.resolve(name + ".wav").toFile();
        double seconds = (FFT_SIZE + 4096) / (double) RATE;
        OfflineRenderer.Result r = OfflineRenderer.renderToWav(ugen, RATE, channels, seconds, wav,
                WavWriter.Encoding.PCM_16, null);
        assertTrue(r.peak > 0.05 && r.peak < 1, "peak " + r.peak + " is audible and unclipped");
        float[] x = readChannel0(wav, channels);
        Spectrum s = new Spectrum(x, 4096, FFT_SIZE, RATE);
        double f1 = StringModel.modeHz(1, k * (double) RATE);
        double previous = 0;
        double fundamentalMagnitude = s.peakMagnitude(0.8 * f1, 1.2 * f1);
        for (int m = 1; m <= 4; m++) {
            double theory = StringModel.modeHz(m, k * (double) RATE);
            double measured = s.peakHz(theory - 0.4 * f1, theory + 0.4 * f1);
            double cents = Spectrum.cents(measured, theory);
            assertTrue(Math.abs(cents) < 1, name + ": partial " + m + " at " + measured + " Hz, theory " + theory
                    + " Hz, off by " + cents + " cents");
            assertTrue(s.peakMagnitude(theory - 0.4 * f1, theory + 0.4 * f1) > 1e-3 * fundamentalMagnitude,
                    name + ": partial " + m + " is present");
            assertTrue(measured > previous, name + ": partials in order");
            previous = measured;
        }
    }

    static float[] readChannel0(File wav, int channels) throws Exception {
        try (AudioInputStream in = AudioSystem.getAudioInputStream(wav)) {
            AudioFormat f = in.getFormat();
            assertEquals(16, f.getSampleSizeInBits());
            assertEquals(channels, f.getChannels());
            assertEquals(RATE, f.getSampleRate(), 0);
            byte[] bytes = in.readAllBytes();
            ByteBuffer b = ByteBuffer.wrap(bytes).order(f.isBigEndian() ? ByteOrder.BIG_ENDIAN : ByteOrder.LITTLE_ENDIAN);
            int frames = bytes.length / (2 * channels);
            float[] x = new float[frames];
            for (int i = 0; i < frames; i++) {
                x[i] = b.getShort(2 * channels * i) / 32767f;
            }
            assertEquals(Files.size(wav.toPath()), 44 + bytes.length);
            return x;
        }
    }

    static double peak(float[] x) {
        double p = 0;
        for (float v : x) {
            p = Math.max(p, Math.abs(v));
        }
        return p;
    }
}
