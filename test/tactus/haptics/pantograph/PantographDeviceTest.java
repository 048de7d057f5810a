package tactus.haptics.pantograph;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.locks.LockSupport;

import org.junit.jupiter.api.Test;

import tactus.haptics.emulator.BoardEmulator;
import tactus.haptics.emulator.Hand;
import tactus.haptics.AvatarLink;
import tactus.haptics.Board;
import tactus.haptics.BoardModel;
import tactus.haptics.Device;
import tactus.haptics.HaplyPreset;
import tactus.haptics.HapticDevice;
import tactus.haptics.HapticLoop;
import tactus.haptics.HapticTelemetry;

/**
 * The 2DIY through the common {@link HapticDevice} interface: position in metres from the kinematics, force in
 * newtons as J^T F, and a {@link HapticLoop} over it renders the same torques as the board path does.
 */
class PantographDeviceTest {

    @Test
    void positionInMetresAndForceInNewtonsAsTheBoardPathDoes() {
        BoardEmulator emulator = new BoardEmulator(HaplyPreset.HAPLY_2018);
        emulator.setHand(Hand.scripted((t, out) -> {
            out[0] = 0.01;
            out[1] = 0.08;
        }));
        try (Board board = new Board(emulator.connect())) {
            Device device = new Device((byte) 3, board);
            HaplyPreset.HAPLY_2018.configure(device);
            device.device_set_parameters();
            PantographDevice pd = new PantographDevice(device, HaplyPreset.HAPLY_2018.newKinematics());
            assertEquals(2, pd.dimensions());
            assertTrue(pd.isReady());
            pd.begin();
            pd.sendForce(0, 0, 0);
            assertTrue(pd.update());
            double[] p = new double[3];
            pd.position(p);
            assertEquals(0.01, p[0], 2e-4, "x in metres");
            assertEquals(0.08, p[1], 2e-4, "y in metres");
            assertEquals(0, p[2], 0);
            pd.sendForce(0.3, -0.2, 5);   // fz is ignored by a planar device
            PantographKinematics k = HaplyPreset.HAPLY_2018.newKinematics();
            double[] th = new double[2];
            assertTrue(k.inverse(p[0], p[1], th));
            k.forward(th[0], th[1]);
            double[] tau = new double[2];
            k.torques(0.3, -0.2, 1, tau);
            // the emulated motors render the duty the firmware computes from the torques: within one PWM count
            double count = BoardModel.MAX_TORQUE / 1023;
            assertEquals(tau[0], emulator.motorTorque(1), 2 * count + 0.002 * Math.abs(tau[0]));
            assertEquals(tau[1], emulator.motorTorque(2), 2 * count + 0.002 * Math.abs(tau[1]));
            pd.zeroForce();
            assertEquals(0, emulator.motorTorque(1), 0);
            assertEquals("-x,y,z", pd.defaultMapping().axes());
        }
    }

    @Test
    void aHapticLoopOverThePantographDeviceRendersTheBoardPathsForce() {
        BoardEmulator emulator = new BoardEmulator(HaplyPreset.HAPLY_2018);
        emulator.setHand(Hand.scripted((t, out) -> {
            out[0] = -0.01;
            out[1] = 0.09;
        }));
        try (Board board = new Board(emulator.connect())) {
            Device device = new Device((byte) 3, board);
            HaplyPreset.HAPLY_2018.configure(device);
            device.device_set_parameters();
            PantographDevice pd = new PantographDevice(device, HaplyPreset.HAPLY_2018.newKinematics());
            AvatarLink constant = new AvatarLink() {
                @Override
                public void setTarget(double x, double y, double z) {
                }

                @Override
                public void takeForce(double[] out) {
                    out[0] = 0.004;
                    out[1] = 0.002;
                    out[2] = 0.5;
                }

                @Override
                public void step(int n) {
                }
            };
            HapticLoop loop = new HapticLoop(pd, constant);   // default axes "-x,y,z", alpha 200, beta 100
            loop.start();
            long deadline = System.nanoTime() + 10_000_000_000L;
            while (loop.ticks() < 300 && loop.isRunning() && System.nanoTime() < deadline) {
                LockSupport.parkNanos(1_000_000);
            }
            double[] f = new double[3];
            loop.deviceForce(f);
            double[] p = new double[3];
            loop.devicePosition(p);
            loop.stop();
            assertTrue(loop.ticks() >= 300, String.valueOf(loop.failure()));
            // as the board path: (s beta Fx, beta Fy) with x mirrored; a planar device gets no z
            assertEquals(-100 * 0.004, f[0], 1e-12);
            assertEquals(100 * 0.002, f[1], 1e-12);
            assertEquals(0, f[2], 0);
            assertEquals(0.09, p[1], 2e-4);
            assertEquals(0, emulator.motorTorque(1), 0, "stop() zeroed the motors");
        }
    }

    /** A board with the 2018 preset, set up, its handle held at (x, y) metres by a scripted hand. */
    private static Device deviceAt(BoardEmulator emulator, double x, double y) {
        emulator.setHand(Hand.scripted((t, out) -> {
            out[0] = x;
            out[1] = y;
        }));
        Board board = new Board(emulator.connect());
        Device device = new Device((byte) 3, board);
        HaplyPreset.HAPLY_2018.configure(device);
        device.device_set_parameters();
        return device;
    }

    @Test
    void anUnreachablePoseIsAFreshFrameWhereNoForceIsRendered() {
        BoardEmulator emulator = new BoardEmulator(HaplyPreset.HAPLY_2018);
        Device device = deviceAt(emulator, 0.01, 0.08);
        try (Board board = device.board()) {
            for (double d : new double[] {0.02, 0.5}) {   // the preset's motor spacing, then one the arms cannot span
                PantographKinematics k = HaplyPreset.HAPLY_2018.newKinematics();
                k.setParameters(0.05, 0.07, d);
                PantographDevice pd = new PantographDevice(device, k);
                pd.begin();
                assertTrue(pd.update(), "a frame came (d = " + d + ")");
                boolean reachable = d < 0.1;
                assertEquals(reachable, pd.canRender(), "d = " + d);
                pd.sendForce(0.3, -0.2, 0);
                assertEquals(reachable ? 1 : 0, pd.renderedShare(), 0, "d = " + d);
                assertEquals(!reachable, pd.torque(1) == 0 && pd.torque(2) == 0, "d = " + d);
            }
        }
    }

    @Test
    void theTorqueLimitScalesTheRenderedShareAndIsCounted() {
        BoardEmulator emulator = new BoardEmulator(HaplyPreset.HAPLY_2018);
        Device device = deviceAt(emulator, 0.01, 0.08);
        try (Board board = device.board()) {
            PantographDevice pd = new PantographDevice(device, HaplyPreset.HAPLY_2018.newKinematics());
            pd.setTorqueGain(0.5);
            pd.setTorqueLimit(0.01);
            pd.begin();
            assertTrue(pd.update());
            for (double f : new double[] {0.001, 5}) {   // below the limit, then far above it
                long before = pd.limitedForces();
                pd.sendForce(f, f, 0);
                double m = Math.max(Math.abs(pd.torque(1)), Math.abs(pd.torque(2)));
                if (m < 0.01 - 1e-12) {
                    assertEquals(0.5, pd.renderedShare(), 0, "below the limit: the gain alone");
                    assertEquals(before, pd.limitedForces());
                } else {
                    assertEquals(0.01, m, 1e-12, "the larger torque at the limit");
                    assertTrue(pd.renderedShare() < 0.5 && pd.renderedShare() > 0, "scaled: " + pd.renderedShare());
                    assertEquals(before + 1, pd.limitedForces());
                }
            }
            assertEquals(1, pd.limitedForces(), "one of the two forces was clipped");
        }
    }

    @Test
    void aLoopOnADeviceTakesItsClipsAndJointTorquesFromItsPantograph() {
        for (double limit : new double[] {0.123, 0.005}) {
            BoardEmulator emulator = new BoardEmulator(HaplyPreset.HAPLY_2018);
            Device device = deviceAt(emulator, 0.01, 0.08);
            AvatarLink push = new AvatarLink() {
                @Override
                public void setTarget(double x, double y, double z) {
                }

                @Override
                public void takeForce(double[] out) {
                    out[0] = 0.002;   // 0.2 N per axis with beta 100
                    out[1] = 0.002;
                    out[2] = 0;
                }

                @Override
                public void step(int n) {
                }
            };
            HapticLoop loop = new HapticLoop(device, HaplyPreset.HAPLY_2018.newKinematics(), push);
            loop.setTorqueLimit(limit);
            try {
                loop.start();
                long deadline = System.nanoTime() + 10_000_000_000L;
                while (loop.ticks() < 100 && loop.isRunning() && System.nanoTime() < deadline) {
                    LockSupport.parkNanos(1_000_000);
                }
                HapticTelemetry tm = loop.telemetry();
                double m = Math.max(Math.abs(loop.torque(1)), Math.abs(loop.torque(2)));
                assertTrue(tm.ticks >= 100, String.valueOf(loop.failure()));
                assertTrue(m > 0, "torques were sent");
                if (limit < 0.1) {
                    assertEquals(limit, m, 1e-9, "the loop's torque limit reached its pantograph");
                    assertTrue(tm.clampedTicks > 0, "clipped ticks counted");
                } else {
                    assertTrue(m < limit, "below the firmware's limit: " + m);
                    assertEquals(0, tm.clampedTicks, "nothing clipped");
                }
                assertNull(loop.hapticDevice(), "a loop built on a Device shows no HapticDevice, as before");
            } finally {
                loop.close();
            }
        }
    }

    @Test
    void thePositionQuantumBoundsTheStepOneCountOfEachEncoderMakesAtThePose() {
        BoardEmulator emulator = new BoardEmulator(HaplyPreset.TWO_DIY_V3, BoardModel.M3);
        long t0 = System.nanoTime();
        emulator.setHand(Hand.scripted((t, out) -> {   // 10 mm/s along y, then along x, by the wall clock
            double s = (System.nanoTime() - t0) * 1e-9;
            out[0] = s < 0.3 ? 0 : 0.01 * (s - 0.3);
            out[1] = 0.08 + 0.01 * Math.min(s, 0.3);
        }));
        try (Board board = new Board(emulator.connect(), BoardModel.M3)) {
            Device device = new Device((byte) 5, board);
            HaplyPreset.TWO_DIY_V3.configure(device);
            device.device_set_parameters();
            PantographDevice pd = new PantographDevice(device, HaplyPreset.TWO_DIY_V3.newKinematics());
            double[] q = new double[3];
            pd.positionQuantum(q);
            assertEquals(0, q[0] + q[1] + q[2], 0, "no quantum before the first pose");
            double[] p = new double[3];
            double[] last = null;
            double lastTh1 = Double.NaN;
            double lastTh2 = Double.NaN;
            double c1 = 360.0 / device.resolution(1);   // one count, degrees
            double c2 = 360.0 / device.resolution(2);
            double[] largest = new double[2];
            double[] ratio = new double[2];   // the largest one-count step over the quantum at its pose
            int oneCount = 0;
            while (System.nanoTime() - t0 < 600_000_000L) {
                pd.begin();
                pd.sendForce(0, 0, 0);
                if (!pd.update()) {
                    continue;
                }
                pd.position(p);
                pd.positionQuantum(q);
                assertEquals(0, q[2], 0, "a planar device has no z quantum");
                double th1 = device.angle(1);
                double th2 = device.angle(2);
                if (last != null) {
                    long n1 = Math.round(Math.abs(th1 - lastTh1) / c1);
                    long n2 = Math.round(Math.abs(th2 - lastTh2) / c2);
                    if (n1 <= 1 && n2 <= 1 && n1 + n2 >= 1) {   // at most one count of each encoder between these
                        oneCount++;
                        for (int i = 0; i < 2; i++) {
                            double step = Math.abs(p[i] - last[i]);
                            assertTrue(q[i] > 0, "axis " + i + ": a quantum at a reachable pose");
                            assertTrue(step <= 1.02 * q[i], "axis " + i + ": one count moved " + step * 1e6
                                    + " um, above the quantum " + q[i] * 1e6 + " um");
                            largest[i] = Math.max(largest[i], step);
                            ratio[i] = Math.max(ratio[i], step / q[i]);
                        }
                    }
                }
                last = p.clone();
                lastTh1 = th1;
                lastTh2 = th2;
            }
            assertTrue(oneCount >= 5, "readings one count apart: " + oneCount);
            for (int i = 0; i < 2; i++) {
                // at the poses crossed, one count of one encoder moves each axis by about half the quantum
                assertTrue(ratio[i] >= 0.4, "axis " + i + ": the largest one-count step, " + largest[i] * 1e6
                        + " um, is " + ratio[i] + " quanta: the quantum overstates the step");
            }
            assertTrue(largest[1] > 60e-6 && largest[1] < 200e-6, "a 2DIY count moves the handle 70-170 um: "
                    + largest[1] * 1e6 + " um");
        }
    }
}
