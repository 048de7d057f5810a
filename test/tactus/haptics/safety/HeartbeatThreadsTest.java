package tactus.haptics.safety;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.locks.LockSupport;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * The guard's look at the sketch's watchdog thread (Linux /proc): runnable means the JVM runs but waits for a
 * CPU (no pause), parked means it is not running. Here the "sketch" is this JVM and the thread is a stand-in
 * with the watchdog's name.
 */
@Timeout(30)
class HeartbeatThreadsTest {

    @Test
    void aRunnableWatchdogIsWaitingForCpuAndAParkedOneIsNot() throws Exception {
        Assumptions.assumeTrue(java.nio.file.Files.isDirectory(java.nio.file.Paths.get("/proc/self/task")), "Linux /proc");
        HeartbeatThreads threads = new HeartbeatThreads(ProcessHandle.current().pid());
        java.util.concurrent.atomic.AtomicBoolean spin = new java.util.concurrent.atomic.AtomicBoolean(true);
        java.util.concurrent.atomic.AtomicBoolean stop = new java.util.concurrent.atomic.AtomicBoolean(false);
        Thread t = new Thread(() -> {
            while (!stop.get()) {
                if (spin.get()) {
                    Thread.onSpinWait();   // runnable: on a CPU or waiting for one
                } else {
                    LockSupport.parkNanos(1_000_000_000L);
                }
            }
        }, "tactus-haply-torque-watchdog");
        t.setDaemon(true);
        t.start();
        try {
            boolean seen = false;
            long deadline = System.nanoTime() + 5_000_000_000L;
            while (!seen && System.nanoTime() < deadline) {
                seen = new HeartbeatThreads(ProcessHandle.current().pid()).waitForCpu();
                Thread.sleep(10);
            }
            assertTrue(seen, "a spinning thread named as the watchdog is runnable");
            spin.set(false);
            boolean parked = false;
            deadline = System.nanoTime() + 5_000_000_000L;
            while (!parked && System.nanoTime() < deadline) {
                Thread.sleep(20);
                parked = !threads.waitForCpu();
            }
            assertTrue(parked, "a parked thread is not waiting for a CPU");
        } finally {
            stop.set(true);
            LockSupport.unpark(t);
            t.join(2_000);
        }
    }
}
