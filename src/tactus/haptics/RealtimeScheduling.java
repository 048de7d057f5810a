package tactus.haptics;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import java.util.regex.Pattern;

/**
 * Asks Linux to run threads under the real-time policy SCHED_FIFO, through the {@code chrt} program of util-linux
 * (Java has no call for it). Used once, before the first tick, by the haptic loop when
 * {@link HapticLoop#setRealtimePriority(int)} asks for it: for the loop thread itself, its safety threads, and the
 * JVM's threads that a Java thread can end up waiting for (the VM thread and the collector's pause workers one step
 * below the loop, the JIT compilers at the lowest real-time priority), so that another program loading the machine
 * cannot hold them, and through them the loop, up (see docs/haptics.md, "Why the loop was late"). It works where the user may raise priorities (root, {@code CAP_SYS_NICE}, or an {@code rtprio}
 * limit in {@code /etc/security/limits.conf}, as audio users often have); elsewhere, and on other systems, it
 * changes nothing and says why.
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
     * Moves the calling thread to SCHED_FIFO at the given priority.
     *
     * @param priority 1..99
     * @return null if it worked, otherwise why not (one short sentence)
     */
    static String applyToCurrentThread(int priority) {
        String why = linuxOnly();
        if (why != null) {
            return why;
        }
        String tid;
        try {
            tid = Files.readSymbolicLink(Paths.get("/proc/thread-self")).getFileName().toString();
        } catch (IOException | UnsupportedOperationException e) {
            return "cannot find the thread id (" + e.getMessage() + ")";
        }
        return chrt(priority, List.of(tid));
    }

    /**
     * Moves the JVM threads that every safepoint waits for ({@link #SAFEPOINT_THREADS}) to SCHED_FIFO at the
     * given priority. Workers the collector starts later are started by the VM thread and inherit its policy.
     *
     * @param priority 1..99
     * @return null if it worked, otherwise why not (one short sentence)
     */
    static String applyToSafepointThreads(int priority) {
        String why = linuxOnly();
        if (why != null) {
            return why;
        }
        List<String> tids = threadsNamed(SAFEPOINT_THREADS);
        if (tids.isEmpty()) {
            return "no VM or collector thread found in /proc/self/task";
        }
        return chrt(priority, tids);
    }

    /**
     * Moves every thread of this process whose name (as Linux keeps it, 15 characters) matches to SCHED_FIFO at the
     * given priority.
     *
     * @param name the pattern
     * @param priority 1..99
     * @return null if it worked (or no thread matched), otherwise why not (one short sentence)
     */
    static String applyToThreadsNamed(Pattern name, int priority) {
        String why = linuxOnly();
        if (why != null) {
            return why;
        }
        List<String> tids = threadsNamed(name);
        return tids.isEmpty() ? null : chrt(priority, tids);
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

    /** Runs {@code chrt -f -p priority tid} for each thread, all in one shell; null if every one worked. */
    private static String chrt(int priority, List<String> tids) {
        StringBuilder script = new StringBuilder();
        for (String tid : tids) {
            script.append(script.length() == 0 ? "" : " && ").append("chrt -f -p ").append(priority).append(' ')
                    .append(tid);
        }
        ProcessBuilder pb = tids.size() == 1 ? new ProcessBuilder("chrt", "-f", "-p", Integer.toString(priority),
                tids.get(0)) : new ProcessBuilder("sh", "-c", script.toString());
        pb.redirectErrorStream(true);
        pb.redirectOutput(ProcessBuilder.Redirect.DISCARD);
        try {
            Process p = pb.start();
            if (!p.waitFor(CHRT_TIMEOUT_MS, TimeUnit.MILLISECONDS)) {
                p.destroyForcibly();
                return "chrt did not answer within " + CHRT_TIMEOUT_MS + " ms";
            }
            return p.exitValue() == 0 ? null
                    : "chrt refused (exit " + p.exitValue() + "): the user may not raise priorities (needs root, "
                            + "CAP_SYS_NICE or an rtprio limit)";
        } catch (IOException e) {
            return "chrt (util-linux) not found";
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return "interrupted while asking for real-time scheduling";
        }
    }

    /** The scheduling policy of a thread of this process, as {@code /proc} gives it (0 normal, 1 FIFO, 2 RR). */
    static int policyOf(String tid) throws IOException {
        Path stat = Paths.get("/proc/self/task", tid, "stat");
        String s = new String(Files.readAllBytes(stat), StandardCharsets.UTF_8);
        String[] f = s.substring(s.lastIndexOf(')') + 2).split(" ");
        return Integer.parseInt(f[38]);
    }
}
