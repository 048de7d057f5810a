package tactus.haptics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.locks.LockSupport;
import org.junit.jupiter.api.Test;
import tactus.PhysicalModel;
import tactus.Vect3D;

/**
 * On Linux a thread inherits its creator's scheduling policy, so every thread that the real-time haptic loop thread
 * starts would run at real-time priority too. While a session's loop runs (a spring pulls the avatar, so the
 * motors get torque and the board's torque watchdog is busy), every thread of this JVM is listed with its policy:
 * only the loop thread and the threads that zero the motors when it stalls (its watchdog, the board's torque
 * watchdog) may be SCHED_FIFO at the session's priority, the VM and collector pause threads one below it, and the
 * JIT compiler threads at 1; every other thread must be at normal priority. It failed on the code before this
 * change (the board's torque watchdog, started by the loop thread at the first torque, inherited SCHED_FIFO 50),
 * and caught the JDK's process reaper thread inheriting it when the loop thread was moved before the reaper
 * was started.
 */
class ThreadPolicyTest {

    private static String comm(File task) throws IOException {
        return new String(Files.readAllBytes(new File(task, "comm").toPath()), StandardCharsets.UTF_8).trim();
    }

    /** {policy, rt priority} of a thread, from /proc/self/task/TID/stat. */
    private static int[] policy(File task) throws IOException {
        String s = new String(Files.readAllBytes(new File(task, "stat").toPath()), StandardCharsets.UTF_8);
        String[] f = s.substring(s.lastIndexOf(')') + 2).split(" ");
        return new int[] {Integer.parseInt(f[38]), Integer.parseInt(f[37])};
    }

    private static void checkEveryThread(HapticLoop loop, int priority) throws IOException {
        boolean realtime = loop.scheduling().startsWith("real-time");
        List<String> wrong = new ArrayList<>();
        int loopThreads = 0;
        int safepointThreads = 0;
        int compilerThreads = 0;
        File[] tasks = new File("/proc/self/task").listFiles();
        assertTrue(tasks != null && tasks.length > 5, "the threads of this JVM are listed in /proc/self/task");
        for (File t : tasks) {
            String name;
            int[] p;
            try {
                name = comm(t);
                p = policy(t);
            } catch (IOException | RuntimeException e) {
                continue;                               // the thread ended while we looked
            }
            int[] expected = {0, 0};
            if (realtime && name.equals("tactus-haptic-l")) {
                expected = new int[] {1, priority};
                loopThreads++;
            } else if (realtime && HapticLoop.SAFETY_THREADS.matcher(name).matches()) {
                expected = new int[] {1, priority};
            } else if (realtime && loop.scheduling().contains("VM and GC threads")
                    && RealtimeScheduling.SAFEPOINT_THREADS.matcher(name).matches()) {
                expected = new int[] {1, priority - 1};
                safepointThreads++;
            } else if (realtime && loop.scheduling().contains("JIT compilers at 1")
                    && RealtimeScheduling.COMPILER_THREADS.matcher(name).matches()) {
                expected = new int[] {1, 1};
                compilerThreads++;
            }
            if (p[0] != expected[0] || p[1] != expected[1]) {
                wrong.add(name + " (tid " + t.getName() + ") policy " + p[0] + " priority " + p[1] + ", expected "
                        + expected[0] + "/" + expected[1]);
            }
        }
        assertTrue(wrong.isEmpty(), loop.scheduling() + ": threads with the wrong scheduling: " + wrong);
        if (realtime) {
            assertEquals(1, loopThreads, "one real-time loop thread");
            assertTrue(safepointThreads >= 2, "the VM thread and at least one collector thread: " + safepointThreads);
            assertTrue(compilerThreads >= 1, "at least one JIT compiler thread: " + compilerThreads);
        }
    }

    private static void awaitTicks(HapticLoop loop, long n) {
        long deadline = System.nanoTime() + 20_000_000_000L;
        while (loop.ticks() < n && loop.isRunning() && System.nanoTime() < deadline) {
            LockSupport.parkNanos(2_000_000);
        }
        assertTrue(loop.ticks() >= n, "the loop ticked " + loop.ticks() + " times; failure " + loop.failure());
    }

    @Test
    void onlyTheLoopAndTheSafepointThreadsRunAtRealTimePriority() throws IOException {
        for (HapticLoop.Mode mode : HapticLoop.Mode.values()) {
            try (HapticSession s = HapticSession.openEmulated(null, HaplyPreset.HAPLY_2018)) {
                PhysicalModel pm = new PhysicalModel(1000);
                Vect3D home = s.home();
                pm.addHapticInput3D("avatar", home, 5);
                pm.addGround3D("anchor", new Vect3D(home.x + 20, home.y + 10, 0));
                pm.addSpringDamper3D("pull", 0, 0.0005, 0, "avatar", "anchor");   // about 1 N at the handle
                pm.init();
                HapticLoop loop = s.attach(pm, "avatar");
                loop.setMode(mode);
                loop.start();
                awaitTicks(loop, 300);
                assertTrue(mode == HapticLoop.Mode.AUDIO || Math.abs(loop.torque(1)) + Math.abs(loop.torque(2)) > 0,
                        "the spring puts torque on the motors");
                checkEveryThread(loop, HapticSession.REALTIME_PRIORITY);
            }
        }
    }
}
