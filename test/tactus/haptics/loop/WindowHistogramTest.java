package tactus.haptics.loop;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/** The telemetry's sliding histogram against sorted copies of the same window. */
class WindowHistogramTest {

    @Test
    void everyBucketHoldsItsLowerEdgeAndIsAtMostOneSixtyFourthWide() {
        for (int b = 0; b < 3000; b++) {
            long lo = WindowHistogram.lowerEdge(b);
            long next = WindowHistogram.lowerEdge(b + 1);
            assertEquals(b, WindowHistogram.bucketOf(lo), "bucket " + b + " lower edge " + lo);
            assertEquals(b, WindowHistogram.bucketOf(next - 1), "bucket " + b + " upper end " + (next - 1));
            assertTrue(next > lo);
            assertTrue(next - lo <= Math.max(1, lo / 64), "bucket " + b + " is " + (next - lo) + " ns wide at " + lo);
        }
        assertEquals(0, WindowHistogram.bucketOf(-5));
        assertTrue(WindowHistogram.lowerEdge(WindowHistogram.bucketOf(Long.MAX_VALUE)) <= Long.MAX_VALUE);
    }

    @Test
    void percentilesMatchASortedCopyOfTheWindowWithinABucket() {
        SplittableRandom r = new SplittableRandom(7);
        for (int window : new int[] {1, 8, 1024, 1 << 16}) {
            WindowHistogram h = new WindowHistogram(window);
            long[] all = new long[3 * window + 17];
            for (int i = 0; i < all.length; i++) {
                // mostly small jitter, a few long stalls, as a haptic loop has them
                all[i] = r.nextInt(100) == 0 ? r.nextLong(1_000_000, 80_000_000) : r.nextLong(0, 50_000);
                h.record(all[i]);
                if (i % (window / 2 + 1) == 0 || i == all.length - 1) {
                    int n = Math.min(i + 1, window);
                    long[] last = Arrays.copyOfRange(all, i + 1 - n, i + 1);
                    Arrays.sort(last);
                    assertEquals(n, h.size());
                    for (double q : new double[] {0, 0.5, 0.9, 0.99, 1}) {
                        long exact = last[(int) Math.max(0, Math.ceil(q * n) - 1)];
                        long got = h.percentile(q);
                        assertTrue(got <= exact && exact - got <= Math.max(0, exact / 64),
                                "window " + window + " after " + (i + 1) + " samples, q " + q + ": " + got
                                        + " for " + exact);
                    }
                }
            }
        }
    }

    @Test
    void anEmptyWindowReadsZeroAndOnlyPowersOfTwoAreWindows() {
        assertEquals(0, new WindowHistogram(4).percentile(0.99));
        assertThrows(IllegalArgumentException.class, () -> new WindowHistogram(0));
        assertThrows(IllegalArgumentException.class, () -> new WindowHistogram(1000));
    }
}
