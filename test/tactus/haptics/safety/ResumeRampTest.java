package tactus.haptics.safety;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * The ramp that brings a device's force back after a guard zeroed it, on a clock the test sets: whatever the
 * writer does (steady at 1 kHz or 100 Hz, a burst of catch-up writes, a pause in the middle of the ramp, jitter),
 * the factor never grows faster than the duration allows in wall time, nor by more than a step per write, and it
 * reaches 1 once the writes have covered the duration.
 */
@Timeout(value = 10, unit = TimeUnit.SECONDS)
class ResumeRampTest {
    private static final long MS = 1_000_000L;
    private static final long DURATION = 100 * MS;
    private static final double STEP = 0.05;

    /**
     * Writes at the given times (ns after start, when the ramp began or last wrote); checks both bounds at each;
     * returns the last factor.
     */
    private static double writeAt(ResumeRamp ramp, long start, long[] times) {
        double last = ramp.last();
        long lastT = 0;
        for (long t : times) {
            double f = ramp.factor(start + t);
            assertTrue(ramp.isRunning() || f == 1, "a ramp ends at 1: " + f);
            assertTrue(f >= last, "the factor never falls during a ramp: " + last + " then " + f + " at " + t / 1e6 + " ms");
            assertTrue(f - last <= STEP + 1e-12, "at most one step per write: " + last + " to " + f + " at " + t / 1e6
                    + " ms");
            assertTrue(f - last <= (t - lastT) / (double) DURATION + 1e-12, "no faster than the duration in the time "
                    + "between writes: " + last + " to " + f + " in " + (t - lastT) / 1e6 + " ms");
            assertTrue(f <= 1, "at most 1: " + f);
            last = f;
            lastT = t;
        }
        return last;
    }

    private static long[] every(long from, long period, int n) {
        long[] t = new long[n];
        for (int i = 0; i < n; i++) {
            t[i] = from + i * period;
        }
        return t;
    }

    @Test
    void aSteadyWriterAt1kHzRampsLinearlyOverTheDuration() {
        ResumeRamp ramp = new ResumeRamp(DURATION, STEP);
        ramp.start(5 * MS);
        assertEquals(0.5, writeAt(ramp, 5 * MS, every(MS, MS, 50)), 1e-9, "half way after 50 ms");
        assertTrue(ramp.isRunning());
        assertEquals(1.0, writeAt(ramp, 55 * MS, every(MS, MS, 50)), 1e-9, "whole after 100 ms");
        assertFalse(ramp.isRunning(), "the ramp ends at 1");
        assertEquals(1.0, ramp.factor(10_000 * MS), "no ramp: factor 1");
    }

    @Test
    void aSlowWriterStillTakesTwentyWrites() {
        ResumeRamp ramp = new ResumeRamp(DURATION, STEP);
        ramp.start(0);
        double f = writeAt(ramp, 0, every(100 * MS, 100 * MS, 19));   // 10 Hz: each write is one step
        assertEquals(19 * STEP, f, 1e-9);
        assertTrue(ramp.isRunning(), "19 writes are not enough");
        assertEquals(1.0, ramp.factor(2_000 * MS), 1e-9);
    }

    /** A fixed-rate executor after a pause: hundreds of writes a few microseconds apart, then 1 kHz again. */
    @Test
    void aBurstOfCatchUpWritesDoesNotShortenTheRamp() {
        for (long spacing : new long[] {0, 1_000, 20_000, 200_000}) {
            ResumeRamp ramp = new ResumeRamp(DURATION, STEP);
            ramp.start(0);
            double f = writeAt(ramp, 0, every(1_000, spacing, 1000));
            double burst = (1000 - 1) * spacing + 1_000;
            assertTrue(f <= burst / DURATION + 1e-9, "spacing " + spacing + " ns: the burst of " + burst / 1e6
                    + " ms moves the force by " + f);
            assertTrue(ramp.isRunning() || burst >= DURATION, "spacing " + spacing + " ns: still ramping");
        }
    }

    /** A pause in the middle of a ramp (the guard did not act: no torque was on) adds one step at most. */
    @Test
    void aPauseInTheMiddleOfARampAddsOneStepAtMost() {
        for (long pause : new long[] {2 * MS, 6 * MS, 150 * MS, 3_000 * MS}) {
            ResumeRamp ramp = new ResumeRamp(DURATION, STEP);
            ramp.start(0);
            double before = writeAt(ramp, 0, every(MS, MS, 30));
            double after = ramp.factor(30 * MS + pause);
            assertTrue(after - before <= STEP + 1e-12, "pause " + pause / MS + " ms: " + before + " then " + after);
            double burst = writeAt(ramp, 30 * MS + pause, every(10_000, 10_000, 200));   // catching up: 2 ms
            assertTrue(burst - after <= 2.0 * MS / DURATION + 1e-9, "pause " + pause / MS + " ms: the burst after it "
                    + "moves the force by " + (burst - after));
        }
    }

    @Test
    void aRestartBeginsAgainFromZero() {
        ResumeRamp ramp = new ResumeRamp(DURATION, STEP);
        ramp.start(0);
        writeAt(ramp, 0, every(MS, MS, 60));
        ramp.start(70 * MS);
        assertEquals(0.0, ramp.last());
        assertEquals(0.0, ramp.factor(70 * MS), 1e-12, "a write at the restart: zero force");
        assertEquals(0.01, ramp.factor(71 * MS), 1e-9);
    }

    @Test
    void jitteredWritesKeepBothBoundsAndEnd() {
        Random r = new Random(20261129L);
        for (int run = 0; run < 50; run++) {
            ResumeRamp ramp = new ResumeRamp(DURATION, STEP);
            ramp.start(0);
            long[] t = new long[3000];
            long now = 0;
            for (int i = 0; i < t.length; i++) {
                now += r.nextInt(10) == 0 ? r.nextInt(40) * MS : r.nextInt(2_000_000);   // jitter, some pauses
                t[i] = now;
            }
            double f = writeAt(ramp, 0, t);
            assertEquals(1.0, f, 1e-12, "run " + run + ": the ramp ends within " + now / 1e6 + " ms of writes");
        }
    }

    @Test
    void refusesADurationOrStepOutOfRange() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new ResumeRamp(0, STEP));
        assertTrue(e.getMessage().contains("0 ns"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> new ResumeRamp(DURATION, 0));
        assertThrows(IllegalArgumentException.class, () -> new ResumeRamp(DURATION, 1.5));
        assertThrows(IllegalArgumentException.class, () -> new ResumeRamp(DURATION, Double.NaN));
    }
}
