package tactus.haptics.loop;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.nio.charset.StandardCharsets;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

/**
 * The heap warm-up that a real-time haptic loop makes at its first start: it must really bring collections about
 * (counted by the JVM's own collectors, for several counts asked for), stop as soon as they happened rather than make
 * all of its garbage, stop at its byte limit, and run only once per JVM. It runs in a fresh child JVM with a small
 * heap, as the warm-up is meant for a fresh JVM: in this test JVM, after hundreds of tests, the young generation may
 * have grown to gigabytes (a run here once counted 2 collections in 4 GiB of garbage).
 */
class HeapWarmupTest {

    /** The child: prints "counts a b c limit once1 once2" and exits. */
    public static void main(String[] args) {
        StringBuilder out = new StringBuilder("counts");
        for (int asked = 1; asked <= 3; asked++) {
            long before = HeapWarmup.collectionCount();
            int counted = HeapWarmup.run(asked, 4L << 30);
            out.append(' ').append(counted).append('/').append(HeapWarmup.collectionCount() - before);
        }
        // a million collections asked for, 1 MB allowed: it returns at the limit
        out.append(' ').append(HeapWarmup.run(1_000_000, 1L << 20));
        out.append(' ').append(HeapWarmup.once()).append(' ').append(HeapWarmup.once());
        System.out.println(out);
    }

    @Test
    void theWarmupMakesGarbageUntilTheCollectorsHaveRunAsOftenAsAskedAndRunsOnce() throws Exception {
        String java = System.getProperty("java.home") + File.separator + "bin" + File.separator + "java";
        Process p = new ProcessBuilder(java, "-Xmx64m", "-XX:+UseG1GC", "-cp", System.getProperty("java.class.path"),
                HeapWarmupTest.class.getName()).redirectErrorStream(true).start();
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), "the child ends within 60 s");
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8).trim();
        assertEquals(0, p.exitValue(), out);
        String[] f = out.substring(out.lastIndexOf("counts")).split("\\s+");
        for (int asked = 1; asked <= 3; asked++) {
            String[] c = f[asked].split("/");
            int counted = Integer.parseInt(c[0]);
            long seen = Long.parseLong(c[1]);
            assertTrue(counted >= asked, "asked for " + asked + " collections, counted " + counted + ": " + out);
            assertTrue(seen >= counted, "the collectors counted " + seen + ": " + out);
            // it stops at the collection it waited for, far before the 4 GiB it was allowed
            assertTrue(counted <= asked + 2, "asked for " + asked + ", went on to " + counted + ": " + out);
        }
        int atLimit = Integer.parseInt(f[4]);
        assertTrue(atLimit >= 0 && atLimit <= 1, "1 MB of garbage brought " + atLimit + " collections about: " + out);
        assertTrue(Integer.parseInt(f[5]) >= HeapWarmup.COLLECTIONS, "the first once() warms up: " + out);
        assertEquals("0", f[6], "the second once() does nothing: " + out);
    }
}
