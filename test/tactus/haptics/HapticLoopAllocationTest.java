package tactus.haptics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.management.ManagementFactory;
import java.util.concurrent.locks.LockSupport;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import tactus.haptics.emulator.BoardEmulator;
import tactus.haptics.emulator.Hand;

/** The haptic thread allocates nothing per tick (with an avatar that allocates nothing itself). */
public class HapticLoopAllocationTest {

    public static Thread loopThread() {
        for (Thread t : Thread.getAllStackTraces().keySet()) {
            if (t.getName().equals("tactus-haptic-loop")) {
                return t;
            }
        }
        return null;
    }

    @Test
    void steadyTicksAllocateNothing() {
        java.lang.management.ThreadMXBean base = ManagementFactory.getThreadMXBean();
        Assumptions.assumeTrue(base instanceof com.sun.management.ThreadMXBean, "no per-thread allocation counter");
        com.sun.management.ThreadMXBean mx = (com.sun.management.ThreadMXBean) base;
        Assumptions.assumeTrue(mx.isThreadAllocatedMemorySupported());
        mx.setThreadAllocatedMemoryEnabled(true);
        BoardEmulator emulator = new BoardEmulator(HaplyPreset.HAPLY_2018);
        emulator.setHand(Hand.scripted((t, out) -> {
            out[0] = 0.01 * Math.sin(t);
            out[1] = 0.08;
        }));
        try (Board board = new Board(emulator.connect())) {
            Device device = new Device((byte) 3, board);
            HaplyPreset.HAPLY_2018.configure(device);
            device.device_set_parameters();
            AvatarLink avatar = new AvatarLink() {
                double x;

                @Override
                public void setTarget(double px, double py, double pz) {
                    x = px;
                }

                @Override
                public void takeForce(double[] out) {
                    out[0] = -1e-4 * x;
                    out[1] = 1e-4;
                    out[2] = 0;
                }

                @Override
                public void step(int n) {
                }
            };
            HapticLoop loop = new HapticLoop(device, HaplyPreset.HAPLY_2018.newKinematics(), avatar);
            loop.start();
            Thread t = null;
            while (loop.ticks() < 2000 && loop.isRunning()) {   // warm up (JIT, buffers)
                LockSupport.parkNanos(1_000_000);
                if (t == null) {
                    t = loopThread();
                }
            }
            assertTrue(t != null && loop.isRunning(), String.valueOf(loop.failure()));
            // A per-tick allocation would show in every window (>= 16 bytes x 1000 ticks); rare one-off
            // allocations (JIT deoptimisation, buffer growth) may show in one. So: some window allocates 0.
            long[] windows = new long[5];
            for (int w = 0; w < windows.length; w++) {
                long ticks0 = loop.ticks();
                long bytes0 = mx.getThreadAllocatedBytes(t.getId());
                while (loop.ticks() < ticks0 + 1000 && loop.isRunning()) {
                    LockSupport.parkNanos(1_000_000);
                }
                windows[w] = mx.getThreadAllocatedBytes(t.getId()) - bytes0;
            }
            loop.stop();
            long best = Long.MAX_VALUE;
            for (long b : windows) {
                best = Math.min(best, b);
            }
            assertEquals(0, best, "bytes allocated by the haptic thread per 1000 ticks: " + java.util.Arrays.toString(windows));
        }
    }
}
