package tactus.haptics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.util.concurrent.locks.LockSupport;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import tactus.PhysicalModel;
import tactus.Vect3D;
import tactus.haptics.pantograph.PantographKinematics;

/** The session a sketch uses: board or emulator, device set up, a loop whose mapping fits the window. */
class HapticSessionTest {

    private static PhysicalModel freeAvatar(Vect3D home) {
        PhysicalModel pm = new PhysicalModel(1000);
        pm.addHapticInput3D("avatar", home, 5);
        pm.init();
        return pm;
    }

    private static void await(java.util.function.BooleanSupplier done, String what) {
        await(done, () -> what);
    }

    /** Waits up to 10 s for {@code done}; the message is made when the wait fails (it shows the state then). */
    private static void await(java.util.function.BooleanSupplier done, java.util.function.Supplier<String> what) {
        await(done, what, 10_000);
    }

    /**
     * Waits up to {@code timeoutMs} for {@code done}, looking every 2 ms, and fails with the result of the look that
     * ended the wait. It never looks a second time: the avatar follows a spring hand and can pass through a target
     * window while it moves, so a second look, a few milliseconds later on a loaded machine, may find it out again.
     * (This helper used to assert a second look; under a CPU hog that failed about 1 to 4 % of fresh runs, which
     * was taken for a stall of the haptic loop: see docs/haptics.md, "The 10-second stall that was not".)
     */
    static void await(java.util.function.BooleanSupplier done, java.util.function.Supplier<String> what,
                      long timeoutMs) {
        long start = System.nanoTime();
        boolean reached;
        while (!(reached = done.getAsBoolean()) && System.nanoTime() - start < timeoutMs * 1_000_000L) {
            LockSupport.parkNanos(2_000_000);
        }
        if (!reached) {
            fail(what.get() + " (waited " + (System.nanoTime() - start) / 1_000_000 + " ms)");
        }
    }

    @Test
    void aWaitEndsOnTheLookThatSawTheConditionAndNeverLooksAgain() {
        // true at the third look only, as an avatar passing through its target window
        int[] looks = {0};
        await(() -> ++looks[0] == 3, () -> "the third look", 2_000);
        assertEquals(3, looks[0], "no look after the one that saw it");
        // never true: fails after the time-out, saying how long it waited
        AssertionError e = assertThrows(AssertionError.class, () -> await(() -> false, () -> "never", 50));
        assertTrue(e.getMessage().startsWith("never (waited "), e.getMessage());
    }

    /** The loop's state and the handle's, for a failure message. */
    private static String state(HapticSession s) {
        HapticLoop l = s.loop();
        double[] d = new double[2];
        l.devicePosition(d);
        return "loop running " + l.isRunning() + ", " + l.ticks() + " ticks, failure " + l.failure()
                + ", loop's handle (" + d[0] + ", " + d[1] + "), emulator's handle (" + s.emulator().x() + ", "
                + s.emulator().y() + "), " + l.telemetry() + ", " + l.scheduling() + loopThreads();
    }

    /** The state and top frames of every haptic loop thread alive, for a failure message. */
    private static String loopThreads() {
        StringBuilder b = new StringBuilder();
        for (java.util.Map.Entry<Thread, StackTraceElement[]> e : Thread.getAllStackTraces().entrySet()) {
            if (e.getKey().getName().startsWith("tactus-haptic")) {
                b.append("; ").append(e.getKey().getName()).append(' ').append(e.getKey().getState());
                StackTraceElement[] st = e.getValue();
                for (int i = 0; i < Math.min(8, st.length); i++) {
                    b.append(" <- ").append(st[i]);
                }
            }
        }
        // what Linux says of those threads (state R/S/D, policy, priority, last CPU): a Java state is only what
        // the thread last set itself, so a runnable thread that gets no CPU still reads TIMED_WAITING
        java.io.File[] tasks = new java.io.File("/proc/self/task").listFiles();
        for (java.io.File t : tasks == null ? new java.io.File[0] : tasks) {
            try {
                String comm = new String(java.nio.file.Files.readAllBytes(new java.io.File(t, "comm").toPath())).trim();
                if (comm.startsWith("tactus-haptic")) {
                    String[] f = new String(java.nio.file.Files.readAllBytes(new java.io.File(t, "stat").toPath()))
                            .replaceFirst("^.*\\) ", "").split(" ");
                    b.append("; linux ").append(comm).append(" state ").append(f[0]).append(" cpu ").append(f[36])
                            .append(" rt_priority ").append(f[37]).append(" policy ").append(f[38])
                            .append(" wchan ").append(new String(java.nio.file.Files.readAllBytes(
                                    new java.io.File(t, "wchan").toPath())).trim());
                }
            } catch (java.io.IOException | RuntimeException e) {
                b.append("; ").append(t.getName()).append(": ").append(e);
            }
        }
        return b.toString();
    }

    @Test
    void theWorkspaceOfEveryPresetIsWithinReachAndUsable() {
        double[] th = new double[2];
        for (HaplyPreset p : HaplyPreset.values()) {
            PantographKinematics k = p.newKinematics();
            double[] box = new double[4];
            HapticSession.workspaceOf(k, box);
            double w = box[1] - box[0];
            double h = box[3] - box[2];
            assertEquals(2 * h, w, 1e-9, p.name());
            assertTrue(h > 0.03, p + ": workspace only " + h + " m tall");
            assertEquals(0.5 * p.d(), 0.5 * (box[0] + box[1]), 1e-12, p.name());
            for (int i = 0; i <= 40; i++) {          // a finer grid than the one that chose it
                for (int j = 0; j <= 20; j++) {
                    double x = box[0] + w * i / 40;
                    double y = box[2] + h * j / 20;
                    assertTrue(k.inverse(x, y, th) && k.forward(th[0], th[1])
                            && Math.abs(k.x() - x) < 1e-9 && Math.abs(k.y() - y) < 1e-9,
                            p + ": (" + x + ", " + y + ") out of reach");
                }
            }
        }
    }

    @Test
    void theMappingFitsTheWorkspaceToTheWindowAndHomeIsTheHandle() {
        try (HapticSession s = HapticSession.openEmulated(null, HaplyPreset.HAPLY_2018)) {
            assertTrue(s.isEmulated());
            assertTrue(s.status().contains("mouse"), s.status());
            double[] ws = new double[4];
            s.workspace(ws);
            // centred in the 800 x 600 default window, 90 % of it in the limiting direction
            assertEquals(400, 0.5 * (ws[0] + ws[1]), 1e-9);
            assertEquals(300, 0.5 * (ws[2] + ws[3]), 1e-9);
            assertTrue(ws[0] >= 0 && ws[1] <= 800 && ws[2] >= 0 && ws[3] <= 600);
            assertTrue(Math.abs(ws[1] - ws[0] - 720) < 1e-6 || Math.abs(ws[3] - ws[2] - 540) < 1e-6);
            // home: the handle's pose at open (the calibration pose), mapped as a tick maps it
            HapticLoop loop = s.attach(freeAvatar(s.home()), "avatar");
            PantographKinematics k = HaplyPreset.HAPLY_2018.newKinematics();
            k.forward(Math.toRadians(s.emulator().jointDegrees(1)), Math.toRadians(s.emulator().jointDegrees(2)));
            double[] m = new double[2];
            loop.deviceToModel(k.x(), k.y(), m);
            Vect3D home = s.home();
            assertEquals(m[0], home.x, 0.5);      // encoder quantisation: well under a pixel
            assertEquals(m[1], home.y, 0.5);
            loop.modelToDevice(m[0], m[1], m);
            assertEquals(k.x(), m[0], 1e-12);
            assertEquals(k.y(), m[1], 1e-12);
        }
    }

    @Test
    void theEmulatedHandTakesTheAvatarToThePixel() {
        try (HapticSession s = HapticSession.openEmulated(null, HaplyPreset.HAPLY_2018)) {
            PhysicalModel pm = freeAvatar(s.home());
            s.attach(pm, "avatar").start();
            double[] ws = new double[4];
            s.workspace(ws);
            double px = ws[0] + 0.3 * (ws[1] - ws[0]);     // left of the centre: x is mirrored on the device
            double py = ws[2] + 0.7 * (ws[3] - ws[2]);
            s.handTowardsPixel(px, py);
            await(() -> {
                Vect3D p = pm.getMatPosition("avatar");
                return Math.abs(p.x - px) < 2 && Math.abs(p.y - py) < 2;
            }, () -> "the avatar did not reach the pixel: " + pm.getMatPosition("avatar") + " vs " + px + ", " + py
                    + "; " + state(s));
            assertTrue(s.emulator().x() > 0.5 * HaplyPreset.HAPLY_2018.d(), "x mirrored: " + s.emulator().x());
            // a pixel outside the workspace is kept at its edge
            s.handTowardsPixel(-10_000, py);
            await(() -> Math.abs(pm.getMatPosition("avatar").x - ws[0]) < 2,
                    () -> "clamped to the left edge: " + pm.getMatPosition("avatar") + "; " + state(s));
            // with a view, the pixel goes through it: model = (pixel - offset) / scale
            s.setView(2, 100, 50);
            s.handTowardsPixel(100 + 2 * px, 50 + 2 * py);
            await(() -> {
                Vect3D p = pm.getMatPosition("avatar");
                return Math.abs(p.x - px) < 2 && Math.abs(p.y - py) < 2;
            }, () -> "through the view: " + pm.getMatPosition("avatar") + "; " + state(s));
            assertThrows(IllegalArgumentException.class, () -> s.setView(0, 0, 0));
            assertThrows(IllegalArgumentException.class, () -> s.setView(1, Double.NaN, 0));
        }
    }

    @Test
    void attachingAgainStopsTheOldLoopAndKeepsTheBoard() {
        try (HapticSession s = HapticSession.openEmulated(null, HaplyPreset.HAPLY_2018)) {
            HapticLoop first = s.attach(freeAvatar(s.home()), "avatar");
            first.start();
            await(() -> first.ticks() > 20, "first loop ticks");
            HapticLoop second = s.attach(freeAvatar(s.home()), "avatar");
            assertNotSame(first, second);
            assertFalse(first.isRunning());
            second.setRate(200);
            second.start();
            await(() -> second.ticks() > 20, () -> "second loop ticks: " + second.failure());
            assertTrue(second.isRunning(), () -> "second loop: " + second.failure());
            assertEquals(second, s.loop());
            assertTrue(second.scheduling().startsWith("real-time") || second.scheduling().startsWith("normal"),
                    second.scheduling());
        }
    }

    @Test
    void closingStopsTheLoopAndZeroesTheMotors() {
        HapticSession s = HapticSession.openEmulated(null, HaplyPreset.HAPLY_2018);
        HapticLoop loop = s.attach(new AvatarLink() {
            @Override
            public void setTarget(double x, double y, double z) {
            }

            @Override
            public void takeForce(double[] out) {
                out[0] = 0.01;        // 1 N with the default force gain: the motors turn
                out[1] = 0.01;
                out[2] = 0;
            }

            @Override
            public void step(int n) {
            }
        });
        loop.start();
        await(() -> s.emulator().duty(1) != 0 || s.emulator().duty(2) != 0, "motors driven");
        s.close();
        assertFalse(loop.isRunning());
        assertEquals(0, s.emulator().duty(1));
        assertEquals(0, s.emulator().duty(2));
        assertThrows(IllegalStateException.class, () -> s.attach(freeAvatar(new Vect3D()), "avatar"));
        s.close();   // twice is harmless
    }

    @Test
    void withNoHaplyTheSessionSaysTheMouseIsTheHand() {
        Assumptions.assumeTrue(SerialPorts.candidates().isEmpty(), "a Haply-like port is present");
        try (HapticSession s = HapticSession.open(null)) {
            assertTrue(s.isEmulated());
            assertEquals("No Haply board found: emulated board, the mouse is your hand", s.status());
            assertEquals(HaplyPreset.HAPLY_2018, s.preset());
        }
    }

    @Test
    void withTheModelsYUpTheMouseStillLandsOnTheAvatarAndForcesFollowTheAxes() {
        try (HapticSession s = HapticSession.openEmulated(null, HaplyPreset.HAPLY_2018)) {
            double[] down = new double[4];
            s.workspace(down);
            Vect3D homeDown = s.home();
            s.setModelYUp(true);
            assertTrue(s.isModelYUp());
            double[] up = new double[4];
            s.workspace(up);
            assertEquals(down[0], up[0], 1e-9);
            assertEquals(HapticSession.DEFAULT_HEIGHT - down[3], up[2], 1e-9);
            assertEquals(HapticSession.DEFAULT_HEIGHT - homeDown.y, s.home().y, 1e-9);
            // a constant upward model force (+y) must push the hand up the window: device -y
            AvatarLink pushUp = new AvatarLink() {
                @Override
                public void setTarget(double x, double y, double z) {
                }

                @Override
                public void takeForce(double[] out) {
                    out[0] = 0;
                    out[1] = 0.002;
                    out[2] = 0;
                }

                @Override
                public void step(int n) {
                }
            };
            HapticLoop loop = s.attach(pushUp);
            loop.setForceGain(100);
            loop.start();
            await(() -> loop.ticks() > 20, "ticks");
            double[] f = new double[2];
            loop.deviceForce(f);
            assertEquals(-0.2, f[1], 1e-9, "device force y");
            s.forceInModel(f);
            assertEquals(0.2, f[1], 1e-9, "force along the model's y");
            // the mouse: pixel (px, py) is model (px, height - py)
            PhysicalModel pm = freeAvatar(s.home());
            s.attach(pm, "avatar").start();
            double px = up[0] + 0.6 * (up[1] - up[0]);
            double my = up[2] + 0.25 * (up[3] - up[2]);
            s.handTowardsPixel(px, HapticSession.DEFAULT_HEIGHT - my);
            await(() -> {
                Vect3D p = pm.getMatPosition("avatar");
                return Math.abs(p.x - px) < 2 && Math.abs(p.y - my) < 2;
            }, () -> "y up: " + pm.getMatPosition("avatar") + " vs " + px + ", " + my + "; " + state(s));
        }
    }

    /** A sketch that is never run, whose registered "pre" methods a test can call as Processing would. */
    public static final class HookedApp extends processing.core.PApplet {
        void runPre() {
            handleMethods("pre");
        }

        /** What PApplet.dispose() does for libraries once the window is gone (it needs a window itself). */
        void runDispose() {
            handleMethods("dispose");
        }
    }

    @Test
    void processingsHooksDriveTheHandFromTheMouseAndDisposeClosesEverything() {
        HookedApp app = new HookedApp();   // never run: no window
        app.width = 640;
        app.height = 480;
        HapticSession s = HapticSession.openEmulated(app, HaplyPreset.HAPLY_2018);
        PhysicalModel pm = freeAvatar(s.home());
        HapticLoop loop = s.attach(pm, "avatar");
        loop.start();
        double[] ws = new double[4];
        s.workspace(ws);
        assertEquals(320, 0.5 * (ws[0] + ws[1]), 1e-9);
        // with the idle tour off, before the mouse has moved, pre() leaves the hand where it is
        s.setIdleTour(false);
        assertFalse(s.isTouring());
        assertFalse(s.status().contains("tours"), s.status());
        app.mouseX = 0;
        app.mouseY = 0;
        long until = System.nanoTime() + 300_000_000L;
        while (System.nanoTime() < until) {          // 0.3 s of frames: the tour would have moved the hand
            app.runPre();
            LockSupport.parkNanos(16_000_000);
        }
        await(() -> loop.ticks() > 50, "ticks");
        Vect3D still = pm.getMatPosition("avatar");
        assertEquals(s.home().x, still.x, 2);
        assertEquals(s.home().y, still.y, 2);
        // the first move hands the hand to the mouse
        int mx = (int) (ws[0] + 0.8 * (ws[1] - ws[0]));
        int my = (int) (ws[2] + 0.5 * (ws[3] - ws[2]));
        app.mouseX = mx;
        app.mouseY = my;
        s.mouseEvent(new processing.event.MouseEvent(null, 0, processing.event.MouseEvent.MOVE, 0, mx, my, 0, 0));
        app.runPre();
        await(() -> {
            Vect3D p = pm.getMatPosition("avatar");
            return Math.abs(p.x - mx) < 2 && Math.abs(p.y - my) < 2;
        }, "the avatar follows the mouse: " + pm.getMatPosition("avatar") + " vs " + mx + ", " + my);
        // Processing's dispose (the sketch ends) stops the loop and zeroes the motors
        app.runDispose();
        assertFalse(loop.isRunning());
        assertEquals(0, s.emulator().duty(1));
        assertEquals(0, s.emulator().duty(2));
        assertTrue(s.emulator().isUnplugged());
    }

    @Test
    void theIdleTourStartsAtHomeStaysInTheWorkspaceAndLoopsSmoothly() {
        for (HaplyPreset p : HaplyPreset.values()) {
            try (HapticSession s = HapticSession.openEmulated(null, p)) {
                double[] box = new double[4];
                s.deviceWorkspace(box);
                double w = box[1] - box[0];
                double h = box[3] - box[2];
                // t = 0: the handle's home position (as home() maps it), or the nearest point of the workspace
                // for a calibration pose outside it
                HapticLoop loop = s.attach(freeAvatar(s.home()), "avatar");
                double[] hd = new double[2];
                loop.modelToDevice(s.home().x, s.home().y, hd);
                double[] q = new double[2];
                s.idleTourTarget(0, q);
                assertEquals(Math.max(box[0], Math.min(box[1], hd[0])), q[0], 1e-9, p.name());
                assertEquals(Math.max(box[2], Math.min(box[3], hd[1])), q[1], 1e-9, p.name());
                double[] m = new double[2];
                s.idleTourTarget(-5, m);                 // before the start: still home
                assertEquals(q[0], m[0], 0);
                assertEquals(q[1], m[1], 0);
                // two laps sampled every 5 ms: inside the workspace, no jump, a slow hand
                double dt = 0.005;
                double lap = 12;                          // 3:2 Lissajous of periods 6 s and 4 s
                double minX = Double.MAX_VALUE;
                double maxX = -Double.MAX_VALUE;
                double minY = Double.MAX_VALUE;
                double maxY = -Double.MAX_VALUE;
                double sumX = 0;
                double sumY = 0;
                int n = 0;
                double[] prev = q.clone();
                for (int i = 1; i * dt <= 2 * lap + HapticSession.TOUR_RAMP; i++) {
                    double t = i * dt;
                    s.idleTourTarget(t, q);
                    String at = p + " at t = " + t + " s: (" + q[0] + ", " + q[1] + ")";
                    assertTrue(q[0] >= box[0] && q[0] <= box[1] && q[1] >= box[2] && q[1] <= box[3], at);
                    double speed = Math.hypot(q[0] - prev[0], q[1] - prev[1]) / dt;
                    assertTrue(speed < 0.2, at + " moves at " + speed + " m/s");
                    prev[0] = q[0];
                    prev[1] = q[1];
                    if (t >= HapticSession.TOUR_RAMP + lap) {   // the last full lap, past the ramp
                        minX = Math.min(minX, q[0]);
                        maxX = Math.max(maxX, q[0]);
                        minY = Math.min(minY, q[1]);
                        maxY = Math.max(maxY, q[1]);
                        sumX += q[0];
                        sumY += q[1];
                        n++;
                        double[] earlier = new double[2];
                        s.idleTourTarget(t - lap, earlier);
                        assertEquals(earlier[0], q[0], 1e-12, at + ": periodic");
                        assertEquals(earlier[1], q[1], 1e-12, at + ": periodic");
                    }
                }
                // a figure centred in the workspace, TOUR_EXTENT of its half-size each way
                assertEquals(0.5 * (box[0] + box[1]), sumX / n, 1e-3 * w, p.name());
                assertEquals(0.5 * (box[2] + box[3]), sumY / n, 1e-3 * h, p.name());
                assertEquals(HapticSession.TOUR_EXTENT * w, maxX - minX, 1e-3 * w, p.name());
                assertEquals(HapticSession.TOUR_EXTENT * h, maxY - minY, 1e-3 * h, p.name());
                // through the middle at TOUR_CENTRE_TIME, and every 6 s after
                for (int k = 0; k < 3; k++) {
                    s.idleTourTarget(HapticSession.TOUR_CENTRE_TIME + 6 * k, q);
                    assertEquals(0.5 * (box[0] + box[1]), q[0], 1e-9 * w, p.name());
                    assertEquals(0.5 * (box[2] + box[3]), q[1], 1e-9 * h, p.name());
                }
                // without a PApplet there is no pre(): no tour, and the status does not promise one
                assertFalse(s.isTouring());
                assertFalse(s.status().contains("tours"), s.status());
            }
        }
    }

    @Test
    void beforeTheMouseMovesTheHandToursAndTheFirstMouseEventEndsTheTour() {
        HookedApp app = new HookedApp();
        app.width = 640;
        app.height = 480;
        HapticSession s = HapticSession.openEmulated(app, HaplyPreset.HAPLY_2018);
        try {
            assertTrue(s.isIdleTour(), "on by default");
            assertTrue(s.isTouring());
            assertTrue(s.status().endsWith("the hand tours on its own until you move the mouse"), s.status());
            PhysicalModel pm = freeAvatar(s.home());
            HapticLoop loop = s.attach(pm, "avatar");
            loop.start();
            double[] ws = new double[4];
            s.workspace(ws);
            Vect3D home = s.home();
            // frames at about 60 Hz for up to 5 s: the avatar leaves home and travels, always inside the workspace
            double far = 0;
            double margin = 3;                       // pixels: the hand is a spring, the avatar smooths
            long until = System.nanoTime() + 5_000_000_000L;
            while (System.nanoTime() < until && far < 0.25 * (ws[1] - ws[0])) {
                app.runPre();
                LockSupport.parkNanos(16_000_000);
                Vect3D p = pm.getMatPosition("avatar");
                assertTrue(p.x > ws[0] - margin && p.x < ws[1] + margin && p.y > ws[2] - margin
                        && p.y < ws[3] + margin, "the avatar left the workspace on the tour: " + p);
                far = Math.max(far, Math.hypot(p.x - home.x, p.y - home.y));
            }
            assertTrue(far >= 0.25 * (ws[1] - ws[0]), "the tour moved the avatar only " + far + " px from home");
            assertTrue(loop.isRunning(), () -> "loop: " + loop.failure());
            // the first mouse event ends the tour: the avatar goes to the mouse and stays there
            int mx = (int) (ws[0] + 0.2 * (ws[1] - ws[0]));
            int my = (int) (ws[2] + 0.8 * (ws[3] - ws[2]));
            app.mouseX = mx;
            app.mouseY = my;
            s.mouseEvent(new processing.event.MouseEvent(null, 0, processing.event.MouseEvent.MOVE, 0, mx, my, 0, 0));
            assertFalse(s.isTouring());
            assertFalse(s.status().contains("tours"), s.status());
            assertTrue(s.isIdleTour(), "the switch itself stays on");
            app.runPre();
            await(() -> {
                Vect3D p = pm.getMatPosition("avatar");
                return Math.abs(p.x - mx) < 2 && Math.abs(p.y - my) < 2;
            }, () -> "the avatar follows the mouse: " + pm.getMatPosition("avatar") + " vs " + mx + ", " + my + "; "
                    + state(s));
            LockSupport.parkNanos(500_000_000L);     // let the hand's spring settle from the tour's speed
            app.runPre();
            long still = System.nanoTime() + 1_000_000_000L;
            while (System.nanoTime() < still) {      // a second of frames with the mouse still: no more touring
                app.runPre();
                LockSupport.parkNanos(16_000_000);
                Vect3D p = pm.getMatPosition("avatar");
                assertTrue(Math.abs(p.x - mx) < 2 && Math.abs(p.y - my) < 2, "the tour went on: " + p);
            }
        } finally {
            app.runDispose();
        }
        assertTrue(s.emulator().isUnplugged());
    }
}
