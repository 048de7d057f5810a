package tactus.haptics.loop;

import java.lang.management.GarbageCollectorMXBean;
import java.lang.management.ManagementFactory;
import java.util.concurrent.atomic.AtomicBoolean;

/**
 * Brings a JVM's first young collections forward, to before the haptic loop starts. The first collections of a
 * fresh JVM are slow (the collector touches memory it has not used yet): on this project's machine under load the
 * first took 37-56 ms and the second 6-20 ms, against 1-3 ms later, and each stops the loop for its whole pause. A
 * sketch that makes garbage as it draws runs into them in its first seconds. Made once per JVM, when a loop with
 * real-time scheduling starts: short-lived garbage, until the collectors have counted {@link #COLLECTIONS} more
 * collections, or {@link #MAX_BYTES} were allocated (see docs/haptics.md, "What a sketch's garbage costs the hand").
 *
 * <p>Not API: public only for {@link tactus.haptics.HapticLoop}.
 */
public final class HeapWarmup {
    /** How many collections the warm-up waits for. */
    static final int COLLECTIONS = 3;
    /** The most garbage the warm-up makes, bytes (about 0.1-0.3 s of allocation). */
    static final long MAX_BYTES = 256L << 20;
    private static final int CHUNK = 1024;
    private static final AtomicBoolean DONE = new AtomicBoolean();
    /** Where the garbage goes, so that the allocation cannot be optimised away. */
    private static volatile Object sink;

    private HeapWarmup() {
    }

    /**
     * Makes the warm-up's garbage the first time it is called in this JVM, and does nothing after that.
     *
     * @return the collections counted during this call (0 when it did nothing, -1 if the count is unavailable)
     */
    public static int once() {
        if (!DONE.compareAndSet(false, true)) {
            return 0;
        }
        return run(COLLECTIONS, MAX_BYTES);
    }

    /**
     * Allocates chunks of garbage until {@code collections} more collections were counted or {@code maxBytes}
     * were allocated.
     *
     * @return the collections counted, or -1 if this JVM does not count them (then all {@code maxBytes} are made)
     */
    static int run(int collections, long maxBytes) {
        long before = collectionCount();
        long made = 0;
        while (made < maxBytes) {
            for (int i = 0; i < 1024; i++) {
                sink = new byte[CHUNK];
            }
            made += 1024L * CHUNK;
            if (before >= 0 && collectionCount() - before >= collections) {
                break;
            }
        }
        sink = null;
        return before < 0 ? -1 : (int) (collectionCount() - before);
    }

    /** The collections counted so far by every collector of this JVM, or -1 if none counts. */
    static long collectionCount() {
        try {
            long n = -1;
            for (GarbageCollectorMXBean gc : ManagementFactory.getGarbageCollectorMXBeans()) {
                long c = gc.getCollectionCount();
                if (c >= 0) {
                    n = Math.max(n, 0) + c;
                }
            }
            return n;
        } catch (LinkageError | RuntimeException e) {
            return -1;   // a runtime without java.management
        }
    }
}
