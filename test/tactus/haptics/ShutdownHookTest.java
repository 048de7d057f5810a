package tactus.haptics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedReader;
import java.io.File;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import tactus.haptics.emulator.BoardEmulator;
import tactus.haptics.emulator.PtyPair;
import tactus.haptics.transport.SerialTransport;

/** A JVM that ends without closing its board still zeroes the motors (the shutdown hook), over a real pty. */
class ShutdownHookTest {
    /** The longest the child JVM may live, s (it normally ends within a few seconds). */
    static final long CHILD_LIMIT_SECONDS = 60;

    @Test
    void exitingWithoutDisposeZeroesTheMotors() throws Exception {
        Assumptions.assumeTrue(PtyPair.socatAvailable(), "socat is not installed");
        try (PtyPair pty = PtyPair.open()) {
            BoardEmulator emulator = new BoardEmulator(HaplyPreset.HAPLY_2018);
            emulator.serve(SerialTransport.open(pty.boardEnd(), 0));
            String java = System.getProperty("java.home") + File.separator + "bin" + File.separator + "java";
            Process child = new ProcessBuilder(java, "-cp", System.getProperty("java.class.path"),
                    ShutdownHookChild.class.getName(), pty.hostEnd()).redirectErrorStream(true).start();
            // readLine below cannot be interrupted: if the child never answers, this reaper ends it (which ends the
            // read), also when JUnit's timeout has already failed the test and left this thread behind
            Thread reaper = new Thread(() -> {
                try {
                    child.waitFor(CHILD_LIMIT_SECONDS, TimeUnit.SECONDS);
                } catch (InterruptedException e) {
                    // the test is over: end the child now
                }
                child.destroyForcibly();
            }, "shutdown-hook-child-reaper");
            reaper.setDaemon(true);
            reaper.start();
            try {
                BufferedReader out = new BufferedReader(new InputStreamReader(child.getInputStream(), StandardCharsets.UTF_8));
                String line;
                StringBuilder log = new StringBuilder();
                while ((line = out.readLine()) != null && !line.equals("READY")) {
                    log.append(line).append('\n');
                }
                assertEquals("READY", line, "child output:\n" + log);
                assertTrue(emulator.duty(1) > 0 && emulator.duty(2) > 0, "the child drives the motors");
                OutputStream in = child.getOutputStream();
                in.write("exit\n".getBytes(StandardCharsets.UTF_8));
                in.flush();
                assertTrue(child.waitFor(20, TimeUnit.SECONDS), "the child ends");
                long deadline = System.nanoTime() + 2_000_000_000L;
                while ((emulator.duty(1) != 0 || emulator.duty(2) != 0) && System.nanoTime() < deadline) {
                    Thread.sleep(1);
                }
                assertEquals(0, emulator.duty(1));
                assertEquals(0, emulator.duty(2));
            } finally {
                child.destroyForcibly();
                reaper.interrupt();
                emulator.close();
            }
        }
    }
}
