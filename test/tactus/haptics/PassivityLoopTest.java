package tactus.haptics;

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
            assertThrows(IllegalStateException.class, () -> loop.setVirtualCoupling(null), "coupling only before start");
            Thread t = null;
            while (loop.ticks() < 2000 && loop.isRunning()) {
                LockSupport.parkNanos(1_000_000);
                if (t == null) {
                    t = HapticLoopAllocationTest.loopThread();
                }
            }
            assertTrue(t != null && loop.isRunning(), String.valueOf(loop.failure()));
            long[] windows = new long[5];
            for (int w = 0; w < windows.length; w++) {
                long bytes0 = mx.getThreadAllocatedBytes(t.getId());
                waitTicks(loop, 1000);
                windows[w] = mx.getThreadAllocatedBytes(t.getId()) - bytes0;
            }
            long best = Long.MAX_VALUE;
            for (long b : windows) {
                best = Math.min(best, b);
            }
            assertEquals(0, best, "bytes per 1000 ticks with every option on: " + java.util.Arrays.toString(windows));
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
        }
    }
}
