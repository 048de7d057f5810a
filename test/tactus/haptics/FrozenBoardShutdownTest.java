package tactus.haptics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedReader;
import java.io.File;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import tactus.haptics.emulator.BoardEmulator;
import tactus.haptics.emulator.PtyPair;
import tactus.haptics.transport.SerialTransport;

/**
 * A hAPI-style sketch JVM whose board stops reading (the emulator's end of the pty closed, socat alive):
 * the sketch thread fails with a message instead of spinning in a write, the JVM burns no CPU while the
 * board is frozen, and it ends on SIGTERM within 2 s. Two ways to the failure: the board's lost-link time
 * (1 s, before the driver's buffer fills) and, with that time set to 100 s, the transport's write timeout
 * once the buffer is full (about 4 s at 1 kHz on a pty).
 */
class FrozenBoardShutdownTest {

    @ParameterizedTest(name = "lost after {0} reads of 100 ms")
    @CsvSource({"10, stopped reading", "1000, did not complete within"})
    @Timeout(60)
    void aFrozenBoardNeitherSpinsNorKeepsTheJvmFromEnding(int lostAfter, String why) throws Exception {
        Assumptions.assumeTrue(PtyPair.socatAvailable(), "socat is not installed");
        try (PtyPair pty = PtyPair.open()) {
            BoardEmulator emulator = new BoardEmulator(HaplyPreset.HAPLY_2018);
            emulator.serve(SerialTransport.open(pty.boardEnd(), 0));
            String java = System.getProperty("java.home") + File.separator + "bin" + File.separator + "java";
            Process child = new ProcessBuilder(java, "-cp", System.getProperty("java.class.path"),
                    FrozenBoardChild.class.getName(), pty.hostEnd(), Integer.toString(lostAfter))
                    .redirectErrorStream(true).start();
            List<String> lines = new CopyOnWriteArrayList<>();
            List<Long> times = new CopyOnWriteArrayList<>();
            Thread reader = collect(child, lines, times);
            try {
                long deadline = System.nanoTime() + 20_000_000_000L;
                while (!lines.contains("READY") && child.isAlive() && System.nanoTime() < deadline) {
                    Thread.sleep(10);
                }
                assertTrue(lines.contains("READY"), "the child runs: " + lines);
                Thread.sleep(300);
                assertTrue(emulator.duty(1) > 0 || emulator.duty(2) > 0, "the child drives the motors");

                long frozenAt = System.nanoTime();
                emulator.unplug();
                assertTrue(pty.isAlive(), "socat stays: the port stays open");
                Thread.sleep(1_500);
                Duration cpuEarly = cpu(child);
                Thread.sleep(4_500);   // past the ~4 s at which the pty's buffer is full
                Duration cpuLate = cpu(child);
                long cpuMs = cpuLate.minus(cpuEarly).toMillis();

                long failedAfter = -1;
                for (int i = 0; i < lines.size(); i++) {
                    if (lines.get(i).contains(why)) {
                        failedAfter = (times.get(i) - frozenAt) / 1_000_000;
                    }
                }

                long term = System.nanoTime();
                child.destroy();   // SIGTERM
                boolean ended = child.waitFor(2, TimeUnit.SECONDS);
                long endMs = (System.nanoTime() - term) / 1_000_000;
                System.out.println("FrozenBoardShutdownTest(lost after " + lostAfter + "): failed " + failedAfter
                        + " ms after the freeze; CPU " + cpuMs + " ms in the 4.5 s from 1.5 s to 6 s after it; "
                        + (ended ? "ended " + endMs + " ms after SIGTERM" : "still running 2 s after SIGTERM"));
                assertTrue(ended, "the JVM must end within 2 s of SIGTERM; its output: " + lines);
                assertTrue(cpuMs < 500, "the frozen child must not burn CPU: " + cpuMs + " ms in 4.5 s");
                assertTrue(failedAfter >= 0, "the child printed why its link failed (\"" + why + "\"): " + lines);
            } finally {
                child.destroyForcibly();
                child.waitFor(5, TimeUnit.SECONDS);
                reader.join(1000);
                emulator.close();
            }
        }
    }

    private static Duration cpu(Process p) {
        return p.toHandle().info().totalCpuDuration().orElseThrow(
                () -> new AssertionError("the child's CPU time cannot be read on this system"));
    }

    private static Thread collect(Process child, List<String> lines, List<Long> times) {
        Thread t = new Thread(() -> {
            try (BufferedReader r = new BufferedReader(new InputStreamReader(child.getInputStream(), StandardCharsets.UTF_8))) {
                String line;
                while ((line = r.readLine()) != null) {
                    times.add(System.nanoTime());
                    lines.add(line);
                }
            } catch (IOException ignored) {
                // the child ended
            }
        }, "frozen-child-output");
        t.setDaemon(true);
        t.start();
        return t;
    }
}
