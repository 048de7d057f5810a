package tactus.haptics.safety;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import tactus.haptics.emulator.BoardEmulator;
import tactus.haptics.emulator.PtyPair;
import tactus.haptics.Board;
import tactus.haptics.HaplyPreset;
import tactus.haptics.transport.SerialTransport;

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

    /**
     * The guard's parent dies while its input pipe stays open (here held by the test through a FIFO): the guard
     * notices from its parent poll and acts.
     */
    @Test
    void actsWhenItsParentIsGoneEvenIfItsInputStaysOpen() throws Exception {
        Path dir = Files.createTempDirectory("motor-guard");
        Path fifo = dir.resolve("in");
        try {
            Process mk = new ProcessBuilder("mkfifo", fifo.toString()).start();
            assertTrue(mk.waitFor(5, TimeUnit.SECONDS) && mk.exitValue() == 0, "mkfifo");
            StringBuilder cmd = new StringBuilder();
            for (String a : MotorGuardLink.command()) {
                cmd.append('\'').append(a.replace("'", "'\\''")).append("' ");
            }
            // the shell starts the guard on the FIFO, then ends: the guard's parent is gone, its input is not
            Path log = dir.resolve("log");
            Process shell = new ProcessBuilder("sh", "-c", cmd + "< '" + fifo + "' & sleep 1")
                    .redirectErrorStream(true).redirectOutput(log.toFile()).start();
            try (OutputStream in = Files.newOutputStream(fifo)) {
                in.write("port 0 /dev/tactus-no-such-port\ndevice 5 10 9\n".getBytes(StandardCharsets.UTF_8));
                in.flush();
                assertTrue(shell.waitFor(10, TimeUnit.SECONDS), "the shell ends");
                long gone = System.nanoTime();
                long deadline = gone + 10_000_000_000L;
                String out = "";
                while (!out.contains("nothing sent") && System.nanoTime() < deadline) {
                    Thread.sleep(20);
                    out = new String(Files.readAllBytes(log), StandardCharsets.UTF_8);
                }
                System.out.printf("MotorGuardProcessTest: parent gone, input open: guard done after %.0f ms%n",
                        (System.nanoTime() - gone) / 1e6);
                assertTrue(out.contains("the sketch's JVM is gone") && out.contains("nothing sent"),
                        "the guard acts once its parent is gone; its output: " + out);
            } finally {
                Files.deleteIfExists(log);
            }
        } finally {
            Files.deleteIfExists(fifo);
            Files.deleteIfExists(dir);
        }
    }

    @Test
    void aBoardStartsAGuardOnlyWhenTheGuardIsOnAndItsCloseEndsIt() throws Exception {
        try (PtyPair pty = PtyPair.open()) {
            BoardEmulator emulator = new BoardEmulator(HaplyPreset.HAPLY_2018);
            emulator.serve(SerialTransport.open(pty.boardEnd(), 0));
            try {
                Board.setMotorGuard(false);
                long before = guards();
                Board off = new Board(pty.hostEnd(), 0);
                assertEquals(before, guards(), "Board.setMotorGuard(false): no guard");
                off.close();
                Board.setMotorGuard(true);
                Board on = new Board(pty.hostEnd(), 0);
                assertEquals(before + 1, guards(), "a board on a serial port starts a guard");
                Board inProcess = new Board(emulator.connect());
                assertEquals(before + 1, guards(), "no guard for an in-process transport");
                inProcess.close();
                on.close();
                long deadline = System.nanoTime() + 3_000_000_000L;
                while (guards() > before && System.nanoTime() < deadline) {
                    Thread.sleep(5);
                }
                assertEquals(before, guards(), "closing the board ends its guard");
            } finally {
                Board.setMotorGuard(!"false".equals(System.getProperty(MotorGuardLink.PROPERTY)));
                emulator.close();
            }
        }
    }

    private static long guards() {
        return ProcessHandle.current().children().filter(h -> {
            String[] a = h.info().arguments().orElse(new String[0]);
            return a.length > 0 && a[a.length - 1].equals(MotorGuard.class.getName());
        }).count();
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
