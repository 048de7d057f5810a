package tactus.haptics.safety;

import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import tactus.sketch.SketchHarness;

/**
 * A Processing sketch with a window (under Xvfb) that pushes on the emulator over a pty ends with the motors at
 * duty 0 when it calls {@code exit()} and when its window is closed (the WINDOW_CLOSING event that a window
 * manager's close button makes): Processing then disposes the sketch, which closes the board.
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class MotorGuardSketchTest {
    private static List<String> xvfb;

    @BeforeAll
    static void needsXvfbAndSocat() {
        MotorGuardTest.needsSocat();
        // xvfb-run waits for Xvfb's SIGUSR1, which a child of a JVM that loaded jSerialComm has ignored: reset it
        xvfb = List.of("env", "--default-signal=USR1", SketchHarness.requireXvfb().toString(), "-a", "-s",
                "-screen 0 640x480x24");
    }

    @Test
    void exitZeroesTheMotors() throws Exception {
        try (SketchEndingRun run = SketchEndingRun.start(xvfb, List.of(), MotorGuardSketchChild.class.getName())) {
            long end = System.nanoTime();
            run.tell("exit");
            MotorGuardTest.assertZeroedByTheSketch(run, "PApplet.exit()", end);
        }
    }

    @Test
    void closingTheWindowZeroesTheMotors() throws Exception {
        try (SketchEndingRun run = SketchEndingRun.start(xvfb, List.of(), MotorGuardSketchChild.class.getName())) {
            long end = System.nanoTime();
            run.tell("close");
            MotorGuardTest.assertZeroedByTheSketch(run, "window close (WINDOW_CLOSING)", end);
        }
    }
}
