package tactus.audio;

import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ddf.minim.AudioOutput;
import ddf.minim.AudioRecorder;
import ddf.minim.Minim;
import java.io.ByteArrayOutputStream;
import java.io.File;
import java.io.FileInputStream;
import java.io.InputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import javax.sound.sampled.AudioInputStream;
import javax.sound.sampled.AudioSystem;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import tactus.PhysicalModel;

/**
 * When Minim.getLineOut() returns null, LineOut turns that into a clear message and a silent AudioOutput whose
 * thread still computes the patched PhyUGen in real time, so the model steps, Minim's mix buffer fills and an
 * AudioRecorder on the output records. (With Tactus's virtual mixer registered, getLineOut() no longer returns
 * null on this machine: VirtualLineOutTest; the fallback is exercised directly here.)
 */
class HeadlessLineOutTest {

    /** Minim finds these two methods by reflection; the class must be public. */
    public static final class Files {
        private final File dir;

        Files(File dir) {
            this.dir = dir;
        }

        public String sketchPath(String name) {
            File f = new File(name);
            return f.isAbsolute() ? name : new File(dir, name).getAbsolutePath();
        }

        public InputStream createInput(String name) throws java.io.IOException {
            return new FileInputStream(sketchPath(name));
        }
    }

    @TempDir
    Path dir;

    @Test
    void noSoundCardGivesASilentOutputThatStillStepsTheModel() throws Exception {
        Minim minim = new Minim(new Files(dir.toFile()));
        try {
            ByteArrayOutputStream text = new ByteArrayOutputStream();
            AudioOutput out = LineOut.silent(Minim.STEREO, 512, 44100f,
                    new PrintStream(text, true, StandardCharsets.UTF_8));
            assertNotNull(out);
            String message = text.toString(StandardCharsets.UTF_8);
            assertTrue(message.contains("no sound output") && message.contains("OfflineRenderer"), message);
            AudioOutput fallback = LineOut.orSilent(null, Minim.MONO, 256, 22050f);
            assertNotNull(fallback);
            fallback.close();

            PhysicalModel pm = new PhysicalModel(44100);
            StringModel.build(pm, 7, 0.001);
            pm.init();
            PhyUGen ugen = new PhyUGen(pm);
            ugen.listenToMass(StringModel.mass(3), SteppedModel.Y, 300, 0);
            File wav = dir.resolve("recorded.wav").toFile();
            AudioRecorder recorder = minim.createRecorder(out, wav.getAbsolutePath(), true);
            ugen.patch(out);
            recorder.beginRecord();
            long deadline = System.nanoTime() + 30_000_000_000L;
            while (pm.getStepCount() < 22050 && System.nanoTime() < deadline) {
                Thread.sleep(20);
            }
            recorder.endRecord();
            assertTrue(pm.getStepCount() >= 22050, "the silent output stepped the model: " + pm.getStepCount());
            try {
                recorder.save();
            } catch (NullPointerException expectedHeadless) {
                // Minim writes the file, then fails to open a playback line for it (no sound card)
            }
            out.close();
            long after = pm.getStepCount();
            Thread.sleep(100);
            assertTrue(pm.getStepCount() == after, "closing the output stops the stepping");
            try (AudioInputStream in = AudioSystem.getAudioInputStream(wav)) {
                byte[] bytes = in.readAllBytes();
                int nonZero = 0;
                for (byte b : bytes) {
                    nonZero += b != 0 ? 1 : 0;
                }
                assertTrue(bytes.length > 0 && nonZero > bytes.length / 10, "the recorder got the string's sound: "
                        + bytes.length + " bytes, " + nonZero + " non-zero");
            }
        } finally {
            minim.stop();
        }
    }
}
