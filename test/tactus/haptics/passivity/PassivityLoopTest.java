package tactus.haptics.passivity;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.management.ManagementFactory;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import tactus.haptics.emulator.BoardEmulator;
import tactus.haptics.emulator.Hand;
import tactus.haptics.AvatarLink;
import tactus.haptics.Board;
import tactus.haptics.BoardModel;
import tactus.haptics.Device;
import tactus.haptics.HaplyPreset;
import tactus.haptics.HapticDevice;
import tactus.haptics.HapticLoop;
import tactus.haptics.HapticLoopAllocationTest;
import tactus.haptics.NoForceAvatar;
import tactus.haptics.WorkspaceMapping;

/**
 * The passivity observer and controller, the virtual coupling and the friction compensation inside a running
 * {@link HapticLoop} on the board emulator: the switches, the published figures, no allocation on the haptic thread.
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class PassivityLoopTest {

    private static void waitTicks(HapticLoop loop, long n) {
        long end = loop.ticks() + n;
        while (loop.ticks() < end && loop.isRunning()) {
            LockSupport.parkNanos(1_000_000);
        }
    }

    /** A stiff spring to x = 0 (model units, 1 N per model unit of force at beta 1). */
    private static final class Spring implements AvatarLink {
        double x;

        @Override
        public void setTarget(double px, double py, double pz) {
            x = px;
        }

        @Override
        public void takeForce(double[] out) {
            out[0] = -2000 * x;
            out[1] = 0;
            out[2] = 0;
        }

        @Override
        public void step(int n) {
        }
    }

    @Test
    void theLoopObservesControlsAndAllocatesNothing() {
        java.lang.management.ThreadMXBean base = ManagementFactory.getThreadMXBean();
        Assumptions.assumeTrue(base instanceof com.sun.management.ThreadMXBean, "no per-thread allocation counter");
        com.sun.management.ThreadMXBean mx = (com.sun.management.ThreadMXBean) base;
        Assumptions.assumeTrue(mx.isThreadAllocatedMemorySupported());
        mx.setThreadAllocatedMemoryEnabled(true);
        BoardEmulator emulator = new BoardEmulator(HaplyPreset.HAPLY_2018);
        emulator.setHand(Hand.scripted((t, out) -> {
            out[0] = 0.01 * Math.sin(6 * t);   // the hand sweeps through the spring's rest point
            out[1] = 0.08;
        }));
        try (Board board = new Board(emulator.connect())) {
            Device device = new Device((byte) 3, board);
            HaplyPreset.HAPLY_2018.configure(device);
            device.device_set_parameters();
            HapticLoop loop = new HapticLoop(device, HaplyPreset.HAPLY_2018.newKinematics(), new Spring());
            loop.useRealUnits();
            loop.setVirtualCoupling(VirtualCoupling.forDevice(0.5, 1e-3, 1));
            loop.setFrictionCompensation(new FrictionCompensation(0.05));
            loop.setPassivityControl(true);
            loop.start();
            // couplings made on this thread, switched in and out while the loop runs (every window below switches)
            VirtualCoupling grip = VirtualCoupling.forContacts(400, 0.1, 20_000, 1e-3);
            VirtualCoupling forDevice = loop.virtualCoupling();
            Thread t = null;
            // warm up (JIT, buffers) longer than HapticLoopAllocationTest: more code runs per tick with every option on,
            // and on a loaded machine its compilation was seen to allocate in the first windows
            while (loop.ticks() < 5000 && loop.isRunning()) {
                LockSupport.parkNanos(1_000_000);
                if (t == null) {
                    t = HapticLoopAllocationTest.loopThread();
                }
            }
            assertTrue(t != null && loop.isRunning(), String.valueOf(loop.failure()));
            long[] windows = new long[8];
            for (int w = 0; w < windows.length; w++) {
                long bytes0 = mx.getThreadAllocatedBytes(t.getId());
                loop.setVirtualCoupling(w % 3 == 0 ? null : w % 3 == 1 ? grip : forDevice);
                waitTicks(loop, 1000);
                windows[w] = mx.getThreadAllocatedBytes(t.getId()) - bytes0;
            }
            long best = Long.MAX_VALUE;
            long bestSwitchedIn = Long.MAX_VALUE;   // the windows that began by switching a coupling in
            for (int w = 0; w < windows.length; w++) {
                best = Math.min(best, windows[w]);
                if (w % 3 != 0) {
                    bestSwitchedIn = Math.min(bestSwitchedIn, windows[w]);
                }
            }
            assertEquals(0, bestSwitchedIn, "bytes in a window that switched a coupling in: "
                    + java.util.Arrays.toString(windows));
            assertEquals(0, best, "bytes per 1000 ticks with every option on, the coupling switched in each: "
                    + java.util.Arrays.toString(windows));
            assertTrue(loop.isRunning(), "the loop ran on through the switches: " + loop.failure());
            assertSame(grip, loop.virtualCoupling(), "the last coupling set");
            PassivityObserver o = loop.passivity();
            assertTrue(o.ticks() > 5000, "observed ticks: " + o.ticks());
            assertTrue(o.energyIn() > 0 && Double.isFinite(o.energyIn()), "the hand pushed energy in: " + o);
            assertTrue(Double.isFinite(o.netEnergy()), o.toString());
            // switched off at run time: the controller stops adding damping
            loop.setPassivityControl(false);
            assertFalse(loop.isPassivityControl());
            waitTicks(loop, 5);
            long active = o.activeTicks();
            waitTicks(loop, 500);
            assertEquals(active, o.activeTicks(), "no damping while off");
            assertEquals(0, o.damping(), 0);
            loop.setFrictionCompensation(null);
            assertNull(loop.frictionCompensation());
            loop.stop();
        }
    }

    /** A model that pushes nothing and records, on the loop's thread, the largest torque the loop sent. */
    private static final class FreeSpace extends NoForceAvatar {
        volatile HapticLoop loop;
        double worst;   // N m, written by the loop's thread only

        @Override
        public void setTarget(double px, double py, double pz) {
            HapticLoop l = loop;
            if (l != null) {
                worst = Math.max(worst, Math.max(Math.abs(l.torque(1)), Math.abs(l.torque(2))));
            }
        }
    }

    @Test
    void aCouplingSwitchedWhileTheLoopRunsStartsWithoutAForceStep() {
        // lockstep (each write is 1 ms of the plant's time): a pen grip sweeps the 2DIY's handle 2 cm up and down while
        // the test thread switches a stiff coupling in, out and in again; the model pushes nothing, so every torque
        // comes from the coupling. Bumpless, the proxy starts at the handle each time and the torques stay at what the
        // encoders' steps give; a proxy left where it was would pull with 800 N/m over centimetres: the torque limit.
        // The passivity controller is on with a 1 mJ tolerance, as recommended for this coupling: with no tolerance it
        // chases the energy the encoders' steps seem to create and bursts to the limit, switched or not
        // (docs/haptics-stability.md, "Passivity control").
        HaplyPreset preset = HaplyPreset.TWO_DIY_V3;
        BoardEmulator em = new BoardEmulator(preset, BoardModel.M3);
        em.setLockstep(1e-3);
        em.setPlant(tactus.haptics.emulator.PlantParameters.twoDiy());
        double x0 = preset.d() / 2;
        double y0 = 0.09;
        assertTrue(em.place(x0, y0));
        double t0 = em.time();
        em.setHand(Hand.grasp((t, out) -> {
            out[0] = x0;
            out[1] = y0 + 0.02 * Math.sin(2 * Math.PI * 0.5 * (t - t0));
        }, 0.03, 300, 2));
        FreeSpace model = new FreeSpace();
        VirtualCoupling coupling = VirtualCoupling.forContacts(800, 1, 20_000, 1e-3);
        try (Board board = new Board(em.connect(), BoardModel.M3)) {
            board.setTorqueWatchdogMillis(0);
            Device device = new Device((byte) 5, board);
            preset.configure(device);
            device.device_set_parameters();
            HapticLoop loop = new HapticLoop(device, preset.newKinematics(), model);
            loop.useRealUnits();
            loop.setExchangeDelay(1);
            loop.setPassivityControl(true);
            loop.setPassivityTolerance(1e-3);
            loop.setRate(1000);   // the loop's own port integrates the proxy at the loop's period: the plant's 1 ms
            loop.setWatchdogMillis(60_000);
            loop.setLinkTimeoutMillis(60_000);
            model.loop = loop;
            loop.start();
            long[] at = {300, 700, 1100, 1600};
            VirtualCoupling[] set = {coupling, null, coupling, null};
            for (int i = 0; i < at.length; i++) {
                while (loop.ticks() < at[i] && loop.isRunning()) {
                    LockSupport.parkNanos(50_000);
                }
                loop.setVirtualCoupling(set[i]);
                assertSame(set[i], loop.virtualCoupling());
            }
            waitTicks(loop, 100);
            assertTrue(loop.isRunning(), "the loop ran through the switches: " + loop.failure());
            loop.stop();
        }
        // 0.123 N m is the firmware's clip; the encoders' steps through an 800 N/m, 1 N s/m coupling give ~0.01 N m
        assertTrue(model.worst > 0, "the coupling pulled at all: " + model.worst);
        assertTrue(model.worst < 0.04, "largest torque " + model.worst + " N m (a stale proxy saturates at 0.123)");
    }

    /**
     * A 3-DoF device that moves along a scripted path, one step per update, and records the work of the forces it was
     * sent: the force sent after reading position k acts until position k + 1.
     */
    private static final class ScriptedDevice implements HapticDevice {
        final double[] p = new double[3];
        long k;
        double fx;
        double fy;
        double fz;
        volatile double work;   // J, the work of the held forces on the handle, as the observer should count it
        volatile long updates;

        @Override
        public int dimensions() {
            return 3;
        }

        @Override
        public boolean isReady() {
            return true;
        }

        @Override
        public void begin() {
        }

        @Override
        public boolean update() {
            double t = ++k * 1e-3;
            double x = 0.01 * Math.sin(7 * t);
            double y = 0.005 * Math.sin(3 * t);
            double z = 0.004 * Math.cos(5 * t);
            work += fx * (x - p[0]) + fy * (y - p[1]) + fz * (z - p[2]);
            p[0] = x;
            p[1] = y;
            p[2] = z;
            updates = k;
            return true;
        }

        @Override
        public void position(double[] out) {
            System.arraycopy(p, 0, out, 0, 3);
        }

        @Override
        public void velocity(double[] out) {
            java.util.Arrays.fill(out, 0);
        }

        @Override
        public void sendForce(double x, double y, double z) {
            fx = x;
            fy = y;
            fz = z;
        }

        @Override
        public void zeroForce() {
        }

        @Override
        public WorkspaceMapping defaultMapping() {
            return WorkspaceMapping.identity();
        }

        @Override
        public String describe() {
            return "scripted 3-DoF device";
        }

        @Override
        public String status() {
            return "ok";
        }

        @Override
        public void close() {
        }
    }

    /** A spring to the origin in all three axes (force per model unit, beta 1). */
    private static final class Spring3 implements AvatarLink {
        final double[] x = new double[3];

        @Override
        public void setTarget(double px, double py, double pz) {
            x[0] = px;
            x[1] = py;
            x[2] = pz;
        }

        @Override
        public void takeForce(double[] out) {
            out[0] = -50 * x[0];
            out[1] = -80 * x[1];
            out[2] = -30 * x[2];
        }

        @Override
        public void step(int n) {
        }
    }

    @Test
    void onAThreeDofDeviceTheObserverCountsTheWorkTheDeviceSaw() {
        ScriptedDevice dev = new ScriptedDevice();
        HapticLoop loop = new HapticLoop(dev, new Spring3());
        loop.useRealUnits();
        loop.start();
        waitTicks(loop, 600);
        loop.stop();   // the loop thread has ended: both sides are final
        PassivityObserver o = loop.passivity();
        assertTrue(dev.updates > 500, "ticks: " + dev.updates);
        assertTrue(Math.abs(dev.work) > 1e-7, "the exchange is not trivial: " + dev.work + " J");
        // the observer counts -F(k) . (x(k+1) - x(k)) for every reading after the first, as the device did (the
        // device's first step started from the origin, before any force: zero work)
        assertEquals(-dev.work, o.netEnergy(), 1e-9 * Math.abs(dev.work) + 1e-15, o.toString());
        assertEquals(dev.updates - 1, o.ticks(), "one record per reading after the first");
    }

    @Test
    void settingsAreValidatedAndKept() {
        BoardEmulator emulator = new BoardEmulator(HaplyPreset.HAPLY_2018);
        try (Board board = new Board(emulator.connect())) {
            Device device = new Device((byte) 3, board);
            HapticLoop loop = new HapticLoop(device, HaplyPreset.HAPLY_2018.newKinematics(), new Spring());
            assertFalse(loop.isPassivityControl(), "off by default");
            assertNull(loop.virtualCoupling());
            assertEquals(PassivityController.DEFAULT_DAMPING_LIMIT, loop.passivityDampingLimit(), 0);
            assertTrue(assertThrows(IllegalArgumentException.class, () -> loop.setPassivityDampingLimit(-2))
                    .getMessage().contains("-2"));
            assertTrue(assertThrows(IllegalArgumentException.class, () -> loop.setExchangeDelay(9))
                    .getMessage().contains("9"));
            VirtualCoupling c = new VirtualCoupling(300, 0.1, 0.01);
            loop.setVirtualCoupling(c);
            assertSame(c, loop.virtualCoupling());
            loop.setExchangeDelay(1);
            assertEquals(1, loop.exchangeDelay());
            loop.setPassivityDampingLimit(20);
            assertEquals(20, loop.passivityDampingLimit(), 0);
            assertEquals(PassivityController.DEFAULT_RESERVE_LIMIT, loop.passivityReserveLimit(), 0);
            assertTrue(assertThrows(IllegalArgumentException.class, () -> loop.setPassivityReserveLimit(-0.5))
                    .getMessage().contains("-0.5"));
            assertThrows(IllegalArgumentException.class, () -> loop.setPassivityReserveLimit(Double.NaN));
            loop.setPassivityReserveLimit(Double.POSITIVE_INFINITY);
            assertEquals(Double.POSITIVE_INFINITY, loop.passivityReserveLimit(), 0);
            assertEquals(0, loop.passivityTolerance(), 0, "no tolerance by default");
            assertTrue(assertThrows(IllegalArgumentException.class, () -> loop.setPassivityTolerance(-1e-3))
                    .getMessage().contains("-0.001"));
            assertThrows(IllegalArgumentException.class, () -> loop.setPassivityTolerance(Double.POSITIVE_INFINITY));
            loop.setPassivityTolerance(1e-3);
            assertEquals(1e-3, loop.passivityTolerance(), 0);
            assertTrue(assertThrows(IllegalArgumentException.class, () -> VirtualCoupling.forContacts(400, 0.1, -3, 1e-3))
                    .getMessage().contains("-3"));
        }
    }
}
