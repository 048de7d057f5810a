package tactus.audio;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ddf.minim.AudioOutput;
import ddf.minim.Minim;
import java.io.File;
import java.nio.file.Path;
import javax.sound.sampled.AudioFormat;
import javax.sound.sampled.AudioInputStream;
import javax.sound.sampled.AudioSystem;
import javax.sound.sampled.DataLine;
import javax.sound.sampled.SourceDataLine;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import tactus.PhysicalModel;

/**
 * With no sound card, Minim's own getLineOut() plays into Tactus's virtual output (registered through
 * META-INF/services): the graph runs at the pace of the sample rate (never faster), and with
 * -Dtactus.audio.record=file.wav everything played lands in a valid WAV file, header kept up to date while it plays.
 * Skipped on a machine whose real mixer plays the format (the virtual output then stays out of the way).
 */
class VirtualLineOutTest {
    @TempDir
    Path dir;

    private static void assumeHeadless(AudioFormat f) {
        Assumptions.assumeFalse(VirtualMixer.realMixerSupports(new DataLine.Info(SourceDataLine.class, f)),
                "this machine has a sound card");
    }

    @Test
    void getLineOutWorksHeadlessAndRecordsWhenAsked() throws Exception {
        assumeHeadless(new AudioFormat(44100f, 16, 2, true, false));
        File wav = dir.resolve("played.wav").toFile();
        String before = System.getProperty(HeadlessRecording.PROPERTY);
        System.setProperty(HeadlessRecording.PROPERTY, wav.getPath());
        HeadlessRecording.releaseClaimForTests();
        Minim minim = new Minim(new HeadlessLineOutTest.Files(dir.toFile()));
        try {
            AudioOutput out = minim.getLineOut(Minim.STEREO, 512, 44100f, 16);
            assertNotNull(out, "getLineOut() must not be null with the virtual output registered");
            PhysicalModel pm = new PhysicalModel(44100);
            StringModel.build(pm, 7, 0.001);
            pm.init();
            PhyUGen ugen = new PhyUGen(pm);
            ugen.listenToMass(StringModel.mass(3), SteppedModel.Y, 300, 0);
            long t0 = System.nanoTime();
            ugen.patch(out);
            long deadline = t0 + 30_000_000_000L;
            while (pm.getStepCount() < 22050 && System.nanoTime() < deadline) {
                Thread.sleep(20);
            }
            long steps = pm.getStepCount();
            double elapsed = (System.nanoTime() - t0) * 1e-9;
            assertTrue(steps >= 22050, "the graph ran: " + steps + " steps");
            // real time, never faster: at most the elapsed time plus the line's buffer (4 x 512 frames) and one
            // buffer being computed; load can only make it slower
            assertTrue(steps <= elapsed * 44100 + 5 * 512 + 512, steps + " steps in " + elapsed + " s");
            // the header is valid while it still plays
            try (AudioInputStream in = AudioSystem.getAudioInputStream(wav)) {
                assertEquals(2, in.getFormat().getChannels());
                assertEquals(44100f, in.getFormat().getSampleRate());
                assertTrue(in.getFrameLength() > 0, "frames recorded so far: " + in.getFrameLength());
            }
            out.close();
            try (AudioInputStream in = AudioSystem.getAudioInputStream(wav)) {
                byte[] bytes = in.readAllBytes();
                assertEquals(in.getFrameLength() * 4, bytes.length);
                long frames = bytes.length / 4;
                // everything computed before the close was written to the line (the line holds at most 4 buffers)
                assertTrue(frames >= steps - 4 * 512, frames + " frames recorded for " + steps + " steps");
                int nonZero = 0;
                for (byte b : bytes) {
                    nonZero += b != 0 ? 1 : 0;
                }
                assertTrue(nonZero > bytes.length / 10, "the string is heard: " + nonZero + " of " + bytes.length);
            }
        } finally {
            minim.stop();
            HeadlessRecording.releaseClaimForTests();
            if (before == null) {
                System.clearProperty(HeadlessRecording.PROPERTY);
            } else {
                System.setProperty(HeadlessRecording.PROPERTY, before);
            }
        }
    }

    @Test
    void theVirtualLinePacesWritesAtTheFrameRate() throws Exception {
        AudioFormat f = new AudioFormat(8000f, 16, 1, true, false);
        VirtualSourceLine line = new VirtualSourceLine(new DataLine.Info(SourceDataLine.class, f), f);
        line.open(f, 800 * 2);               // 0.1 s of buffer
        line.start();
        assertEquals(1600, line.available());
        byte[] b = new byte[1600];
        for (int i = 0; i < 5; i++) {
            assertEquals(b.length, line.write(b, 0, b.length));
        }
        // 0.5 s written into a 0.1 s buffer: the last write returns only once 0.4 s of it has played (by the line's
        // own clock), and it never plays more than it was given
        long played = line.getLongFramePosition();
        assertTrue(played >= 4 * 800 && played <= 5 * 800, "frames played when the writes returned: " + played);
        line.close();
    }
}
