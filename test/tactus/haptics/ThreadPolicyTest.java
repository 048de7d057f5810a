package tactus.haptics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;
import org.junit.jupiter.api.Test;
import tactus.PhysicalModel;
import tactus.Vect3D;
import tactus.haptics.emulator.BoardEmulator;

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

    /** Linux's number for the SCHED_DEADLINE policy. */
    private static final int SCHED_DEADLINE = 6;

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
                expected = loop.scheduling().contains("SCHED_DEADLINE") ? new int[] {SCHED_DEADLINE, 0}
                        : new int[] {1, priority};
                loopThreads++;
            } else if (realtime && HapticLoop.SAFETY_THREADS.matcher(name).matches()) {
                expected = new int[] {1, priority};
            } else if (realtime && loop.scheduling().contains("VM and GC threads")
                    && tactus.scheduling.RealtimeThreads.SAFEPOINT_THREADS.matcher(name).matches()) {
                expected = new int[] {1, priority - 1};
                safepointThreads++;
            } else if (realtime && loop.scheduling().contains("JIT compilers at 1")
                    && tactus.scheduling.RealtimeThreads.COMPILER_THREADS.matcher(name).matches()) {
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
            for (boolean deadline : new boolean[] {true, false}) {
                runAndCheck(mode, deadline);
            }
        }
    }

    /**
     * A thread that the loop thread starts while it runs: under SCHED_FIFO it would inherit the loop's policy, under
     * SCHED_DEADLINE its creation would fail outright without the reset-on-fork flag. Either way it must come out
     * at normal priority, and be created at all.
     */
    @Test
    void aThreadStartedByTheLoopThreadRunsAtNormalPriority() throws Exception {
        for (boolean deadline : new boolean[] {true, false}) {
            BoardEmulator emulator = new BoardEmulator(HaplyPreset.HAPLY_2018);
            Board board = new Board(emulator.connect());
            try {
                Device device = new Device((byte) 3, board);
                HaplyPreset.HAPLY_2018.configure(device);
                device.device_set_parameters();
                ThreadStartingAvatar avatar = new ThreadStartingAvatar();
                HapticLoop loop = new HapticLoop(device, HaplyPreset.HAPLY_2018.newKinematics(), avatar);
                loop.setRealtimePriority(HapticSession.REALTIME_PRIORITY);
                loop.setDeadlineScheduling(deadline);
                loop.start();
                int[] p = avatar.childPolicy.get(10, TimeUnit.SECONDS);
                String sched = loop.scheduling();
                loop.close();
                assertTrue(sched.startsWith("real-time") || sched.startsWith("normal"), sched);
                assertTrue(!deadline || !sched.startsWith("real-time") || sched.contains("SCHED_DEADLINE"),
                        "the deadline policy was asked for: " + sched);
                assertEquals(0, p[0], sched + ": the policy of a thread the loop thread started");
                assertEquals(0, p[1], sched + ": the real-time priority of a thread the loop thread started");
            } finally {
                board.close();
            }
        }
    }

    /** An avatar that, at the loop thread's 50th tick, starts a thread that reports its own scheduling policy. */
    private static final class ThreadStartingAvatar extends NoForceAvatar {
        final CompletableFuture<int[]> childPolicy = new CompletableFuture<>();
        private int ticks;

        @Override
        public void setTarget(double x, double y, double z) {
            if (++ticks == 50) {
                try {
                    Thread child = new Thread(() -> {
                        try {
                            childPolicy.complete(policy(new File("/proc/thread-self")));
                        } catch (IOException | RuntimeException e) {
                            childPolicy.completeExceptionally(e);
                        }
                    }, "policy-child");
                    child.start();
                } catch (Throwable e) {   // under SCHED_DEADLINE without reset-on-fork: "unable to create native thread"
                    childPolicy.completeExceptionally(e);
                }
            }
        }
    }

    private static void runAndCheck(HapticLoop.Mode mode, boolean deadline) throws IOException {
        try (HapticSession s = HapticSession.openEmulated(null, HaplyPreset.HAPLY_2018)) {
            PhysicalModel pm = new PhysicalModel(1000);
            Vect3D home = s.home();
            pm.addHapticInput3D("avatar", home, 5);
            pm.addGround3D("anchor", new Vect3D(home.x + 20, home.y + 10, 0));
            pm.addSpringDamper3D("pull", 0, 0.0005, 0, "avatar", "anchor");   // about 1 N at the handle
            pm.init();
            HapticLoop loop = s.attach(pm, "avatar");
            loop.setMode(mode);
            loop.setDeadlineScheduling(deadline);
            loop.start();
            awaitTicks(loop, 300);
            assertTrue(mode == HapticLoop.Mode.AUDIO || Math.abs(loop.torque(1)) + Math.abs(loop.torque(2)) > 0,
                    "the spring puts torque on the motors");
            checkEveryThread(loop, HapticSession.REALTIME_PRIORITY);
            assertTrue(!deadline || !loop.scheduling().startsWith("real-time")
                    || loop.scheduling().contains("SCHED_DEADLINE"), loop.scheduling());
        }
    }
}
