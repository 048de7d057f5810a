package tactus.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import tactus.haptics.TimingVerdict;

/** The demo's last line judges the real-time run it measured (fed figures, no clock). */
class DemoVerdictTest {
    @Test
    void anOnTimeRunEndsWithTheFiguresAndTheScheduling() {
        String line = Demo.finalLine(TimingVerdict.haptic(3000, 0, 1.2, 0, "real-time (SCHED_FIFO 50)")
                .withAudio(3.0, 3.05));
        assertEquals("Demo finished: all files written, the strings' pitches match theory, and the real-time run was on "
                + "time (3000 ticks, 0.0 % missed, worst tick 1.2 ms late, 0 watchdog trips; scheduling: real-time "
                + "(SCHED_FIFO 50)).", line);
    }

    @Test
    void aLateRunEndsSayingSoAndWhatToDo() {
        String line = Demo.finalLine(TimingVerdict.haptic(3000, 153, 64, 2, "normal priority").withAudio(3.0, 3.75));
        assertTrue(line.startsWith("Demo finished: all files written, the strings' pitches match theory, but the "
                + "real-time run was LATE: the haptic loop missed 5.1 % of its ticks"), line);
        assertTrue(line.contains("the audio stalled: 3.00 s of sound took 3.75 s") && line.contains("Close other "
                + "programs") && line.contains("real-time priority"), line);
    }
}
