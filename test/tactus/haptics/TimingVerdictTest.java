package tactus.haptics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** The verdict of a real-time run, fed measured figures (no clock): on time, or late with the reasons and the fix. */
class TimingVerdictTest {
    private static final String DEADLINE = "real-time (SCHED_DEADLINE 800 us of every 1000 us; safety threads at "
            + "SCHED_FIFO 50)";

    @Test
    void aQuietRunIsOnTimeAndSaysItsFigures() {
        TimingVerdict v = TimingVerdict.haptic(3000, 3, 2.5, 0, DEADLINE).withAudio(3.0, 3.1);
        assertTrue(v.onTime());
        assertEquals("the real-time run was on time (3000 ticks, 0.1 % missed, worst tick 2.5 ms late, 0 watchdog trips; "
                + "scheduling: " + DEADLINE + ")", v.text());
    }

    @Test
    void theLoadedDemoOfTheIssueIsLateWithEachReason() {
        // the demo at load 3-7: audio stalled 0.75 s, 5.1 % missed, plots 0.5 s apart; normal priority
        TimingVerdict v = TimingVerdict.haptic(3000, 153, 64.0, 2, "normal priority (real-time refused: chrt: "
                + "Operation not permitted)").withAudio(3.0, 3.75).withAgreement("the waveform and path plots", 0.5, 0.05);
        assertFalse(v.onTime());
        assertEquals(5, v.reasons().size(), v.text());
        String t = v.text();
        assertTrue(t.startsWith("the real-time run was LATE: the haptic loop missed 5.1 % of its ticks (153 of 3000; bound 1 %);"
                + " its worst tick was 64.0 ms late (bound 20 ms); 2 watchdog trips zeroed the motors (the loop stalled);"
                + " the audio stalled: 3.00 s of sound took 3.75 s, 0.75 s behind (bound 0.25 s); the waveform and path"
                + " plots disagree by 0.50 s (bound 0.05 s)"), t);
        assertTrue(t.contains("let the loop run at real-time priority") && t.contains("rtprio"), t);
    }

    @Test
    void eachBoundIsJudgedOnItsOwn() {
        assertTrue(TimingVerdict.haptic(1000, 10, 20.0, 0, DEADLINE).onTime(), "1.0 % and 20 ms are within");
        assertFalse(TimingVerdict.haptic(1000, 11, 1.0, 0, DEADLINE).onTime(), "1.1 % missed");
        assertFalse(TimingVerdict.haptic(1000, 0, 20.1, 0, DEADLINE).onTime(), "20.1 ms");
        assertFalse(TimingVerdict.haptic(1000, 0, 1.0, 1, DEADLINE).onTime(), "a watchdog trip");
        assertFalse(TimingVerdict.haptic(1000, 0, 1.0, 0, DEADLINE).withAudio(1.0, 1.3).onTime(), "audio 0.3 s behind");
        TimingVerdict rt = TimingVerdict.haptic(1000, 50, 1.0, 0, DEADLINE);
        assertTrue(rt.text().contains("the loop had real-time scheduling, so the delays came from elsewhere"), rt.text());
        String notAsked = TimingVerdict.haptic(1000, 50, 1.0, 0, "normal priority").text();
        assertTrue(notAsked.contains("ask for real-time priority for the loop (HapticLoop.setRealtimePriority"), notAsked);
        HapticTelemetry t = new HapticTelemetry(1000, 488, 1.0, 12, 100_000, 500_000, 30_000_000, 50_000, 90_000,
                200_000, 0, 0, 0, 0);
        TimingVerdict fromTelemetry = TimingVerdict.of(t, "normal priority");
        assertEquals(2, fromTelemetry.reasons().size(), fromTelemetry.text());
        assertTrue(fromTelemetry.text().contains("missed 2.5 % of its ticks (12 of 488") 
                && fromTelemetry.text().contains("worst tick was 30.0 ms late"), fromTelemetry.text());
    }
}
