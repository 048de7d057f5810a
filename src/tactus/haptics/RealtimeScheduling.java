package tactus.haptics;

import java.io.File;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;
import java.util.regex.Pattern;

/**
 * Asks Linux to run threads under the real-time policy SCHED_FIFO, through the {@code chrt} program of util-linux
 * (Java has no call for it). Used once, before the first tick, by the haptic loop when
 * {@link HapticLoop#setRealtimePriority(int)} asks for it: for the loop thread itself, its safety threads, and the
 * JVM's threads that a Java thread can end up waiting for (the VM thread and the collector's pause workers one step
 * below the loop, the JIT compilers at the lowest real-time priority), so that another program loading the machine
 * cannot hold them, and through them the loop, up (see docs/haptics.md, "Why the loop was late"). It works where
 * the user may raise priorities (root, {@code CAP_SYS_NICE}, or an {@code rtprio} limit in
 * {@code /etc/security/limits.conf}, as audio users often have); elsewhere, and on other systems, it changes
 * nothing and says why.
 */
final class RealtimeScheduling {
    private static final long CHRT_TIMEOUT_MS = 2000;
    /**
     * The JVM threads that every safepoint waits for: HotSpot's VM thread, which runs the safepoint's operation,
     * and the workers of a stop-the-world collection (G1, Parallel and Serial name them "GC Thread#n"). The
     * collectors' concurrent threads are left alone: they run beside the application and must not starve it.
     */
    static final Pattern SAFEPOINT_THREADS = Pattern.compile("VM Thread|GC Thread#\\d+");
    /**
     * HotSpot's JIT compiler threads ("C1 CompilerThread0", "C2 CompilerThread0", ... as Linux keeps their names,
     * cut to 15 characters). A thread that runs code the JIT is about to compile, or whose counters ask for a
     * compilation, takes locks that these threads hold while they work; at normal priority on a loaded machine they
     * were preempted holding them and held a real-time tick up by up to 126 ms.
     */
    static final Pattern COMPILER_THREADS = Pattern.compile("C[12] CompilerThre");

    private RealtimeScheduling() {
    }

    /**
     * Moves the threads of this process whose names match each pattern to SCHED_FIFO at that pattern's priority,
     * then the calling thread to its own policy, in one run of a shell (one process start instead of one per
     * thread: under load each start took tens of milliseconds). A thread that ends meanwhile is skipped. For the
     * calling thread it asks first for SCHED_DEADLINE
     * ({@code runtimeNanos} of CPU time in every {@code periodNanos}, deadline = period, with reset-on-fork so that
     * a thread it starts runs at normal priority), and falls back to SCHED_FIFO at {@code priority} where that is
     * refused (an older kernel or chrt, the JVM pinned to some of the CPUs, or the system's deadline bandwidth
     * taken). A SCHED_DEADLINE thread runs ahead of every SCHED_FIFO thread and of the kernel's "fair server": the
     * reservation of 50 ms a second that Linux (6.12 and later, and RT throttling before it) gives normal threads
     * starved by real-time ones, which otherwise stops a SCHED_FIFO thread for up to 50 ms (see docs/haptics.md).
     *
     * @param others patterns of thread names and their SCHED_FIFO priorities (1..99), applied in order
     * @param priority the calling thread's SCHED_FIFO priority (also with reset-on-fork) if the deadline policy is
     *        refused, 1..99
     * @param runtimeNanos the CPU time reserved per period, ns; 0 to ask for SCHED_FIFO only
     * @param periodNanos the period and relative deadline, ns (at least {@code runtimeNanos})
     * @return what was granted, or why nothing was
     */
    static Grant applyWithCurrentThread(Map<Pattern, Integer> others, int priority, long runtimeNanos,
            long periodNanos) {
        String why = linuxOnly();
        if (why != null) {
            return Grant.refused(why);
        }
        String self;
        try {
            self = Files.readSymbolicLink(Paths.get("/proc/thread-self")).getFileName().toString();
        } catch (IOException | UnsupportedOperationException e) {
            return Grant.refused("cannot find the thread id (" + e.getMessage() + ")");
        }
        // The shell waits for a line on its input before it changes anything: the JDK starts the thread that reaps
        // the process (a thread this one creates, and which inherits its policy) only after the process started,
        // so this thread must still be at normal priority then.
        StringBuilder script = new StringBuilder("read go; ");
        for (Map.Entry<Pattern, Integer> e : others.entrySet()) {
            for (String tid : threadsNamed(e.getKey())) {
                if (!tid.equals(self)) {
                    script.append("chrt -f -p ").append(e.getValue()).append(' ').append(tid).append(" 2>/dev/null; ");
                }
            }
        }
        if (runtimeNanos > 0) {
            script.append("chrt -R -d --sched-runtime ").append(runtimeNanos).append(" --sched-deadline ")
                    .append(periodNanos).append(" --sched-period ").append(periodNanos).append(" -p 0 ").append(self)
                    .append(" 2>/dev/null && exit ").append(DEADLINE_GRANTED).append("; ");
        }
        // reset-on-fork: a thread that the calling thread starts later runs at normal priority, not at its policy
        script.append("chrt -R -f -p ").append(priority).append(' ').append(self);   // its status is the script's
        int exit = run(new ProcessBuilder("sh", "-c", script.toString()));
        if (exit == DEADLINE_GRANTED && runtimeNanos > 0) {
            return Grant.DEADLINE;
        }
        if (exit == 0) {
            return Grant.FIFO;
        }
        return Grant.refused(exit == NO_ANSWER ? "chrt did not answer within " + CHRT_TIMEOUT_MS + " ms"
                : exit == NOT_FOUND ? "chrt (util-linux) not found"
                : exit == INTERRUPTED ? "interrupted while asking for real-time scheduling"
                : "chrt refused (exit " + exit + "): the user may not raise priorities (needs root, "
                        + "CAP_SYS_NICE or an rtprio limit)");
    }

    /** What {@link #applyWithCurrentThread(Map, int, long, long)} obtained for the calling thread. */
    static final class Grant {
        /** SCHED_DEADLINE was granted. */
        static final Grant DEADLINE = new Grant(null, true);
        /** SCHED_FIFO was granted (the deadline policy was refused or not asked for). */
        static final Grant FIFO = new Grant(null, false);
        /** Why nothing was granted, or null. */
        final String why;
        /** True when the calling thread runs under SCHED_DEADLINE. */
        final boolean deadline;

        private Grant(String why, boolean deadline) {
            this.why = why;
            this.deadline = deadline;
        }

        static Grant refused(String why) {
            return new Grant(why, false);
        }

        /** True when the calling thread got a real-time policy. */
        boolean granted() {
            return why == null;
        }
    }

    /**
     * Waits until a thread of this process whose name matches shows up in {@code /proc/self/task} (a new thread
     * names itself as it starts, after {@code Thread.start()} has returned), at most {@code maxMillis}.
     *
     * @return true if one showed up
     */
    static boolean awaitThreadNamed(Pattern name, long maxMillis) {
        long end = System.nanoTime() + maxMillis * 1_000_000L;
        while (threadsNamed(name).isEmpty()) {
            if (System.nanoTime() > end) {
                return false;
            }
            LockSupport.parkNanos(1_000_000L);
        }
        return true;
    }

    /** The ids of this process's threads whose name (as Linux keeps it, 15 characters) matches. */
    static List<String> threadsNamed(Pattern name) {
        List<String> tids = new ArrayList<>();
        File[] tasks = new File("/proc/self/task").listFiles();
        for (File t : tasks == null ? new File[0] : tasks) {
            try {
                String comm = new String(Files.readAllBytes(new File(t, "comm").toPath()), StandardCharsets.UTF_8)
                        .trim();
                if (name.matcher(comm).matches()) {
                    tids.add(t.getName());
                }
            } catch (IOException e) {
                // the thread ended meanwhile
            }
        }
        return tids;
    }

    private static String linuxOnly() {
        if (!System.getProperty("os.name", "").toLowerCase(Locale.ROOT).contains("linux")
                || !Files.exists(Paths.get("/proc/thread-self"))) {
            return "real-time scheduling is only requested on Linux";
        }
        return null;
    }

    private static final int DEADLINE_GRANTED = 10;
    private static final int NO_ANSWER = -1;
    private static final int NOT_FOUND = -2;
    private static final int INTERRUPTED = -3;

    /** Runs a shell of chrt calls, bounded in time, and writes its go line; its exit status, or a negative code. */
    private static int run(ProcessBuilder pb) {
        pb.redirectErrorStream(true);
        pb.redirectOutput(ProcessBuilder.Redirect.DISCARD);
        try {
            Process p = pb.start();
            try (OutputStream in = p.getOutputStream()) {
                in.write('\n');
            }
            if (!p.waitFor(CHRT_TIMEOUT_MS, TimeUnit.MILLISECONDS)) {
                p.destroyForcibly();
                return NO_ANSWER;
            }
            return p.exitValue();
        } catch (IOException e) {
            return NOT_FOUND;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return INTERRUPTED;
        }
    }
}
