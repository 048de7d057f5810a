package tactus.haptics;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * Judges how well a real-time run kept time, from what it measured: the haptic loop's telemetry, how it was
 * scheduled and, when the run also made sound, how long its audio took against how long it lasts. The verdict says
 * "on time" with the figures, or which figure was beyond its bound and what to do about it; a demo or an
 * application prints it instead of a claim it did not check.
 *
 * <p>The bounds: at most {@value #MAX_MISSED_PERCENT} % of the ticks missed, no tick more than
 * {@value #MAX_LATE_MS} ms late, no watchdog trip, and the audio no more than {@value #MAX_AUDIO_STALL_S} s behind
 * its own duration. Late is not broken: the model's results (pitches, forces) can still be right; the verdict says
 * that the run was not what a quiet machine gives.
 */
public final class TimingVerdict {
    /** The largest share of missed ticks (a period more than 1.5 periods long) still on time, in percent. */
    public static final double MAX_MISSED_PERCENT = 1.0;
    /** The largest lateness of one tick still on time, in milliseconds. */
    public static final double MAX_LATE_MS = 20.0;
    /** The largest delay of the audio behind its own duration still on time, in seconds. */
    public static final double MAX_AUDIO_STALL_S = 0.25;

    private final List<String> late = new ArrayList<>();
    private final String figures;
    private final String scheduling;

    private TimingVerdict(String figures, String scheduling) {
        this.figures = figures;
        this.scheduling = scheduling;
    }

    /**
     * Judges a haptic loop's run.
     *
     * @param t the loop's telemetry at the end of the run
     * @param scheduling what {@link HapticLoop#scheduling()} said
     */
    public static TimingVerdict of(HapticTelemetry t, String scheduling) {
        return haptic(t.ticks, t.missedSteps, t.jitterMaxUs / 1000, t.watchdogTrips, scheduling);
    }

    /**
     * Judges a haptic loop's run from its figures.
     *
     * @param ticks the ticks run
     * @param missed the ticks that came more than half a period late
     * @param worstLateMs the lateness of the latest tick, in milliseconds
     * @param watchdogTrips the times the loop's watchdog zeroed the motors
     * @param scheduling how the loop thread was scheduled, as {@link HapticLoop#scheduling()} says it
     */
    public static TimingVerdict haptic(long ticks, long missed, double worstLateMs, long watchdogTrips,
                                       String scheduling) {
        double missedPercent = ticks > 0 ? 100.0 * missed / ticks : 0;
        TimingVerdict v = new TimingVerdict(String.format(Locale.ROOT, "%d ticks, %.1f %% missed, worst tick %.1f ms"
                + " late, %d watchdog trips", ticks, missedPercent, worstLateMs, watchdogTrips), scheduling);
        if (missedPercent > MAX_MISSED_PERCENT) {
            v.late.add(String.format(Locale.ROOT, "the haptic loop missed %.1f %% of its ticks (%d of %d; bound %.0f %%)",
                    missedPercent, missed, ticks, MAX_MISSED_PERCENT));
        }
        if (worstLateMs > MAX_LATE_MS) {
            v.late.add(String.format(Locale.ROOT, "its worst tick was %.1f ms late (bound %.0f ms)", worstLateMs,
                    MAX_LATE_MS));
        }
        if (watchdogTrips > 0) {
            v.late.add(watchdogTrips + " watchdog trip" + (watchdogTrips > 1 ? "s" : "")
                    + " zeroed the motors (the loop stalled)");
        }
        return v;
    }

    /**
     * Adds the audio of the same run: {@code audioSeconds} of sound that took {@code wallSeconds} to play (a real-time
     * output plays a second of sound in a second).
     *
     * @return this verdict
     */
    public TimingVerdict withAudio(double audioSeconds, double wallSeconds) {
        double behind = wallSeconds - audioSeconds;
        if (behind > MAX_AUDIO_STALL_S) {
            late.add(String.format(Locale.ROOT, "the audio stalled: %.2f s of sound took %.2f s, %.2f s behind (bound"
                    + " %.2f s)", audioSeconds, wallSeconds, behind, MAX_AUDIO_STALL_S));
        }
        return this;
    }

    /**
     * Adds a disagreement between two records of the same run that should coincide in time (for example the
     * waveform and the handle's path).
     *
     * @param what the two records
     * @param seconds how far apart they are, in seconds
     * @param boundSeconds the largest gap still on time
     * @return this verdict
     */
    public TimingVerdict withAgreement(String what, double seconds, double boundSeconds) {
        if (Math.abs(seconds) > boundSeconds) {
            late.add(String.format(Locale.ROOT, "%s disagree by %.2f s (bound %.2f s)", what, Math.abs(seconds),
                    boundSeconds));
        }
        return this;
    }

    /** Whether every figure was within its bound. */
    public boolean onTime() {
        return late.isEmpty();
    }

    /** The reasons the run was late, one per figure beyond its bound (empty when on time). */
    public List<String> reasons() {
        return new ArrayList<>(late);
    }

    /**
     * The verdict in one paragraph: "the real-time run was on time (figures; scheduling)", or "... was LATE: reasons (figures; scheduling). The
     * machine was busy ..." with what to do.
     */
    public String text() {
        String tail = " (" + figures + "; scheduling: " + scheduling + ")";
        if (late.isEmpty()) {
            return "the real-time run was on time" + tail;
        }
        return "the real-time run was LATE: " + String.join("; ", late) + tail + ". " + advice();
    }

    private String advice() {
        boolean realtime = scheduling != null && scheduling.startsWith("real-time");
        String first = "The machine was busy: what you hear and feel in this run is not what a quiet machine gives, "
                + "though the model's own results (pitches, forces) are computed the same. Close other programs or run "
                + "again when the machine is idle";
        if (realtime) {
            return first + "; the loop had real-time scheduling, so the delays came from elsewhere (the audio thread,"
                    + " the JVM's safepoints, the machine's other real-time work): see docs/haptics.md.";
        }
        if (scheduling != null && scheduling.contains("refused")) {
            return first + ", and let the loop run at real-time priority: allow it for your user (an rtprio limit in "
                    + "/etc/security/limits.conf, as audio users have, or CAP_SYS_NICE), see docs/haptics.md.";
        }
        return first + ", and ask for real-time priority for the loop (HapticLoop.setRealtimePriority, which a "
                + "HapticSession does), see docs/haptics.md.";
    }

    @Override
    public String toString() {
        return text();
    }
}
