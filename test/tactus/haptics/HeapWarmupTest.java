package tactus.haptics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * The heap warm-up that a real-time haptic loop makes at its first start: it must really bring collections about
 * (counted by the JVM's own collectors, for several counts asked for), stop as soon as they happened rather than make
 * all of its garbage, and run only once per JVM.
 */
class HeapWarmupTest {

    @Test
    void theWarmupMakesGarbageUntilTheCollectorsHaveRunAsOftenAsAsked() {
        assertTrue(HeapWarmup.collectionCount() >= 0, "this JVM counts its collections");
        for (int asked = 1; asked <= 3; asked++) {
            long before = HeapWarmup.collectionCount();
            int counted = HeapWarmup.run(asked, 4L << 30);
            long after = HeapWarmup.collectionCount();
            assertTrue(counted >= asked, "asked for " + asked + " collections, counted " + counted);
            assertTrue(after - before >= asked, "the collectors counted " + (after - before));
            // it stops at the collection it waited for: far fewer than the 4 GiB it was allowed would cause
            assertTrue(counted <= asked + 2, "asked for " + asked + ", went on to " + counted);
        }
    }

    @Test
    void theWarmupStopsAtItsByteLimitAndRunsOncePerJvm() {
        // a million collections asked for, 1 MB allowed: it returns at the limit (one collection at most, if the
        // young generation happened to be nearly full)
        int counted = HeapWarmup.run(1_000_000, 1L << 20);
        assertTrue(counted >= 0 && counted <= 1, "1 MB of garbage brought " + counted + " collections about");
        HeapWarmup.once();
        assertEquals(0, HeapWarmup.once(), "the second call does nothing");
    }
}
