package tactus.haptics;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.locks.Lock;
import java.util.concurrent.locks.LockSupport;
import org.junit.jupiter.api.Test;
import tactus.PhysicalModel;
import tactus.Vect3D;
import tactus.haptics.emulator.BoardEmulator;

/**
 * A thread that holds the model's lock (a {@code draw()} reading positions, preempted by a busy machine while it
 * holds it) must not hold up the haptic loop in haptics-only mode: the loop thread is the model's one stepping
 * thread and takes no lock. Before, every tick waited for the lock: under load 14 a reader that polled
 * {@code getMatPosition} every 2 ms delayed ticks by up to 498 ms, and here a 300 ms hold stopped the loop for 300
 * ms every run. Changes made meanwhile by other threads are queued and applied between steps.
 */
class ModelLockInversionTest {

    @Test
    void aThreadHoldingTheModelsLockDoesNotStopTheTicks() throws Exception {
        BoardEmulator emulator = new BoardEmulator(HaplyPreset.HAPLY_2018);
        try (Board board = new Board(emulator.connect())) {
            Device device = new Device((byte) 3, board);
            HaplyPreset.HAPLY_2018.configure(device);
            device.device_set_parameters();
            PhysicalModel pm = new PhysicalModel(1000);
            pm.addHapticInput3D("avatar", new Vect3D(), 5);
            pm.addMass3D("m", 1, new Vect3D(1, 0, 0), new Vect3D());
            pm.addSpringDamper3D("k", 1, 0.001, 0.0001, "avatar", "m");
            pm.init();
            HapticLoop loop = new HapticLoop(device, HaplyPreset.HAPLY_2018.newKinematics(),
                    new PhysicalModelAvatar(pm, "avatar"));
            loop.start();
            long deadline = System.nanoTime() + 20_000_000_000L;
            while (loop.ticks() < 100 && System.nanoTime() < deadline) {
                LockSupport.parkNanos(1_000_000);
            }
            assertTrue(loop.ticks() >= 100, "the loop ticks: " + loop.failure());
            Lock lock = pm.getLock();
            long before;
            long during;
            long steps;
            lock.lock();
            try {
                before = loop.ticks();
                long stepsBefore = pm.getStepCount();
                LockSupport.parkNanos(300_000_000L);     // 300 ms: 300 ticks are due
                during = loop.ticks() - before;
                steps = pm.getStepCount() - stepsBefore;
            } finally {
                lock.unlock();
            }
            assertTrue(during >= 100, "ticks while another thread held the model's lock for 300 ms: " + during);
            assertTrue(steps >= 100, "model steps meanwhile: " + steps);
            loop.stop();
            assertTrue(!pm.isRealtimeStepping(), "stop() returns the model to the locked mode");
        }
    }
}
