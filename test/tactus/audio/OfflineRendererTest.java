package tactus.audio;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ddf.minim.ugens.Gain;
import ddf.minim.ugens.Oscil;
import ddf.minim.ugens.Waves;
import java.io.ByteArrayOutputStream;
import java.io.File;
import java.io.PrintStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import javax.sound.sampled.AudioFormat;
import javax.sound.sampled.AudioInputStream;
import javax.sound.sampled.AudioSystem;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Any Minim UGen graph renders to a float WAV that javax.sound reads back; progress lines; bad arguments. */
class OfflineRendererTest {
    @TempDir
    Path dir;

    @Test
    void aPlainMinimGraphRendersToAFloatWavWithProgressLines() throws Exception {
        Oscil osc = new Oscil(441f, 0.5f, Waves.SINE);
        Gain gain = new Gain(-6f);
        osc.patch(gain);
        File wav = dir.resolve("osc.wav").toFile();
        ByteArrayOutputStream text = new ByteArrayOutputStream();
        PrintStream progress = new PrintStream(text, true, StandardCharsets.UTF_8);
        OfflineRenderer.Result r = OfflineRenderer.renderToWav(gain, 44100, 1, 1.5, wav, WavWriter.Encoding.FLOAT_32,
                progress, 0);
        assertEquals(66150, r.frames);
        String lines = text.toString(StandardCharsets.UTF_8);
        assertTrue(lines.contains("rendering osc.wav:") && lines.contains("real time") && lines.contains("rendered osc.wav"),
                lines);
        try (AudioInputStream in = AudioSystem.getAudioInputStream(wav)) {
            AudioFormat f = in.getFormat();
            assertEquals(AudioFormat.Encoding.PCM_FLOAT, f.getEncoding());
            assertEquals(32, f.getSampleSizeInBits());
            byte[] bytes = in.readAllBytes();
            assertEquals(4 * 66150, bytes.length);
            ByteBuffer b = ByteBuffer.wrap(bytes).order(ByteOrder.LITTLE_ENDIAN);
            float[] x = new float[66150];
            double peak = 0;
            for (int i = 0; i < x.length; i++) {
                x[i] = b.getFloat(4 * i);
                peak = Math.max(peak, Math.abs(x[i]));
            }
            assertEquals(0.5 * Math.pow(10, -6 / 20.0), peak, 1e-3, "amplitude 0.5 at -6 dB");
            double hz = new Spectrum(x, 0, 1 << 16, 44100).peakHz(300, 600);
            assertTrue(Math.abs(Spectrum.cents(hz, 441)) < 1, "441 Hz sine measured at " + hz);
        }
        assertEquals(r.peak, 0.5 * Math.pow(10, -6 / 20.0), 1e-3);
    }

    @Test
    void badArgumentsAreRejectedWithTheValue() {
        Oscil osc = new Oscil(441f, 0.5f, Waves.SINE);
        assertTrue(assertThrows(IllegalArgumentException.class, () -> OfflineRenderer.renderToArray(osc, 0, 1, 1))
                .getMessage().contains("0.0"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> OfflineRenderer.renderToArray(osc, 44100, 9, 1))
                .getMessage().contains("9"));
        assertThrows(IllegalArgumentException.class, () -> OfflineRenderer.renderToArray(osc, 44100, 1, -1));
    }
}
