package tactus.sketch;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.function.IntToDoubleFunction;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import tactus.audio.WavWriter;

/**
 * Checks the measures that {@link ExamplesTest} applies to every example, on synthetic inputs whose results are
 * known in closed form: the drawn share of a frame, the changed share between two frames, and the level of a WAV
 * recording, with the thresholds the examples must pass.
 */
class FrameAndSoundChecksTest {

    @TempDir
    Path tmp;

    private static final int RATE = 44100;

    private Path wav(String name, WavWriter.Encoding enc, int channels, int frames, IntToDoubleFunction signal)
            throws IOException {
        Path p = tmp.resolve(name);
        try (WavWriter w = new WavWriter(p.toFile(), RATE, channels, frames, enc)) {
            float[] frame = new float[channels];
            for (int i = 0; i < frames; i++) {
                for (int c = 0; c < channels; c++) {
                    frame[c] = (float) signal.applyAsDouble(i);
                }
                w.writeFrame(frame);
            }
        }
        return p;
    }

    @Test
    void aSineHasTheRmsOfTheory() throws IOException {
        // A sine of amplitude A over a whole number of periods: RMS A / sqrt(2), peak A. 441 Hz: 100 samples a period.
        double a = 0.5;
        for (WavWriter.Encoding enc : WavWriter.Encoding.values()) {
            Path p = wav("sine-" + enc + ".wav", enc, 2, RATE, i -> a * Math.sin(2 * Math.PI * 441 * i / RATE));
            FrameAndSoundChecks.Level l = FrameAndSoundChecks.level(p);
            assertEquals(RATE, l.frames);
            assertEquals(RATE, l.sampleRate);
            // 16-bit rounding adds at most half a step of error per sample.
            double tol = enc == WavWriter.Encoding.PCM_16 ? 1.0 / 32768 : 1e-6;
            assertEquals(a / Math.sqrt(2), l.acRms, tol, enc.toString());
            assertEquals(a, l.peak, tol, enc.toString());
            assertTrue(l.acRms >= ExamplesTest.MIN_AC_RMS);
        }
    }

    @Test
    void silenceAndAConstantOffsetAreSilent() throws IOException {
        FrameAndSoundChecks.Level zero = FrameAndSoundChecks.level(wav("zero.wav", WavWriter.Encoding.PCM_16, 1,
                4410, i -> 0));
        assertEquals(0.0, zero.acRms, 0.0);
        assertEquals(Double.NEGATIVE_INFINITY, zero.acRmsDbfs());
        // A stuck output (a constant 0.3) is not sound: the mean is removed.
        FrameAndSoundChecks.Level dc = FrameAndSoundChecks.level(wav("dc.wav", WavWriter.Encoding.FLOAT_32, 1,
                4410, i -> 0.3));
        assertEquals(0.0, dc.acRms, 1e-7);
        assertEquals(0.3, dc.peak, 1e-7);
        assertFalse(dc.acRms >= ExamplesTest.MIN_AC_RMS);
    }

    @Test
    void theThresholdSitsBetweenQuantisationNoiseAndAQuietSound() throws IOException {
        // A sine at -70 dBFS RMS fails the check, one at -50 dBFS passes.
        double quiet = Math.sqrt(2) * Math.pow(10, -70 / 20.0);
        double audible = Math.sqrt(2) * Math.pow(10, -50 / 20.0);
        FrameAndSoundChecks.Level q = FrameAndSoundChecks.level(wav("q.wav", WavWriter.Encoding.FLOAT_32, 1, 44100,
                i -> quiet * Math.sin(2 * Math.PI * 441 * i / RATE)));
        FrameAndSoundChecks.Level l = FrameAndSoundChecks.level(wav("l.wav", WavWriter.Encoding.FLOAT_32, 1, 44100,
                i -> audible * Math.sin(2 * Math.PI * 441 * i / RATE)));
        assertEquals(-70, q.acRmsDbfs(), 0.01);
        assertEquals(-50, l.acRmsDbfs(), 0.01);
        assertFalse(q.acRms >= ExamplesTest.MIN_AC_RMS);
        assertTrue(l.acRms >= ExamplesTest.MIN_AC_RMS);
        // Alternating one-step 16-bit noise, +-2^-15: RMS 2^-15, about -90 dBFS, far below the threshold.
        FrameAndSoundChecks.Level lsb = FrameAndSoundChecks.level(wav("lsb.wav", WavWriter.Encoding.PCM_16, 1,
                44100, i -> (i % 2 == 0 ? 1 : -1) / 32768.0));
        assertEquals(1.0 / 32768, lsb.acRms, 1e-6);
        assertFalse(lsb.acRms >= ExamplesTest.MIN_AC_RMS);
    }

    /** 8-bit WAV samples are unsigned, 128 being zero: a square wave of +-64 steps has an RMS of 0.5. */
    @Test
    void eightBitFilesAreRead() throws IOException {
        int n = 1000;
        java.nio.ByteBuffer b = java.nio.ByteBuffer.allocate(44 + n).order(java.nio.ByteOrder.LITTLE_ENDIAN);
        b.put("RIFF".getBytes(java.nio.charset.StandardCharsets.US_ASCII)).putInt(36 + n)
                .put("WAVEfmt ".getBytes(java.nio.charset.StandardCharsets.US_ASCII)).putInt(16)
                .putShort((short) 1).putShort((short) 1).putInt(8000).putInt(8000).putShort((short) 1)
                .putShort((short) 8).put("data".getBytes(java.nio.charset.StandardCharsets.US_ASCII)).putInt(n);
        for (int i = 0; i < n; i++) {
            b.put((byte) (i % 2 == 0 ? 128 + 64 : 128 - 64));
        }
        Path p = tmp.resolve("eight.wav");
        Files.write(p, b.array());
        FrameAndSoundChecks.Level l = FrameAndSoundChecks.level(p);
        assertEquals(n, l.frames);
        assertEquals(8000, l.sampleRate);
        assertEquals(0.5, l.acRms, 1e-12);
        assertEquals(0.5, l.peak, 1e-12);
    }

    @Test
    void notAWaveFileIsRefused() throws IOException {
        Path p = tmp.resolve("text.wav");
        Files.write(p, "hello, not a wave file".getBytes(java.nio.charset.StandardCharsets.US_ASCII));
        assertThrows(IllegalArgumentException.class, () -> FrameAndSoundChecks.level(p));
    }

    @Test
    void drawnShareCountsPixelsOffTheBackground() {
        BufferedImage img = new BufferedImage(100, 50, BufferedImage.TYPE_INT_RGB);
        assertEquals(0.0, FrameAndSoundChecks.drawnShare(img), 0.0);
        // A 10 x 5 white rectangle on black: 50 of 5000 pixels.
        for (int y = 0; y < 5; y++) {
            for (int x = 0; x < 10; x++) {
                img.setRGB(x, y, 0xFFFFFF);
            }
        }
        assertEquals(0.01, FrameAndSoundChecks.drawnShare(img), 1e-12);
    }

    @Test
    void changedShareCountsPixelsBeyondTheTolerance() {
        BufferedImage a = new BufferedImage(20, 10, BufferedImage.TYPE_INT_RGB);
        BufferedImage b = new BufferedImage(20, 10, BufferedImage.TYPE_INT_RGB);
        assertEquals(0.0, FrameAndSoundChecks.changedShare(a, b, 0), 0.0);
        b.setRGB(0, 0, 0x000008);   // within a tolerance of 8: not a change
        b.setRGB(1, 0, 0x090000);   // beyond it
        b.setRGB(2, 0, 0x00FF00);
        assertEquals(2.0 / 200, FrameAndSoundChecks.changedShare(a, b, 8), 1e-12);
        assertEquals(3.0 / 200, FrameAndSoundChecks.changedShare(a, b, 0), 1e-12);
        assertThrows(IllegalArgumentException.class, () -> FrameAndSoundChecks.changedShare(a,
                new BufferedImage(10, 10, BufferedImage.TYPE_INT_RGB), 0));
    }

    @Test
    void soundIsRecognisedFromTheSource() {
        assertTrue(FrameAndSoundChecks.makesSound("PhyUGen simUGen;"));
        assertTrue(FrameAndSoundChecks.makesSound("out = minim.getLineOut();"));
        assertTrue(FrameAndSoundChecks.makesSound("LineOut.open(this)"));
        assertFalse(FrameAndSoundChecks.makesSound("PhyUGenerator x; // a LineOutline"));
        assertFalse(FrameAndSoundChecks.makesSound("mdl.draw_physics();"));
    }
}
