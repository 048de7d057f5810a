package tactus.haptics;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.management.ManagementFactory;
import java.util.concurrent.locks.LockSupport;
import org.junit.jupiter.api.Test;
import tactus.haptics.emulator.BoardEmulator;

/**
 * Reading the telemetry copies no window: a sketch may read it every frame, or a tool every 2 ms, without making
 * the garbage whose collection pauses the haptic loop (a copy of the two 65,536-tick windows was 1 MB a read).
 */
class TelemetryReadTest {

    @Test
    void aTelemetryReadAllocatesOnlyItsResult() {
        com.sun.management.ThreadMXBean mx = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        assertTrue(mx.isThreadAllocatedMemorySupported(), "the JVM counts allocated bytes per thread");
        mx.setThreadAllocatedMemoryEnabled(true);
        BoardEmulator emulator = new BoardEmulator(HaplyPreset.HAPLY_2018);
        try (Board board = new Board(emulator.connect())) {
            Device device = new Device((byte) 3, board);
            HaplyPreset.HAPLY_2018.configure(device);
            device.device_set_parameters();
            HapticLoop loop = new HapticLoop(device, HaplyPreset.HAPLY_2018.newKinematics(), new NoForceAvatar());
            loop.start();
            long deadline = System.nanoTime() + 20_000_000_000L;
            while (loop.ticks() < 300 && loop.isRunning() && System.nanoTime() < deadline) {
                LockSupport.parkNanos(1_000_000);
            }
            assertTrue(loop.ticks() >= 300, "the loop ticks: " + loop.failure());
            for (int i = 0; i < 50; i++) {
                loop.telemetry();                       // warm up
            }
            long me = Thread.currentThread().getId();
            long best = Long.MAX_VALUE;
            for (int round = 0; round < 5; round++) {
                long before = mx.getThreadAllocatedBytes(me);
                HapticTelemetry t = null;
                for (int i = 0; i < 100; i++) {
                    t = loop.telemetry();
                }
                long perRead = (mx.getThreadAllocatedBytes(me) - before) / 100;
                best = Math.min(best, perRead);
                assertTrue(t.jitterP50Us <= t.jitterP99Us && t.jitterP99Us <= t.jitterMaxUs + 1e-9, t.toString());
            }
            // the result object is about 150 bytes; a copy of one window alone would be 512 KiB
            assertTrue(best <= 1024, "bytes allocated per telemetry() read: " + best);
            loop.stop();
        }
    }
}
