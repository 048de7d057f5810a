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
     * then the calling thread to SCHED_FIFO at {@code priority}, in one run of a shell (one process start instead
     * of one per thread: under load each start took tens of milliseconds). A thread that ends meanwhile is skipped.
     *
     * @param others patterns of thread names and their priorities (1..99), applied in order
     * @param priority the calling thread's priority, 1..99
     * @return null if the calling thread got its priority, otherwise why not (one short sentence)
     */
    static String applyWithCurrentThread(Map<Pattern, Integer> others, int priority) {
        String why = linuxOnly();
        if (why != null) {
            return why;
        }
        String self;
        try {
            self = Files.readSymbolicLink(Paths.get("/proc/thread-self")).getFileName().toString();
        } catch (IOException | UnsupportedOperationException e) {
            return "cannot find the thread id (" + e.getMessage() + ")";
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
        script.append("chrt -f -p ").append(priority).append(' ').append(self);   // its status is the script's
        return run(new ProcessBuilder("sh", "-c", script.toString()));
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

    /** Runs a shell of chrt calls, bounded in time, and writes its go line; null if it exited with 0. */
    private static String run(ProcessBuilder pb) {
        pb.redirectErrorStream(true);
        pb.redirectOutput(ProcessBuilder.Redirect.DISCARD);
        try {
            Process p = pb.start();
            try (OutputStream in = p.getOutputStream()) {
                in.write('\n');
            }
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
}
