package tactus.haptics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.sun.jdi.Location;
import com.sun.jdi.Method;
import com.sun.jdi.ReferenceType;
import com.sun.jdi.VirtualMachine;
import com.sun.jdi.event.BreakpointEvent;
import com.sun.jdi.event.Event;
import com.sun.jdi.event.EventSet;
import com.sun.jdi.request.BreakpointRequest;
import com.sun.jdi.request.EventRequest;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * A sketch's JVM that stays alive but stops running: the motor guard zeroes the motors when the JVM's heartbeat
 * stops, and hands the board back when it runs again. A hAPI-style child JVM pushes with a constant force at
 * 1 kHz on the emulator over a pty (duty 665/665); the test pauses it as a user does (SIGSTOP; the Java debugger
 * with a breakpoint that suspends every thread, as the Processing editor's Debug button does), and checks that
 * the duty reaches 0 within {@link #ZERO_LIMIT_MS}, stays there while the JVM is paused, and that after the JVM
 * resumes the force comes back as a ramp (not a jump), with no byte taken for a stray one, no reply misread and
 * no watchdog trip in the sketch.
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class MotorGuardPauseTest {
    /** The bound on the time from the pause to duty 0: the guard's stale time plus room for a loaded machine. */
    static final long ZERO_LIMIT_MS = MotorGuardLink.HEARTBEAT_STALE_MS + 400;
    /** How long the test keeps the JVM paused, in milliseconds. */
    private static final long PAUSE_MS = 1_000;
    private static final int FULL_DUTY = 665;
    private static final List<String> JDWP =
            List.of("-agentlib:jdwp=transport=dt_socket,server=y,suspend=n,address=127.0.0.1:0");
    private static final String CHILD = MotorGuardChild.class.getName();
    private static final Pattern STATS = Pattern.compile(
            "STATS unexpected=(\\d+) mismatches=(\\d+) implausible=(\\d+) zeroings=(\\d+) trips=(\\d+) closed=(\\w+)");

    @BeforeAll
    static void needsSocat() {
        MotorGuardTest.needsSocat();
    }

    @Test
    void sigstopZeroesTheMotorsAndSigcontRampsTheForceBackIn() throws Exception {
        try (SketchEndingRun run = SketchEndingRun.start(List.of(), List.of(), CHILD)) {
            long pid = run.child.pid();
            long stopped = System.nanoTime();
            signal("STOP", pid);
            double ms = run.millisToZero(stopped, ZERO_LIMIT_MS + 1_000);
            assertZeroedInTime(run, "SIGSTOP", ms);
            assertStaysZero(run, "SIGSTOP");
            Sampler ramp = new Sampler(run);
            signal("CONT", pid);
            long resumed = System.nanoTime();
            ramp.record(resumed);
            assertRampedBackIn(run, "SIGSTOP", ramp);
        }
    }

    @Test
    void aBreakpointThatSuspendsEveryThreadZeroesTheMotorsAndResumingRampsTheForceBackIn() throws Exception {
        try (SketchEndingRun run = SketchEndingRun.start(List.of(), JDWP, CHILD)) {
            VirtualMachine vm = run.attach();
            try {
                List<ReferenceType> types = vm.classesByName(CHILD);
                assertEquals(1, types.size(), "the sketch's class is loaded");
                Method draw = types.get(0).methodsByName("draw").get(0);
                Location at = draw.location();
                BreakpointRequest bp = vm.eventRequestManager().createBreakpointRequest(at);
                bp.setSuspendPolicy(EventRequest.SUSPEND_ALL);   // as the editor's breakpoints: every thread stops
                bp.enable();
                long hit = awaitBreakpoint(vm, 5_000);
                double ms = run.millisToZero(hit, ZERO_LIMIT_MS + 1_000);
                assertZeroedInTime(run, "a breakpoint (JDI, SUSPEND_ALL)", ms);
                assertStaysZero(run, "a breakpoint");
                bp.disable();
                vm.eventRequestManager().deleteEventRequest(bp);
                Sampler ramp = new Sampler(run);
                vm.resume();
                long resumed = System.nanoTime();
                ramp.record(resumed);
                assertRampedBackIn(run, "a breakpoint", ramp);
            } finally {
                vm.dispose();
            }
        }
    }

    private static long awaitBreakpoint(VirtualMachine vm, long ms) throws InterruptedException {
        long deadline = System.nanoTime() + ms * 1_000_000L;
        while (System.nanoTime() < deadline) {
            EventSet set = vm.eventQueue().remove(100);
            if (set == null) {
                continue;
            }
            for (Event e : set) {
                if (e instanceof BreakpointEvent) {
                    return System.nanoTime();
                }
            }
            set.resume();
        }
        throw new AssertionError("the breakpoint in draw() was not hit within " + ms + " ms");
    }

    private static void signal(String sig, long pid) throws Exception {
        Process kill = new ProcessBuilder("kill", "-" + sig, Long.toString(pid)).inheritIO().start();
        assertTrue(kill.waitFor(5, TimeUnit.SECONDS) && kill.exitValue() == 0, "kill -" + sig + " " + pid);
    }

    private static void assertZeroedInTime(SketchEndingRun run, String how, double ms) {
        System.out.printf("MotorGuardPauseTest: %s: duty 0 after %.0f ms%n", how, ms);
        assertTrue(ms >= 0 && ms <= ZERO_LIMIT_MS, how + ": the duty must reach 0 within " + ZERO_LIMIT_MS
                + " ms of the pause; it took " + ms + " ms (-1: not within " + (ZERO_LIMIT_MS + 1_000) + " ms; duty "
                + run.emulator.duty(1) + "/" + run.emulator.duty(2) + "); output:\n" + run.log());
    }

    private static void assertStaysZero(SketchEndingRun run, String how) throws InterruptedException {
        long deadline = System.nanoTime() + PAUSE_MS * 1_000_000L;
        while (System.nanoTime() < deadline) {
            assertTrue(run.emulator.duty(1) == 0 && run.emulator.duty(2) == 0, how + ": the duty stays 0 while the JVM "
                    + "is paused, got " + run.emulator.duty(1) + "/" + run.emulator.duty(2));
            Thread.sleep(1);
        }
        assertTrue(run.child.isAlive(), how + ": the sketch's JVM lives on");
    }

    private static void assertRampedBackIn(SketchEndingRun run, String how, Sampler ramp) throws Exception {
        assertTrue(ramp.firstNonZero >= 0, how + ": the sketch drives the motors again within 2 s of resuming; output:\n"
                + run.log());
        System.out.printf("MotorGuardPauseTest: %s: resumed; first duty %d/%d of %d, %.1f ms after resuming; full "
                + "duty %.1f ms after that%n", how, ramp.firstDuty, ramp.firstDuty2, FULL_DUTY,
                ramp.firstNonZeroMs, ramp.rampMs);
        assertTrue(ramp.firstDuty <= FULL_DUTY / 4, how + ": the force comes back as a ramp: first duty "
                + ramp.firstDuty + " of " + FULL_DUTY);
        assertTrue(ramp.rampMs >= Board.RESUME_RAMP_NANOS / 2e6, how + ": the ramp lasts about "
                + Board.RESUME_RAMP_NANOS / 1_000_000 + " ms, took " + ramp.rampMs + " ms");
        run.tell("stats");
        Matcher m = awaitStats(run);
        System.out.println("MotorGuardPauseTest: " + how + ": the sketch's board after the pause: " + m.group());
        assertEquals("0", m.group(1), how + ": no byte was taken for a stray one: " + m.group());
        assertEquals("0", m.group(2), how + ": no reply was misread: " + m.group());
        assertEquals("0", m.group(3), how + ": no reply was misread: " + m.group());
        assertTrue(Long.parseLong(m.group(4)) >= 1, how + ": the board saw the guard's writes: " + m.group());
        assertEquals("0", m.group(5), how + ": the board's watchdog did not trip after the pause: " + m.group());
        assertEquals("false", m.group(6), how + ": the board is open: " + m.group());
        assertTrue(run.guard().isPresent() && run.guard().get().isAlive(), how + ": the guard still watches");
    }

    private static Matcher awaitStats(SketchEndingRun run) throws InterruptedException {
        long deadline = System.nanoTime() + 5_000_000_000L;
        while (System.nanoTime() < deadline) {
            Matcher m = STATS.matcher(run.log());
            if (m.find()) {
                return m;
            }
            Thread.sleep(5);
        }
        throw new AssertionError("the child prints its board's counters; output:\n" + run.log());
    }

    /** Samples the emulator's duty after a resume: the first non-zero duty, and when both reached full duty. */
    private static final class Sampler {
        private final SketchEndingRun run;
        int firstDuty = -1;
        int firstDuty2 = -1;
        long firstNonZero = -1;
        double firstNonZeroMs;
        double rampMs = -1;

        Sampler(SketchEndingRun run) {
            this.run = run;
        }

        void record(long resumed) throws InterruptedException {
            long deadline = resumed + 2_000_000_000L;
            while (System.nanoTime() < deadline) {
                int d1 = run.emulator.duty(1);
                int d2 = run.emulator.duty(2);
                long now = System.nanoTime();
                if (firstNonZero < 0 && (d1 != 0 || d2 != 0)) {
                    firstNonZero = now;
                    firstDuty = Math.max(d1, d2);
                    firstDuty2 = Math.min(d1, d2);
                    firstNonZeroMs = (now - resumed) / 1e6;
                }
                if (firstNonZero >= 0 && d1 == FULL_DUTY && d2 == FULL_DUTY) {
                    rampMs = (now - firstNonZero) / 1e6;
                    return;
                }
                Thread.sleep(0, 100_000);
            }
            assertNotNull(null, "full duty again within 2 s of resuming (duty " + run.emulator.duty(1) + "/"
                    + run.emulator.duty(2) + ")");
        }
    }
}
