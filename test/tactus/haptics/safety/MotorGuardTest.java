package tactus.haptics.safety;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.sun.jdi.VirtualMachine;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import tactus.haptics.emulator.BoardEmulator;
import tactus.haptics.emulator.PtyPair;
import tactus.haptics.Board;
import tactus.haptics.Device;
import tactus.haptics.HaplyPreset;
import tactus.haptics.transport.SerialTransport;

/**
 * Every way a sketch's JVM can end leaves the motors at duty 0: a sketch-like child JVM pushes with a constant
 * force on the emulator over a pty, is ended, and the board's duty must reach 0 within {@link #LIMIT_MS}.
 * Where no shutdown hook runs (the Processing editor's Stop button, SIGKILL, {@code Runtime.halt}) the motor
 * guard does it; where hooks run (SIGTERM, {@code System.exit}) the board's hook does it and the guard exits
 * without touching the port. A control run shows the Stop button leaving the motors on without the guard.
 */
@Timeout(value = 40, unit = TimeUnit.SECONDS)
class MotorGuardTest {
    /** The stated bound: the duty is 0 at most this long after the end, in milliseconds. */
    static final long LIMIT_MS = 2_000;
    /** How long the guard may live on after the end (its own act limit plus its start), in milliseconds. */
    static final long GUARD_GONE_MS = MotorGuard.ACT_LIMIT_MS + 1_000;
    private static final List<String> JDWP =
            List.of("-agentlib:jdwp=transport=dt_socket,server=y,suspend=n,address=127.0.0.1:0");
    private static final String CHILD = MotorGuardChild.class.getName();

    @BeforeAll
    static void needsSocat() {
        assertTrue(PtyPair.socatAvailable(), "socat is needed for the pty tests (Debian: apt-get install socat)");
    }

    @Test
    void stopButtonZeroesTheMotorsThroughTheGuard() throws Exception {
        try (SketchEndingRun run = SketchEndingRun.start(List.of(), JDWP, CHILD)) {
            VirtualMachine vm = run.attach();
            long end = System.nanoTime();
            SketchEndingRun.stopButton(vm);
            assertZeroedByTheGuard(run, "Stop button (vm.exit(0) over JDWP)", end);
        }
    }

    @Test
    void sigkillZeroesTheMotorsThroughTheGuard() throws Exception {
        try (SketchEndingRun run = SketchEndingRun.start(List.of(), List.of(), CHILD)) {
            long end = System.nanoTime();
            run.child.destroyForcibly();
            assertZeroedByTheGuard(run, "SIGKILL", end);
        }
    }

    @Test
    void runtimeHaltZeroesTheMotorsThroughTheGuard() throws Exception {
        try (SketchEndingRun run = SketchEndingRun.start(List.of(), List.of(), CHILD)) {
            long end = System.nanoTime();
            run.tell("halt");
            assertZeroedByTheGuard(run, "Runtime.halt", end);
        }
    }

    @Test
    void sigtermZeroesTheMotorsThroughTheShutdownHook() throws Exception {
        try (SketchEndingRun run = SketchEndingRun.start(List.of(), List.of(), CHILD)) {
            long end = System.nanoTime();
            run.child.destroy();
            assertZeroedByTheSketch(run, "SIGTERM", end);
        }
    }

    @Test
    void systemExitZeroesTheMotorsThroughTheShutdownHook() throws Exception {
        try (SketchEndingRun run = SketchEndingRun.start(List.of(), List.of(), CHILD)) {
            long end = System.nanoTime();
            run.tell("exit");
            assertZeroedByTheSketch(run, "System.exit", end);
        }
    }

    @Test
    void closingTheBoardZeroesTheMotorsAndEndsTheGuard() throws Exception {
        try (SketchEndingRun run = SketchEndingRun.start(List.of(), List.of(), CHILD)) {
            long end = System.nanoTime();
            run.tell("close");
            assertZeroedByTheSketch(run, "Board.close (dispose)", end);
        }
    }

    /** The control: without the guard, the Stop button leaves the last torque on the motors. */
    @Test
    void withoutTheGuardTheStopButtonLeavesTheMotorsRunning() throws Exception {
        try (SketchEndingRun run = SketchEndingRun.start(List.of(), JDWP, CHILD, "noguard")) {
            assertFalse(run.guard().isPresent(), "Board.setMotorGuard(false) starts no guard");
            VirtualMachine vm = run.attach();
            long end = System.nanoTime();
            SketchEndingRun.stopButton(vm);
            assertTrue(run.child.waitFor(10, TimeUnit.SECONDS), "the Stop button ends the child");
            assertEquals(-1.0, run.millisToZero(end, LIMIT_MS), "nothing zeroes the motors");
            assertTrue(run.motorsDriven(), "the last torque stays on: duty " + run.emulator.duty(1) + "/"
                    + run.emulator.duty(2));
        }
    }

    /**
     * Only zeros the board answered count as sent: a close() whose zero torques got no answer does not tell the
     * guard "clean", and the guard sends them again once the port is free (before, it was told "clean" and left
     * without touching the port: every run); close() then sends no reset, so the board still takes the guard's
     * write as the device's.
     */
    @Test
    void aCloseWhoseZerosGoUnansweredLeavesTheMotorsToTheGuard() throws Exception {
        try (PtyPair pty = PtyPair.open()) {
            BoardEmulator emulator = new BoardEmulator(HaplyPreset.HAPLY_2018);
            emulator.serve(SerialTransport.open(pty.boardEnd(), 0));
            Board board = new Board(pty.hostEnd(), 0);
            try {
                Process guard = board.guardLink().process();
                assertTrue(guard != null && guard.isAlive(), "the board started a motor guard");
                Device device = new Device((byte) 5, board);
                HaplyPreset.HAPLY_2018.configure(device);
                device.device_set_parameters();
                device.set_actuator_torque(1, 0.08f);
                device.set_actuator_torque(2, -0.08f);
                device.device_write_torques();
                long deadline = System.nanoTime() + 2_000_000_000L;
                while ((emulator.duty(1) == 0 || emulator.duty(2) == 0) && System.nanoTime() < deadline) {
                    Thread.sleep(1);
                }
                assertTrue(emulator.duty(1) != 0 && emulator.duty(2) != 0, "the motors are driven");
                emulator.dropReplies(Integer.MAX_VALUE);   // the board takes the zeros but its answers are lost
                board.close();
                long writes = emulator.writes();
                long foreign = emulator.foreignWrites();
                long resets = emulator.resets();
                assertTrue(guard.waitFor(MotorGuard.ACT_LIMIT_MS + 2_000, TimeUnit.MILLISECONDS), "the guard ends");
                assertTrue(emulator.writes() > writes, "the guard, not told \"clean\", sent the zeros again");
                assertEquals(foreign, emulator.foreignWrites(), "the board took the guard's write as device 5's (close() "
                        + "did not reset it, as its zeros went unanswered)");
                assertEquals(resets + 1, emulator.resets(), "the guard reset the board after its zeros");
            } finally {
                board.close();
                emulator.close();
            }
        }
    }

    private static void assertZeroedByTheGuard(SketchEndingRun run, String how, long end) throws Exception {
        assertTrue(run.guard().isPresent(), "the board started a motor guard");
        double ms = run.millisToZero(end, LIMIT_MS);
        System.out.printf("MotorGuardTest: %s: duty 0 after %.0f ms%n", how, ms);
        assertTrue(ms >= 0, how + ": the duty is still " + run.emulator.duty(1) + "/" + run.emulator.duty(2)
                + " " + LIMIT_MS + " ms after the end; output:\n" + run.log());
        assertTrue(run.child.waitFor(10, TimeUnit.SECONDS), how + " ends the child");
        assertGuardGone(run, how);
        // no shutdown hook ran: the one reset after the Board constructor's is the guard's, after its zeros
        assertEquals(2, run.emulator.resets(), how + ": the guard zeroed the motors and reset the board once");
    }

    static void assertZeroedByTheSketch(SketchEndingRun run, String how, long end) throws Exception {
        assertTrue(run.guard().isPresent(), "the board started a motor guard");
        double ms = run.millisToZero(end, LIMIT_MS);
        System.out.printf("MotorGuardTest: %s: duty 0 after %.0f ms%n", how, ms);
        assertTrue(ms >= 0, how + ": the duty is still " + run.emulator.duty(1) + "/" + run.emulator.duty(2)
                + " " + LIMIT_MS + " ms after the end; output:\n" + run.log());
        assertTrue(run.child.waitFor(10, TimeUnit.SECONDS), how + " ends the child");
        assertGuardGone(run, how);
        assertEquals(2, run.emulator.resets(), how + ": the board zeroed the motors and reset once itself, and "
                + "the guard, told so, did not touch the port; output:\n" + run.log());
    }

    private static void assertGuardGone(SketchEndingRun run, String how) throws InterruptedException {
        ProcessHandle guard = run.guard().get();
        long deadline = System.nanoTime() + GUARD_GONE_MS * 1_000_000L;
        while (guard.isAlive() && System.nanoTime() < deadline) {
            Thread.sleep(5);
        }
        assertFalse(guard.isAlive(), how + ": the guard does not linger");
        assertTrue(run.awaitOutputEnd(2_000), how + ": the guard's output ends");
    }
}
