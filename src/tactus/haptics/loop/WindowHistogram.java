package tactus.haptics.loop;

/**
 * A histogram of the last {@code window} durations (nanoseconds) recorded by one writer thread, from which any
 * thread reads percentiles without copying the window.
 *
 * <p>Buckets are log-linear: exact below 64 ns, then 64 buckets per power of two, so a bucket's width is at most
 * 1/64 (1.6 %) of its lower edge. The writer keeps the bucket of each sample in a ring so that the sample leaving
 * the window is taken out of its bucket when a new one comes in. {@link #record(long)} allocates nothing and takes
 * no lock; {@link #percentile(double)} scans the counts (about 2,300 of them). A reader that runs beside the
 * writer sees counts that may be off by the few samples recorded during its scan: these are statistics, not
 * state.
 *
 * <p>Not API: public only for {@link tactus.haptics.HapticLoop}.
 */
public final class WindowHistogram {
    private static final int SUB_BITS = 6;
    private static final int SUB = 1 << SUB_BITS;
    /** Enough buckets for any non-negative long. */
    private static final int BUCKETS = (64 - SUB_BITS + 1) * SUB;

    private final int[] counts = new int[BUCKETS];
    private final short[] ring;
    private final int mask;
    private volatile long recorded;

    /**
     * Creates a histogram of the most recent samples.
     *
     * @param window the number of most recent samples kept (a power of two, at most 2^30)
     */
    public WindowHistogram(int window) {
        if (window <= 0 || Integer.bitCount(window) != 1 || window > (1 << 30)) {
            throw new IllegalArgumentException("WindowHistogram: window must be a power of two, got " + window);
        }
        ring = new short[window];
        mask = window - 1;
    }

    /** The bucket of a duration (negative durations count as 0). */
    static int bucketOf(long nanos) {
        long v = Math.max(0, nanos);
        if (v < SUB) {
            return (int) v;
        }
        int e = 63 - Long.numberOfLeadingZeros(v);          // floor(log2 v) >= SUB_BITS
        int sub = (int) (v >>> (e - SUB_BITS)) & (SUB - 1);
        return (e - SUB_BITS + 1) * SUB + sub;
    }

    /** The smallest duration that falls in a bucket, in nanoseconds. */
    static long lowerEdge(int bucket) {
        if (bucket < SUB) {
            return bucket;
        }
        int e = bucket / SUB - 1 + SUB_BITS;
        long sub = bucket & (SUB - 1);
        return (SUB + sub) << (e - SUB_BITS);
    }

    /** Records one duration (writer thread only). */
    public void record(long nanos) {
        long n = recorded;
        int slot = (int) (n & mask);
        if (n > mask) {
            counts[ring[slot] & 0xFFFF]--;
        }
        int b = bucketOf(nanos);
        ring[slot] = (short) b;
        counts[b]++;
        recorded = n + 1;
    }

    /** The number of samples in the window (at most the window's size). */
    int size() {
        return (int) Math.min(recorded, mask + 1L);
    }

    /**
     * The q-quantile of the samples in the window, as the lower edge of its bucket, in nanoseconds (0 when the
     * window is empty). {@code q} in [0, 1]; the rank is ceil(q n), as for a sorted copy of the window.
     */
    public long percentile(double q) {
        int n = size();
        if (n == 0) {
            return 0;
        }
        long rank = Math.max(1, (long) Math.ceil(q * n));
        long seen = 0;
        for (int b = 0; b < BUCKETS; b++) {
            seen += Math.max(0, counts[b]);
            if (seen >= rank) {
                return lowerEdge(b);
            }
        }
        return lowerEdge(BUCKETS - 1);
    }
}
