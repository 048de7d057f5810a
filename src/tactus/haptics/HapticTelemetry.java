package tactus.haptics;

import java.util.Locale;

/**
 * A snapshot of a {@link HapticLoop}'s timing and safety counters. Jitter is |period - nominal| between the
 * starts of consecutive ticks; percentiles are over the last {@link HapticLoop#WINDOW} ticks, read from
 * log-linear histograms (each percentile is the lower edge of its bucket: at most 1.6 % below the sample).
 */
public final class HapticTelemetry {
    /** Nominal rate in Hz. */
    public final double nominalHz;
    /** Ticks run since start. */
    public final long ticks;
    /** Seconds since start. */
    public final double seconds;
    /** Achieved rate in Hz (ticks / seconds). */
    public final double achievedHz;
    /** Periods longer than 1.5 times the nominal period. */
    public final long missedSteps;
    /** Period jitter percentiles and maximum, microseconds. */
    public final double jitterP50Us;
    /** 99th percentile of the period jitter, microseconds. */
    public final double jitterP99Us;
    /** Largest period jitter seen since start, microseconds. */
    public final double jitterMaxUs;
    /** Compute time per tick (read to write), median, microseconds. */
    public final double computeP50Us;
    /** Compute time per tick, 99th percentile, microseconds. */
    public final double computeP99Us;
    /** Largest compute time per tick since start, microseconds. */
    public final double computeMaxUs;
    /** Ticks that found no new reply from the board (the previous position was reused). */
    public final long staleTicks;
    /** Ticks whose force was non-finite or above the runaway limit (zero torque was sent). */
    public final long faultTicks;
    /** Ticks whose torque was scaled down to the torque limit. */
    public final long clampedTicks;
    /** Times the watchdog zeroed the torque because no tick ran for too long. */
    public final long watchdogTrips;

    HapticTelemetry(double nominalHz, long ticks, double seconds, long missed, long jitterP50, long jitterP99,
                    long jitterMax, long computeP50, long computeP99, long computeMax, long stale, long faults,
                    long clamped, long watchdog) {
        this.nominalHz = nominalHz;
        this.ticks = ticks;
        this.seconds = seconds;
        this.achievedHz = seconds > 0 ? ticks / seconds : 0;
        this.missedSteps = missed;
        this.jitterP50Us = jitterP50 / 1e3;
        this.jitterP99Us = jitterP99 / 1e3;
        this.jitterMaxUs = jitterMax / 1e3;
        this.computeP50Us = computeP50 / 1e3;
        this.computeP99Us = computeP99 / 1e3;
        this.computeMaxUs = computeMax / 1e3;
        this.staleTicks = stale;
        this.faultTicks = faults;
        this.clampedTicks = clamped;
        this.watchdogTrips = watchdog;
    }

    /** Missed steps as a fraction of ticks. */
    public double missedFraction() {
        return ticks == 0 ? 0 : (double) missedSteps / ticks;
    }

    @Override
    public String toString() {
        return String.format(Locale.ROOT,
                "haptic loop: %.1f Hz of %.0f (%d ticks in %.2f s), missed %d (%.3f%%), jitter p50 %.1f us, "
                        + "p99 %.1f us, max %.1f us, compute p50 %.1f us, p99 %.1f us, max %.1f us, stale %d, "
                        + "faults %d, clamped %d, watchdog %d",
                achievedHz, nominalHz, ticks, seconds, missedSteps, 100 * missedFraction(), jitterP50Us,
                jitterP99Us, jitterMaxUs, computeP50Us, computeP99Us, computeMaxUs, staleTicks, faultTicks,
                clampedTicks, watchdogTrips);
    }
}
