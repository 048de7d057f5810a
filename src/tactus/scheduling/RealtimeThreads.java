package tactus.scheduling;

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
 * Asks Linux to run threads of this JVM under the real-time policy SCHED_FIFO, through the {@code chrt} program of
 * util-linux (Java has no call for it), for a thread and the JVM's threads that a Java thread can end up waiting for
 * (the VM thread and the collector's pause workers, the JIT compilers; see docs/haptics.md, "Why the loop was
 * late"). The audio side uses it for the output thread that plays a {@code PhyUGen} (docs/audio.md, "Audio under
 * load") and the haptic loop for its own thread, which it asks for SCHED_DEADLINE first (docs/haptics.md, "A fifth
 * wait, in the kernel"). It works where the user may raise priorities (root,
 * {@code CAP_SYS_NICE}, or an {@code rtprio} limit in {@code /etc/security/limits.conf}, as audio users often have);
 * elsewhere, and on other systems, it changes nothing and says why. Every call starts one short shell process: call
 * it once per thread, never from a thread that must not wait (an audio or haptic tick).
 */
public final class RealtimeThreads {
    private static final long CHRT_TIMEOUT_MS = 5000;
    /** One request at a time: a request that only raises threads must see the previous request's result. */
    private static final Object REQUESTS = new Object();
    private static final Pattern THREAD_ID = Pattern.compile("\\d+");
    /** Linux's number for the SCHED_DEADLINE policy. */
    private static final int SCHED_DEADLINE = 6;
    private static final int DEADLINE_GRANTED = 10;
    private static final int NO_ANSWER = -1;
    private static final int NOT_FOUND = -2;
    private static final int INTERRUPTED = -3;
    /**
     * The JVM threads that every safepoint waits for: HotSpot's VM thread, which runs the safepoint's operation,
     * and the workers of a stop-the-world collection (G1, Parallel and Serial name them "GC Thread#n"). The
     * collectors' concurrent threads are left alone: they run beside the application and must not starve it.
     */
    public static final Pattern SAFEPOINT_THREADS = Pattern.compile("VM Thread|GC Thread#\\d+");
    /**
     * HotSpot's JIT compiler threads ("C1 CompilerThread0", "C2 CompilerThread0", ... as Linux keeps their names,
     * cut to 15 characters). A thread that runs code the JIT is about to compile, or whose counters ask for a
     * compilation, takes locks that these threads hold while they work; at normal priority on a loaded machine they
     * were preempted holding them and held a real-time tick up by up to 126 ms.
     */
    public static final Pattern COMPILER_THREADS = Pattern.compile("C[12] CompilerThre");

    private RealtimeThreads() {
    }

    /**
     * Moves the threads of this process whose names match each pattern to SCHED_FIFO at that pattern's priority,
     * then the calling thread to SCHED_FIFO at {@code priority} with reset-on-fork (a thread it starts later runs
     * at normal priority), in one run of a shell (one process start instead of one per thread: under load each start
     * took tens of milliseconds). A thread that ends meanwhile is skipped.
     *
     * @param others patterns of thread names and their priorities (1..99), applied in order
     * @param priority the calling thread's priority, 1..99
     * @return null if the calling thread got its priority, otherwise why not (one short sentence)
     */
    public static String applyWithCurrentThread(Map<Pattern, Integer> others, int priority) {
        return applyWithCurrentThread(others, priority, 0, 0).why;
    }

    /**
     * As {@link #applyWithCurrentThread(Map, int)}, but asks first for SCHED_DEADLINE for the calling thread
     * ({@code runtimeNanos} of CPU time in every {@code periodNanos}, the period as its deadline, with reset-on-fork)
     * and falls back to SCHED_FIFO at {@code priority} where that is refused (an older kernel or chrt, the JVM pinned
     * to some of the CPUs, or the system's deadline bandwidth taken). A SCHED_DEADLINE thread runs ahead of every
     * SCHED_FIFO thread and of the kernel's "fair server": the 50 ms a second that Linux (6.12 and later, and RT
     * throttling before it) gives normal threads starved by real-time ones, which otherwise stops a SCHED_FIFO thread
     * for up to 50 ms (see docs/haptics.md).
     *
     * @param others patterns of thread names and their SCHED_FIFO priorities (1..99), applied in order
     * @param priority the calling thread's SCHED_FIFO priority if the deadline policy is refused, 1..99
     * @param runtimeNanos the CPU time reserved per period, ns; 0 to ask for SCHED_FIFO only
     * @param periodNanos the period and relative deadline, ns (at least {@code runtimeNanos} when that is not 0)
     * @return what was granted, or why nothing was
     */
    public static Grant applyWithCurrentThread(Map<Pattern, Integer> others, int priority, long runtimeNanos,
            long periodNanos) {
        checkPriorities(others, priority);
        if (runtimeNanos < 0 || (runtimeNanos > 0 && periodNanos < runtimeNanos)) {
            throw new IllegalArgumentException("RealtimeThreads: a deadline reservation needs 0 < runtime <= period, "
                    + "got " + runtimeNanos + " ns of " + periodNanos + " ns");
        }
        String why = linuxOnly();
        if (why != null) {
            return new Grant(why, false);
        }
        String self = currentThreadId();
        if (self == null) {
            return new Grant("cannot find the thread id", false);
        }
        int exit;
        synchronized (REQUESTS) {
            exit = run(new ProcessBuilder("sh", "-c",
                    scriptWithCurrentThread(self, others, priority, runtimeNanos, periodNanos)));
        }
        if (exit == DEADLINE_GRANTED && runtimeNanos > 0) {
            return new Grant(null, true);
        }
        return new Grant(exit == 0 ? null : refusal(exit), false);
    }

    private static String scriptWithCurrentThread(String self, Map<Pattern, Integer> others, int priority,
            long runtimeNanos, long periodNanos) {
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
        return script.append("chrt -R -f -p ").append(priority).append(' ').append(self).toString();   // its status
    }

    /** What {@link #applyWithCurrentThread(Map, int, long, long)} obtained for the calling thread. */
    public static final class Grant {
        /** Why nothing was granted (one short sentence), or null when a real-time policy was. */
        public final String why;
        /** True when the calling thread runs under SCHED_DEADLINE; false under SCHED_FIFO or when refused. */
        public final boolean deadline;

        Grant(String why, boolean deadline) {
            this.why = why;
            this.deadline = deadline;
        }

        /** {@return true when the calling thread got a real-time policy} */
        public boolean granted() {
            return why == null;
        }
    }

    /**
     * Waits until a thread of this process whose name matches shows up in {@code /proc/self/task} (a new thread
     * names itself as it starts, after {@code Thread.start()} has returned), at most {@code maxMillis}.
     *
     * @param name the pattern of the thread's name, as Linux keeps it (15 characters)
     * @param maxMillis the longest wait, ms
     * @return true if one showed up
     */
    public static boolean awaitThreadNamed(Pattern name, long maxMillis) {
        long end = System.nanoTime() + maxMillis * 1_000_000L;
        while (threadsNamed(name).isEmpty()) {
            if (System.nanoTime() > end) {
                return false;
            }
            LockSupport.parkNanos(1_000_000L);
        }
        return true;
    }

    /**
     * Moves another thread of this process (named by its Linux thread id, see {@link #currentThreadId()}) to
     * SCHED_FIFO at {@code priority}, and raises the threads whose names match each pattern to at least that
     * pattern's priority: a thread already real-time at that priority or above (set by the haptic loop, say) is
     * left as it is, so that two users of this class never lower each other's threads. One run of a shell, from the
     * calling thread, which stays as it is.
     *
     * @param threadId the Linux id of the thread to move (digits, a thread of this process)
     * @param others patterns of thread names and their lowest priorities (1..99)
     * @param priority the thread's priority, 1..99
     * @return null if the thread got its priority, otherwise why not (one short sentence)
     */
    public static String applyToThread(String threadId, Map<Pattern, Integer> others, int priority) {
        checkPriorities(others, priority);
        if (threadId == null || !THREAD_ID.matcher(threadId).matches()) {
            throw new IllegalArgumentException("RealtimeThreads.applyToThread: the thread id must be digits, got "
                    + threadId);
        }
        String why = linuxOnly();
        if (why != null) {
            return why;
        }
        if (!new File("/proc/self/task/" + threadId).isDirectory()) {
            return "thread " + threadId + " is not a thread of this process (it may have ended)";
        }
        synchronized (REQUESTS) {   // after any earlier request, so that "already at or above" is up to date
            int exit = run(new ProcessBuilder("sh", "-c", scriptRaising(threadId, others, priority)));
            return exit == 0 ? null : refusal(exit);
        }
    }

    private static String scriptRaising(String threadId, Map<Pattern, Integer> others, int priority) {
        StringBuilder script = new StringBuilder("read go; ");
        for (Map.Entry<Pattern, Integer> e : others.entrySet()) {
            for (String tid : threadsNamed(e.getKey())) {
                int[] p = policyOf(tid);
                boolean realtime = p != null && (p[0] == 1 || p[0] == 2);
                boolean deadline = p != null && p[0] == SCHED_DEADLINE;   // above every SCHED_FIFO priority
                if (!tid.equals(threadId) && !deadline && !(realtime && p[1] >= e.getValue())) {
                    // looked at again when the shell runs: another request (a haptic loop's) may have raised it since
                    script.append("p=$(chrt -p ").append(tid).append(" 2>/dev/null | sed -n 's/.*priority: //p'); ")
                            .append("[ \"${p:-0}\" -lt ").append(e.getValue()).append(" ] && chrt -f -p ")
                            .append(e.getValue()).append(' ').append(tid).append(" 2>/dev/null; ");
                }
            }
        }
        return script.append("chrt -f -p ").append(priority).append(' ').append(threadId).toString();   // its status
    }

    /** {@return the calling thread's Linux thread id (from {@code /proc/thread-self}), or null where there is none} */
    public static String currentThreadId() {
        try {
            return Files.readSymbolicLink(Paths.get("/proc/thread-self")).getFileName().toString();
        } catch (IOException | UnsupportedOperationException | SecurityException e) {
            return null;
        }
    }

    /**
     * Reads the scheduling policy and real-time priority that Linux reports for a thread of this process.
     *
     * @param threadId the Linux id of a thread of this process
     * @return {policy, real-time priority} as Linux reports them (policy 0 normal, 1 SCHED_FIFO, 2 SCHED_RR,
     *     6 SCHED_DEADLINE; priority 0 for a normal or deadline thread), or null when the thread is gone or this is not Linux
     */
    public static int[] policyOf(String threadId) {
        try {
            String s = new String(Files.readAllBytes(Paths.get("/proc/self/task", threadId, "stat")),
                    StandardCharsets.UTF_8);
            String[] f = s.substring(s.lastIndexOf(')') + 2).split(" ");
            return new int[] {Integer.parseInt(f[38]), Integer.parseInt(f[37])};
        } catch (IOException | RuntimeException e) {
            return null;
        }
    }

    /** {@return the ids of this process's threads whose name (as Linux keeps it, 15 characters) matches} */
    public static List<String> threadsNamed(Pattern name) {
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

    private static void checkPriorities(Map<Pattern, Integer> others, int priority) {
        if (priority < 1 || priority > 99) {
            throw new IllegalArgumentException("RealtimeThreads: the priority must be 1..99, got " + priority);
        }
        if (others == null) {
            throw new IllegalArgumentException("RealtimeThreads: the map of other threads must not be null");
        }
        for (Map.Entry<Pattern, Integer> e : others.entrySet()) {
            if (e.getKey() == null || e.getValue() == null || e.getValue() < 1 || e.getValue() > 99) {
                throw new IllegalArgumentException("RealtimeThreads: threads " + e.getKey()
                        + " need a priority 1..99, got " + e.getValue());
            }
        }
    }

    private static String linuxOnly() {
        if (!System.getProperty("os.name", "").toLowerCase(Locale.ROOT).contains("linux")
                || !Files.exists(Paths.get("/proc/thread-self"))) {
            return "real-time scheduling is only requested on Linux";
        }
        return null;
    }

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

    /** Why a shell of chrt calls that ended with this status gave nothing. */
    private static String refusal(int exit) {
        switch (exit) {
            case NO_ANSWER:
                return "chrt did not answer within " + CHRT_TIMEOUT_MS + " ms";
            case NOT_FOUND:
                return "chrt (util-linux) not found";
            case INTERRUPTED:
                return "interrupted while asking for real-time scheduling";
            default:
                return "chrt refused (exit " + exit + "): the user may not raise priorities (needs root, "
                        + "CAP_SYS_NICE or an rtprio limit)";
        }
    }
}
