package tactus.audio;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ddf.minim.AudioOutput;
import ddf.minim.Minim;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import tactus.PhysicalModel;
import tactus.scheduling.RealtimeThreads;

/**
 * The output thread that plays a PhyUGen asks for real-time scheduling (issue 27): Minim's own output thread
 * (behind the virtual output here) and a SilentAudioOut's thread end up SCHED_FIFO at {@link
 * AudioScheduling#DEFAULT_PRIORITY} where the system grants it (this test runs as root in CI), with the VM thread at
 * least one above; where it is refused, the status says why and the thread is left alone. A thread that computes a
 * PhyUGen itself (an offline render) is never changed, and 0 asks for nothing. On the code before issue 27 the output
 * thread stayed at normal priority, which is what let a busy machine empty the line.
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class AudioSchedulingTest {
    @TempDir
    Path dir;
    private final List<AudioOutput> outputs = new ArrayList<>();

    @AfterEach
    void closeOutputsAndRestore() {
        for (AudioOutput o : outputs) {
            o.close();
        }
        AudioScheduling.setRealtimePriority(AudioScheduling.DEFAULT_PRIORITY);
    }

    private static PhyUGen smallString() {
        PhysicalModel pm = new PhysicalModel(44100);
        StringModel.build(pm, 7, 0.001);
        pm.init();
        PhyUGen ugen = new PhyUGen(pm);
        ugen.listenToMass(StringModel.mass(3), SteppedModel.Y, 300, 0);
        return ugen;
    }

    /** {policy, priority} of the live threads named {@code name} (as Linux keeps it, 15 characters). */
    private static List<int[]> policiesOf(String name) {
        String comm = name.length() > 15 ? name.substring(0, 15) : name;
        List<int[]> found = new ArrayList<>();
        for (String tid : RealtimeThreads.threadsNamed(java.util.regex.Pattern.compile(
                java.util.regex.Pattern.quote(comm)))) {
            int[] p = RealtimeThreads.policyOf(tid);
            if (p != null) {
                found.add(p);
            }
        }
        return found;
    }

    private static int[] policyOfCurrentThread() {
        String tid = RealtimeThreads.currentThreadId();
        assertNotNull(tid, "this test runs on Linux");
        return RealtimeThreads.policyOf(tid);
    }

    /** Waits until the status names {@code thread}'s outcome, or the output thread is SCHED_FIFO. */
    private static String awaitStatusFor(Thread thread) throws InterruptedException {
        long deadline = System.nanoTime() + 20_000_000_000L;
        while (System.nanoTime() < deadline) {
            String s = AudioScheduling.status();
            if (s.contains("\"" + thread.getName() + "\"") || s.startsWith("normal priority (real-time refused")) {
                return s;
            }
            Thread.sleep(5);
        }
        return AudioScheduling.status();
    }

    /** Patches a PhyUGen into {@code out} and returns the thread that computes its samples. */
    private Thread play(AudioOutput out) throws InterruptedException {
        outputs.add(out);
        PhyUGen ugen = smallString();
        Thread[] computing = new Thread[1];
        out.addListener(new ddf.minim.AudioListener() {
            @Override
            public void samples(float[] samp) {
                computing[0] = Thread.currentThread();
            }

            @Override
            public void samples(float[] left, float[] right) {
                computing[0] = Thread.currentThread();
            }
        });
        ugen.patch(out);
        long deadline = System.nanoTime() + 20_000_000_000L;
        while (computing[0] == null && System.nanoTime() < deadline) {
            Thread.sleep(5);
        }
        assertNotNull(computing[0], "the output computed a block");
        return computing[0];
    }

    private static void checkScheduled(Thread output, String status) {
        List<int[]> p = policiesOf(output.getName());
        assertEquals(1, p.size(), "one live thread named " + output.getName());
        if (status.startsWith("real-time")) {
            assertEquals(1, p.get(0)[0], "SCHED_FIFO for the output thread; " + status);
            assertEquals(AudioScheduling.DEFAULT_PRIORITY, p.get(0)[1], status);
            for (int[] vm : policiesOf("VM Thread")) {
                assertTrue(vm[0] == 1 && vm[1] > AudioScheduling.DEFAULT_PRIORITY,
                        "the VM thread runs above the audio thread: policy " + vm[0] + " priority " + vm[1]);
            }
        } else {
            assertTrue(status.startsWith("normal priority (real-time refused: "), status);
            assertEquals(0, p.get(0)[0], "a refused request leaves the thread alone; " + status);
        }
        // the helper and the thread that patched stay at normal priority (nothing inherited a real-time policy)
        for (int[] h : policiesOf("Tactus audio helper")) {
            assertEquals(0, h[0], "the scheduling helper stays at normal priority");
        }
        assertEquals(0, policyOfCurrentThread()[0], "the test thread stays at normal priority");
    }

    @Test
    void minimsOutputThreadIsMovedToRealTimeWhereAllowed() throws Exception {
        Minim minim = new Minim(new HeadlessLineOutTest.Files(dir.toFile()));
        try {
            AudioOutput out = LineOut.open(minim, Minim.MONO, 256, 44100f);
            Thread output = play(out);
            assertTrue(AudioScheduling.isOutputThread(output), "Minim's output thread: " + output.getClass());
            checkScheduled(output, awaitStatusFor(output));
        } finally {
            minim.stop();
        }
    }

    @Test
    void aSilentOutputsThreadIsMovedToRealTimeWhereAllowed() throws Exception {
        Thread output = play(LineOut.silent(Minim.STEREO, 256, 44100f, null));
        assertTrue(output instanceof SilentAudioOut.OutputThread, "the silent output's thread: " + output);
        checkScheduled(output, awaitStatusFor(output));
    }

    @Test
    void zeroAsksForNothing() throws Exception {
        AudioScheduling.setRealtimePriority(0);
        String before = AudioScheduling.status();
        Thread output = play(LineOut.silent(Minim.MONO, 256, 44100f, null));
        Thread.sleep(300);   // time enough for a request, if one had been made
        List<int[]> p = policiesOf(output.getName());
        assertEquals(1, p.size());
        assertEquals(0, p.get(0)[0], "no request with priority 0");
        assertEquals(before, AudioScheduling.status(), "the status speaks of no new thread");
    }

    @Test
    void anOfflineRenderNeverChangesTheCallingThread() throws Exception {
        PhyUGen ugen = smallString();
        float[][] out = OfflineRenderer.renderToArray(ugen, 44100f, 1, 0.2);
        assertEquals(8820, out[0].length, "rendered 0.2 s");
        Thread.sleep(200);
        assertTrue(!AudioScheduling.status().contains("\"" + Thread.currentThread().getName() + "\""),
                AudioScheduling.status());
        assertEquals(0, policyOfCurrentThread()[0], "the sketch's thread that rendered stays at normal priority");
        assertTrue(!AudioScheduling.isOutputThread(Thread.currentThread()));
    }

    @Test
    void prioritiesOutOfRangeAreRefused() {
        assertThrows(IllegalArgumentException.class, () -> AudioScheduling.setRealtimePriority(-1));
        assertThrows(IllegalArgumentException.class, () -> AudioScheduling.setRealtimePriority(100));
        assertThrows(IllegalArgumentException.class, () -> RealtimeThreads.applyToThread("12a", java.util.Map.of(), 10));
        assertThrows(IllegalArgumentException.class, () -> RealtimeThreads.applyToThread("1", java.util.Map.of(), 0));
        assertEquals(AudioScheduling.DEFAULT_PRIORITY, AudioScheduling.realtimePriority(), "unchanged by a refusal");
    }
}
