package tactus.haptics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.ServerSocket;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

import tactus.PhysicalModel;
import tactus.Vect3D;
import tactus.haptics.emulator.Hand3D;
import tactus.haptics.emulator.InverseServiceEmulator;
import tactus.haptics.emulator.SimulatedInverse3;
import tactus.haptics.inverse.Inverse3Device;

/** Discovery and banner of the 3-D session, and a 3-D model touched through it. */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class HapticSession3DTest {

    private static HapticSession3D openWith(String uri) {
        String old = System.getProperty("tactus.haptics.inverse.uri");
        System.setProperty("tactus.haptics.inverse.uri", uri);
        try {
            return HapticSession3D.open(null);
        } finally {
            if (old == null) {
                System.clearProperty("tactus.haptics.inverse.uri");
            } else {
                System.setProperty("tactus.haptics.inverse.uri", old);
            }
        }
    }

    @Test
    void aServiceWithAnInverse3IsFoundFirstAndNamed() {
        try (InverseServiceEmulator service = InverseServiceEmulator.start(0);
             HapticSession3D s = openWith(service.uri().toString())) {
            assertTrue(s.device() instanceof Inverse3Device);
            assertEquals(null, s.emulator(), "a service was found: no in-process emulator");
            assertTrue(s.status().startsWith("Haply inverse3 through the Inverse Service at " + service.uri()), s.status());
        }
    }

    @Test
    void withNoServiceAndNoBoardTheEmulatorIsUsedAndSaysWhy() throws Exception {
        int port;
        try (ServerSocket free = new ServerSocket(0)) {
            port = free.getLocalPort();
        }
        try (HapticSession3D s = openWith("ws://localhost:" + port)) {
            assertNotNull(s.emulator());
            assertTrue(s.isEmulated());
            assertTrue(s.status().contains("emulated Inverse3, the mouse is your hand"), s.status());
            assertTrue(s.status().startsWith("No Haply Inverse Service at ws://localhost:" + port), s.status());
        }
    }

    @Test
    void aModelIsTouchedInThreeDimensionsThroughTheSession() {
        try (HapticSession3D s = HapticSession3D.openEmulated(null)) {
            assertTrue(s.status().startsWith("Emulated Inverse3 (asked for)"), s.status());
            double[] lo = new double[3];
            double[] hi = new double[3];
            s.workspace(lo, hi);
            assertTrue(hi[0] - lo[0] > 100 && hi[1] - lo[1] > 100 && hi[2] - lo[2] > 100, "pixels, all three axes");
            Vect3D home = s.home();
            assertEquals(HapticSession.DEFAULT_WIDTH / 2.0, home.x, 1, "the handle starts in the middle of the window");
            assertEquals(HapticSession.DEFAULT_HEIGHT / 2.0, home.y, 1);
            assertEquals(0, home.z, 1);
            PhysicalModel pm = new PhysicalModel(1000);
            pm.addHapticInput3D("avatar", home, 1);
            pm.init();
            HapticLoop loop = s.attach(pm, "avatar");
            loop.start();
            double[] min = {Double.MAX_VALUE, Double.MAX_VALUE, Double.MAX_VALUE};
            double[] max = {-Double.MAX_VALUE, -Double.MAX_VALUE, -Double.MAX_VALUE};
            double[] target = new double[3];
            long t0 = System.nanoTime();
            for (int k = 0; k < 60; k++) {
                s.idleTourTarget(k * 0.2, target);     // 12 s of the tour, in 3 s
                s.emulator().device().hand().setTarget(target[0], target[1], target[2]);
                LockSupport.parkNanos(50_000_000);
                Vect3D p = pm.getMatPosition("avatar");
                min[0] = Math.min(min[0], p.x);
                min[1] = Math.min(min[1], p.y);
                min[2] = Math.min(min[2], p.z);
                max[0] = Math.max(max[0], p.x);
                max[1] = Math.max(max[1], p.y);
                max[2] = Math.max(max[2], p.z);
            }
            assertTrue(loop.isRunning(), String.valueOf(loop.failure()));
            for (int i = 0; i < 3; i++) {
                assertTrue(max[i] - min[i] > 0.5 * (hi[i] - lo[i]), "the avatar swept axis " + i + ": " + min[i] + ".." + max[i]);
            }
            assertTrue(System.nanoTime() - t0 < 30_000_000_000L);
        }
    }

    @Test
    void theVerseGripIsReadable() {
        try (InverseServiceEmulator service = InverseServiceEmulator.start(0)) {
            service.setVerseGrip("wireless_verse_grip");
            service.device().setHand(Hand3D.scripted((t, out) -> System.arraycopy(SimulatedInverse3.HOME, 0, out, 0, 3)));
            try (HapticSession3D s = openWith(service.uri().toString())) {
                HapticLoop loop = s.attach(new PhysicalModelAvatar(model(), "avatar"));
                loop.start();
                service.setButtons(false, true, false);
                service.setGripOrientation(0, 0, 0, 1);
                long deadline = System.nanoTime() + 5_000_000_000L;
                while (!s.button(1) && System.nanoTime() < deadline) {
                    LockSupport.parkNanos(1_000_000);
                }
                assertTrue(s.hasGrip());
                assertTrue(s.button(1));
                double[] q = new double[4];
                s.gripOrientation(q);
                assertEquals(1, q[3], 1e-12);
            }
        }
    }

    private static PhysicalModel model() {
        PhysicalModel pm = new PhysicalModel(1000);
        pm.addHapticInput3D("avatar", new Vect3D(400, 300, 0), 1);
        pm.init();
        return pm;
    }

    @Test
    void anEmulatedSessionsLoopOutlivesAnEmulatorHeldBackForASecond() {
        try (HapticSession3D s = HapticSession3D.openEmulated(null)) {
            PhysicalModel pm = new PhysicalModel(1000);
            pm.addHapticInput3D("avatar", s.home(), 1);
            pm.init();
            HapticLoop loop = s.attach(pm, "avatar");
            loop.start();
            long t = System.nanoTime() + 20_000_000_000L;
            while (loop.ticks() < 100 && System.nanoTime() < t) {
                LockSupport.parkNanos(1_000_000);
            }
            s.emulator().setMute(true);     // no answers for a second: what a loaded machine can do to it
            LockSupport.parkNanos(1_000_000_000L);
            s.emulator().setMute(false);
            long ticks = loop.ticks();
            while (loop.ticks() < ticks + 100 && System.nanoTime() < t) {
                LockSupport.parkNanos(1_000_000);
            }
            assertEquals(null, loop.failure(), "the loop on the emulator waits longer than 500 ms for its answers");
            assertTrue(loop.isRunning());
        }
    }

    @Test
    void aPairOfEmulatedHandsDrivesTwoDevicesEachThroughItsOwnSession() {
        HapticSession3D[] pair = HapticSession3D.openEmulatedPair(null);
        try {
            assertEquals("left", ((Inverse3Device) pair[0].device()).handedness());
            assertEquals("right", ((Inverse3Device) pair[1].device()).handedness());
            assertEquals(HapticSession3D.LEFT_ID, ((Inverse3Device) pair[0].device()).deviceId());
            assertEquals(InverseServiceEmulator.DEVICE_ID, ((Inverse3Device) pair[1].device()).deviceId());
            assertTrue(pair[0].emulator() == pair[1].emulator(), "one emulator serves both");
            // each emulated hand is moved apart; each session's model avatar follows its own hand
            double[] h = SimulatedInverse3.HOME;
            pair[0].emulator().device(HapticSession3D.LEFT_ID).hand().setTarget(h[0] - 0.05, h[1], h[2]);
            pair[1].emulator().device().hand().setTarget(h[0] + 0.05, h[1], h[2]);
            PhysicalModel pm = new PhysicalModel(1000);
            pm.addHapticInput3D("left", pair[0].home(), 1);
            pm.addHapticInput3D("right", pair[1].home(), 1);
            pm.init();
            HapticLoop r = pair[1].attach(pm, "right");
            HapticLoop l = pair[0].attach(pm, "left");
            l.setMode(HapticLoop.Mode.AUDIO);
            r.start();
            l.start();
            long t = System.nanoTime() + 20_000_000_000L;
            while ((pm.getMatPosition("right").x - pm.getMatPosition("left").x) < 50 && System.nanoTime() < t) {
                LockSupport.parkNanos(5_000_000);
            }
            assertTrue(pm.getMatPosition("right").x - pm.getMatPosition("left").x >= 50,
                    "the avatars are 0.1 m apart in the device, some hundred pixels on screen: "
                    + pm.getMatPosition("left") + " " + pm.getMatPosition("right"));
        } finally {
            pair[1].close();
            pair[0].close();
        }
    }
}
