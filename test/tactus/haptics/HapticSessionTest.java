package tactus.haptics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.locks.LockSupport;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import tactus.PhysicalModel;
import tactus.Vect3D;

/** The session a sketch uses: board or emulator, device set up, a loop whose mapping fits the window. */
class HapticSessionTest {

    private static PhysicalModel freeAvatar(Vect3D home) {
        PhysicalModel pm = new PhysicalModel(1000);
        pm.addHapticInput3D("avatar", home, 5);
        pm.init();
        return pm;
    }

    private static void await(java.util.function.BooleanSupplier done, String what) {
        long deadline = System.nanoTime() + 10_000_000_000L;
        while (!done.getAsBoolean() && System.nanoTime() < deadline) {
            LockSupport.parkNanos(2_000_000);
        }
        assertTrue(done.getAsBoolean(), what);
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
            }, "the avatar did not reach the pixel: " + pm.getMatPosition("avatar") + " vs " + px + ", " + py);
            assertTrue(s.emulator().x() > 0.5 * HaplyPreset.HAPLY_2018.d(), "x mirrored: " + s.emulator().x());
            // a pixel outside the workspace is kept at its edge
            s.handTowardsPixel(-10_000, py);
            await(() -> Math.abs(pm.getMatPosition("avatar").x - ws[0]) < 2,
                    "clamped to the left edge: " + pm.getMatPosition("avatar"));
            // with a view, the pixel goes through it: model = (pixel - offset) / scale
            s.setView(2, 100, 50);
            s.handTowardsPixel(100 + 2 * px, 50 + 2 * py);
            await(() -> {
                Vect3D p = pm.getMatPosition("avatar");
                return Math.abs(p.x - px) < 2 && Math.abs(p.y - py) < 2;
            }, "through the view: " + pm.getMatPosition("avatar"));
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
            await(() -> second.ticks() > 20, "second loop ticks: " + second.failure());
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
            }, "y up: " + pm.getMatPosition("avatar") + " vs " + px + ", " + my);
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
        // before the mouse has moved, pre() leaves the hand where it is
        app.mouseX = 0;
        app.mouseY = 0;
        app.runPre();
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
}
