package tactus.audio;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.File;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import javax.sound.sampled.AudioFormat;
import javax.sound.sampled.DataLine;
import javax.sound.sampled.Line;
import javax.sound.sampled.SourceDataLine;
import org.junit.jupiter.api.Test;

/** With no sound device, one line says that the sound goes nowhere and how to render a WAV instead, once per JVM. */
class NoSoundDeviceNoticeTest {
    @Test
    void theLineSaysWhereTheSoundGoesAndHowToHearIt() {
        assertEquals("Tactus audio: no sound device, so the sound plays into Tactus's virtual output and goes nowhere. "
                + "To hear it, render a WAV: run with -Dtactus.audio.record=out.wav to record this output, or render "
                + "offline with tactus.audio.OfflineRenderer.renderToWav", VirtualMixer.notice(null));
        assertEquals("Tactus audio: no sound device, so the sound plays into Tactus's virtual output and is recorded to "
                + new File("take.wav").getAbsolutePath() + " (tactus.audio.record)", VirtualMixer.notice("take.wav"));
    }

    @Test
    void itIsPrintedOnceWhenTheVirtualOutputHandsOutALine() throws Exception {
        VirtualMixer.forgetToldForTests();
        ByteArrayOutputStream copy = new ByteArrayOutputStream();
        PrintStream out = new PrintStream(copy, true, StandardCharsets.UTF_8);
        assertTrue(VirtualMixer.tellOnce(out));
        assertFalse(VirtualMixer.tellOnce(out), "once per JVM");
        assertEquals(1, copy.toString(StandardCharsets.UTF_8).split("\n").length);

        VirtualMixer.forgetToldForTests();
        PrintStream before = System.err;
        ByteArrayOutputStream err = new ByteArrayOutputStream();
        System.setErr(new PrintStream(err, true, StandardCharsets.UTF_8));
        try {
            AudioFormat f = new AudioFormat(44100f, 16, 2, true, false);
            Line line = new VirtualMixerProvider().getMixer(null).getLine(new DataLine.Info(SourceDataLine.class, f));
            line.close();
        } finally {
            System.setErr(before);
        }
        assertTrue(err.toString(StandardCharsets.UTF_8).contains("no sound device"), err.toString());
    }
}
