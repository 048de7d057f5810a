package tactus.haptics.safety;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;

/**
 * For the {@link MotorGuard}: tells a sketch's JVM that is starved of CPU from one that is paused, when its
 * heartbeat is stale. On Linux the board's watchdog thread, which beats every 5 ms while a torque is on, is
 * runnable (state R in {@code /proc/<pid>/task/<tid>/stat}) when it waits for a CPU, and sleeping or stopped
 * when the JVM is paused (a debugger's suspension, a safepoint) or stopped (SIGSTOP). Elsewhere, or when the
 * thread cannot be found, nothing is known and the JVM counts as paused.
 */
final class HeartbeatThreads {
    /** The watchdog thread's name as Linux keeps it (the first 15 characters of the Java name). */
    static final String WATCHDOG_COMM = "tactus-haply-torque-watchdog".substring(0, 15);

    private final Path tasks;
    private List<Path> watchdogs;

    HeartbeatThreads(long pid) {
        this.tasks = Paths.get("/proc", Long.toString(pid), "task");
    }

    /** True if a watchdog thread of the sketch's JVM is runnable: the JVM runs but gets no CPU. */
    boolean waitForCpu() {
        try {
            if (watchdogs == null || watchdogs.isEmpty()) {
                watchdogs = find();
            }
            for (Path t : watchdogs) {
                String stat = new String(Files.readAllBytes(t.resolve("stat")), StandardCharsets.US_ASCII);
                int close = stat.lastIndexOf(')');
                if (close > 0 && close + 2 < stat.length() && stat.charAt(close + 2) == 'R') {
                    return true;
                }
            }
        } catch (IOException | RuntimeException e) {
            watchdogs = null;   // a thread ended, or no /proc: look again next time
        }
        return false;
    }

    private List<Path> find() throws IOException {
        List<Path> out = new ArrayList<>();
        if (!Files.isDirectory(tasks)) {
            return out;
        }
        try (DirectoryStream<Path> all = Files.newDirectoryStream(tasks)) {
            for (Path t : all) {
                try {
                    String comm = new String(Files.readAllBytes(t.resolve("comm")), StandardCharsets.UTF_8).trim();
                    if (comm.equals(WATCHDOG_COMM)) {
                        out.add(t);
                    }
                } catch (IOException ended) {
                    // the thread ended while we looked
                }
            }
        }
        return out;
    }
}
