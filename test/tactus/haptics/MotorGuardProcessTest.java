package tactus.haptics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import tactus.haptics.emulator.BoardEmulator;
import tactus.haptics.emulator.PtyPair;

/**
 * The motor guard process on its own, started with the command line a board uses and told its lines by the
 * test: it holds no port while its parent lives, leaves on "clean" without touching the port, and never
 * hangs or lingers when the port is silent or missing.
 */
@Timeout(value = 30, unit = TimeUnit.SECONDS)
class MotorGuardProcessTest {

    @BeforeAll
    static void needsSocat() {
        MotorGuardTest.needsSocat();
    }

    private static Process startGuard() throws IOException {
        return new ProcessBuilder(MotorGuardLink.command()).redirectErrorStream(true).start();
    }

    private static void tell(Process guard, String lines) throws IOException {
        OutputStream in = guard.getOutputStream();
        in.write((lines + "\n").getBytes(StandardCharsets.UTF_8));
        in.flush();
    }

    private static String output(Process guard) throws IOException {
        return new String(guard.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
    }

    @Test
    void holdsNoPortWhileWaitingAndLeavesOnCleanWithoutTouchingIt() throws Exception {
        try (PtyPair pty = PtyPair.open()) {
            BoardEmulator emulator = new BoardEmulator(HaplyPreset.HAPLY_2018);
            emulator.serve(SerialTransport.open(pty.boardEnd(), 0));
            Process guard = startGuard();
            try {
                tell(guard, MotorGuard.HELLO + "\nport 0 " + pty.hostEnd() + "\ndevice 5 10 9");
                Thread.sleep(300);
                // jSerialComm locks a port it opens: this open fails if the guard holds the port
                SerialTransport.open(pty.hostEnd(), 0).close();
                tell(guard, "clean");
                assertTrue(guard.waitFor(2, TimeUnit.SECONDS), "the guard leaves on 'clean'");
                assertEquals(0, guard.exitValue());
                Thread.sleep(100);
                assertEquals(0, emulator.writes(), "nothing written to the board");
                assertEquals(0, emulator.resets(), "nothing written to the board");
            } finally {
                guard.destroyForcibly();
                emulator.close();
            }
        }
    }

    @Test
    void aSilentBoardDoesNotHoldTheGuard() throws Exception {
        try (PtyPair pty = PtyPair.open()) {   // nobody reads or answers on the board's end
            Process guard = startGuard();
            try {
                tell(guard, "port 0 " + pty.hostEnd() + "\ndevice 5 10 9\ndevice 7 12 13");
                long end = System.nanoTime();
                guard.getOutputStream().close();
                assertTrue(guard.waitFor(MotorGuard.ACT_LIMIT_MS + 2_000, TimeUnit.MILLISECONDS), "the guard ends");
                String out = output(guard);
                System.out.printf("MotorGuardProcessTest: silent board: guard gone after %.0f ms%n",
                        (System.nanoTime() - end) / 1e6);
                assertEquals(0, guard.exitValue(), out);
                assertTrue(out.contains("sent zero torques to device 5, 7") && out.contains("no answer within"), out);
            } finally {
                guard.destroyForcibly();
            }
        }
    }

    /** Ctrl-C, a closed terminal or a service stop signal the whole process group: the guard must outlive it. */
    @Test
    void terminalSignalsDoNotEndTheGuard() throws Exception {
        Process guard = startGuard();
        try {
            tell(guard, "port 0 /dev/tactus-no-such-port\ndevice 5 10 9");
            Thread.sleep(500);   // the guard has set up its signal handling
            for (String signal : new String[] {"INT", "TERM", "HUP"}) {
                Process kill = new ProcessBuilder("kill", "-" + signal, Long.toString(guard.pid())).start();
                assertTrue(kill.waitFor(5, TimeUnit.SECONDS) && kill.exitValue() == 0, "kill -" + signal);
            }
            assertFalse(guard.waitFor(1_000, TimeUnit.MILLISECONDS), "the guard ignores SIGINT, SIGTERM and SIGHUP");
            guard.getOutputStream().close();
            assertTrue(guard.waitFor(MotorGuard.ACT_LIMIT_MS + 2_000, TimeUnit.MILLISECONDS), "the guard ends");
            assertTrue(output(guard).contains("nothing sent"), "it still did its job once its input ended");
        } finally {
            guard.destroyForcibly();
        }
    }

    @Test
    void aMissingPortDoesNotHoldTheGuard() throws Exception {
        Process guard = startGuard();
        try {
            tell(guard, "port 0 /dev/tactus-no-such-port\ndevice 5 10 9");
            guard.getOutputStream().close();
            assertTrue(guard.waitFor(MotorGuard.ACT_LIMIT_MS + 2_000, TimeUnit.MILLISECONDS), "the guard ends");
            String out = output(guard);
            assertEquals(0, guard.exitValue(), out);
            assertTrue(out.contains("nothing sent"), out);
        } finally {
            guard.destroyForcibly();
        }
    }

    @Test
    void withNoDeviceSetUpTheGuardLeavesAtOnce() throws Exception {
        Process guard = startGuard();
        try {
            tell(guard, "port 0 /dev/tactus-no-such-port\ndevice 0 10 9\nbogus");
            guard.getOutputStream().close();
            assertTrue(guard.waitFor(2, TimeUnit.SECONDS), "the guard ends");
            String out = output(guard);
            assertEquals(0, guard.exitValue(), out);
            assertTrue(out.contains("ignored \"device 0 10 9\"") && out.contains("ignored \"bogus\""), out);
            assertTrue(!out.contains("nothing sent") && !out.contains("sent zero"), "nothing to do: " + out);
        } finally {
            guard.destroyForcibly();
        }
    }
}
