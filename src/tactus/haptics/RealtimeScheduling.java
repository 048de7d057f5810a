package tactus.haptics;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.concurrent.TimeUnit;

/**
 * Asks Linux to run the calling thread under the real-time policy SCHED_FIFO, through the {@code chrt}
 * program of util-linux (Java has no call for it). Used once, before the first tick, by the haptic loop when
 * {@link HapticLoop#setRealtimePriority(int)} asks for it. It works where the user may raise priorities
 * (root, {@code CAP_SYS_NICE}, or an {@code rtprio} limit in {@code /etc/security/limits.conf}, as audio
 * users often have); elsewhere, and on other systems, it changes nothing and says why.
 */
final class RealtimeScheduling {
    private static final long CHRT_TIMEOUT_MS = 2000;

    private RealtimeScheduling() {
    }

    /**
     * Moves the calling thread to SCHED_FIFO at the given priority.
     *
     * @param priority 1..99
     * @return null if it worked, otherwise why not (one short sentence)
     */
    static String applyToCurrentThread(int priority) {
        Path self = Paths.get("/proc/thread-self");
        if (!System.getProperty("os.name", "").toLowerCase(java.util.Locale.ROOT).contains("linux")
                || !Files.exists(self)) {
            return "real-time scheduling is only requested on Linux";
        }
        String tid;
        try {
            tid = Files.readSymbolicLink(self).getFileName().toString();
        } catch (IOException | UnsupportedOperationException e) {
            return "cannot find the thread id (" + e.getMessage() + ")";
        }
        ProcessBuilder pb = new ProcessBuilder("chrt", "-f", "-p", Integer.toString(priority), tid);
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
}
