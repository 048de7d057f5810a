package tactus.haptics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

import tactus.PhysicalModel;
import tactus.Vect3D;
import tactus.haptics.emulator.Hand3D;
import tactus.haptics.emulator.InverseServiceEmulator;
import tactus.haptics.emulator.SimulatedInverse3;
import tactus.haptics.inverse.PlanarInverse3;

/** A 2-D sketch's session finds an Inverse3 first and drives it in its vertical plane, the depth free. */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class HapticSessionOnInverse3Test {
    private static final double[] H = SimulatedInverse3.HOME;

    @Test
    void aTwoDSketchRunsUnchangedOnAnInverse3WithItsDepthFree() {
        try (InverseServiceEmulator service = InverseServiceEmulator.start(0)) {
            double[] where = H.clone();
            service.device().setHand(Hand3D.scripted((t, out) -> System.arraycopy(where, 0, out, 0, 3)));
            service.setRecording(true);
            String old = System.getProperty("tactus.haptics.inverse.uri");
            System.setProperty("tactus.haptics.inverse.uri", service.uri().toString());
            HapticSession s;
            try {
                s = HapticSession.open(null);     // exactly what a 2-D sketch calls
            } finally {
                if (old == null) {
                    System.clearProperty("tactus.haptics.inverse.uri");
                } else {
                    System.setProperty("tactus.haptics.inverse.uri", old);
                }
            }
            try {
                assertNull(s.device(), "no 2DIY device");
                assertTrue(s.hapticDevice() instanceof PlanarInverse3);
                assertTrue(s.status().startsWith("Haply inverse3 through the Inverse Service"), s.status());
                assertTrue(s.status().contains("the depth is free"), s.status());
                Vect3D home = s.home();
                assertEquals(HapticSession.DEFAULT_WIDTH / 2.0, home.x, 1, "the handle's home is the window's middle");
                assertEquals(HapticSession.DEFAULT_HEIGHT / 2.0, home.y, 1);
                // a spring from the avatar to a fixed point: a 2-D scene
                PhysicalModel pm = new PhysicalModel(1000);
                pm.addHapticInput3D("avatar", home, 1);
                pm.addGround3D("anchor", new Vect3D(home.x, home.y, 0));
                pm.addSpring3D("spring", 0, 0.0005, "avatar", "anchor");   // about 5 N at 3 cm (beta 100 N per unit)
                pm.init();
                HapticLoop loop = s.attach(pm, "avatar");
                loop.start();
                // the hand moves right (device +x), up (device +z) and away (device +y, the free depth)
                where[0] = H[0] + 0.03;
                where[1] = H[1] + 0.04;
                where[2] = H[2] + 0.02;
                long deadline = System.nanoTime() + 10_000_000_000L;
                while (loop.ticks() < 600 && loop.isRunning() && System.nanoTime() < deadline) {
                    LockSupport.parkNanos(2_000_000);
                }
                assertTrue(loop.ticks() >= 600, String.valueOf(loop.failure()));
                Vect3D p = pm.getMatPosition("avatar");
                double a = s.positionGain();
                assertEquals(home.x + a * 0.03, p.x, 1, "device right is screen right");
                assertEquals(home.y - a * 0.02, p.y, 1, "device up is screen up");
                assertEquals(0, p.z, 1e-9, "the depth does not reach the 2-D model");
                List<double[]> f = service.receivedForces();
                double[] last = f.get(f.size() - 1);
                assertEquals(0, last[1], 0, "the depth gets no force: it is free");
                assertTrue(last[0] < 0, "the spring pulls the hand back left: " + last[0]);
                assertTrue(last[2] < 0, "and back down: " + last[2]);
            } finally {
                s.close();
            }
            long deadline = System.nanoTime() + 2_000_000_000L;
            // every session gone: the sketch's and its guard's (either may end first)
            while ((service.zeroedOnDisconnect() == 0 || service.openConnections() > 0) && System.nanoTime() < deadline) {
                LockSupport.parkNanos(1_000_000);
            }
            List<double[]> f = service.receivedForces();
            double[] last = f.get(f.size() - 1);
            assertEquals(0, last[0] * last[0] + last[1] * last[1] + last[2] * last[2], 0, "closing the session sent zero force");
        }
    }
}
