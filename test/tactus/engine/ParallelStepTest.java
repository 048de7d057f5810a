package tactus.engine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.fail;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/**
 * Parallel stepping must be bit-identical to single-threaded stepping, including the irregular links and
 * contacts that run serially between the parallel phases, for any sequence of batch sizes and 2 to 4
 * threads; the divergence guard must still stop the batch at the right step; a kernel failure must reach
 * the caller; and the worker threads must end with the engine.
 */
class ParallelStepTest {
    private Engine parallel;

    @AfterEach
    void stopThreads() {
        if (parallel != null) {
            parallel.close();
        }
    }

    /** A sheet with gravity, friction, a few ropes and contacts (irregular kinds), fixed on two edges. */
    private static Engine scene(int w, int h) {
        Engine e = new Engine();
        e.setGravity(0, 0, -1e-6);
        e.setFriction(1e-4);
        int[] id = new int[w * h];
        for (int j = 0; j < h; j++) {
            for (int i = 0; i < w; i++) {
                MassKind kind = (j == 0 || j == h - 1) ? MassKind.GROUND3D : MassKind.MASS3D;
                id[j * w + i] = e.addMass(kind, 1 + 0.1 * ((i + 2 * j) % 3), i, j,
                        0.02 * Math.sin(0.3 * i) * Math.sin(0.5 * j), 0, 0, 0);
            }
        }
        for (int j = 0; j < h; j++) {
            for (int i = 0; i < w; i++) {
                int a = id[j * w + i];
                if (i + 1 < w) {
                    e.addLink(LinkKind.SPRING_DAMPER3D, a, id[j * w + i + 1], 0.2, 0.002, 0.97);
                }
                if (j + 1 < h) {
                    e.addLink(LinkKind.SPRING_DAMPER3D, a, id[(j + 1) * w + i], 0.2, 0.002, 1.01);
                }
            }
        }
        for (int i = 0; i < w - 5; i += 7) {
            e.addLink(LinkKind.ROPE3D, id[w + i], id[3 * w + i + 5], 0.05, 0.001, 5.0);
            e.addLink(LinkKind.CONTACT3D, id[2 * w + i], id[2 * w + i + 1], 0.05, 0.001, 1.0);
        }
        return e;
    }

    @Test
    void parallelIsBitIdenticalToSerial() {
        Engine serial = scene(120, 60);
        parallel = scene(120, 60);
        parallel.setThreads(2);
        parallel.setParallelThreshold(0);
        assertTrue(parallel.plan().elementCount() > 20_000);
        double[] a = new double[3];
        double[] b = new double[3];
        for (int batch = 0; batch < 10; batch++) {
            assertEquals(serial.step(300), parallel.step(300));
            for (int id = 0; id < 120 * 60; id += 7) {
                serial.position(id, a);
                parallel.position(id, b);
                for (int c = 0; c < 3; c++) {
                    assertEquals(a[c], b[c], 0.0, "mass " + id + " axis " + c + " batch " + batch);
                }
            }
        }
        assertEquals(serial.stepCount(), parallel.stepCount());
    }

    @Test
    void guardStopsAParallelBatchAtTheSameStepAsSerial() {
        Engine serial = scene(60, 20);
        parallel = scene(60, 20);
        parallel.setThreads(2);
        parallel.setParallelThreshold(0);
        // one far too stiff link makes the sheet diverge
        serial.addLink(LinkKind.SPRING3D, 65, 66, 50.0, 0, 1.0);
        parallel.addLink(LinkKind.SPRING3D, 65, 66, 50.0, 0, 1.0);
        int rs = serial.step(100_000);
        int rp = parallel.step(100_000);
        assertTrue(rs < 100_000, "the serial model should diverge");
        assertEquals(rs, rp);
        assertEquals(serial.divergedMass(), parallel.divergedMass());
        assertEquals(serial.divergedAt(), parallel.divergedAt());
    }

    @Test
    void smallModelsStaySerialAndThreadsCanBeReleased() {
        parallel = scene(10, 5);
        parallel.setThreads(2);
        assertEquals(2, parallel.threads());
        assertTrue(parallel.plan().elementCount() < parallel.parallelThreshold());
        parallel.step(1000);
        parallel.setThreads(1);
        assertEquals(1, parallel.threads());
        parallel.step(10);
    }

    /** Steps a serial and a parallel copy of a scene through the same batch sizes and compares every coordinate bit for bit after each batch. */
    private void assertBatchesMatchSerial(int w, int h, int threads, int[] batches, String what) {
        Engine serial = scene(w, h);
        parallel = scene(w, h);
        parallel.setThreads(threads);
        parallel.setParallelThreshold(0);
        double[] a = new double[3];
        double[] b = new double[3];
        for (int i = 0; i < batches.length; i++) {
            assertEquals(serial.step(batches[i]), parallel.step(batches[i]));
            for (int id = 0; id < w * h; id++) {
                serial.position(id, a);
                parallel.position(id, b);
                for (int c = 0; c < 3; c++) {
                    if (Double.doubleToLongBits(a[c]) != Double.doubleToLongBits(b[c])) {
                        fail(what + ": mass " + id + " axis " + c + " differs after batch " + i + " (" + batches[i]
                                + " steps): serial " + a[c] + ", parallel " + b[c]);
                    }
                }
            }
        }
        assertEquals(serial.stepCount(), parallel.stepCount());
        parallel.setThreads(1);
    }

    // Was: after a batch's last barrier a worker re-read the shared step count and stop flag; when the caller
    // had already started a longer batch, the worker ran extra phases and the barriers fell out of step.
    @Test
    void alternatingBatchSizesMatchSerialOnTwoAndThreeThreads() {
        int[] batches = new int[2000];
        for (int i = 0; i < batches.length; i++) {
            batches[i] = 2 + i % 3;
        }
        assertTimeoutPreemptively(Duration.ofMinutes(3), () -> {
            assertBatchesMatchSerial(40, 10, 2, batches, "2 threads, batches 2,3,4");
            assertBatchesMatchSerial(40, 10, 3, java.util.Arrays.copyOf(batches, 600), "3 threads, batches 2,3,4");
        });
    }

    @Test
    void randomBatchSizesMatchSerialOnTwoToFourThreads() {
        assertTimeoutPreemptively(Duration.ofMinutes(3), () -> {
            for (int threads = 2; threads <= 4; threads++) {
                for (long seed = 1; seed <= 2; seed++) {
                    java.util.Random rnd = new java.util.Random(seed * 31 + threads);
                    int[] batches = new int[threads == 2 ? 800 : 250];
                    for (int i = 0; i < batches.length; i++) {
                        batches[i] = 1 + rnd.nextInt(5);
                    }
                    assertBatchesMatchSerial(30 + 7 * threads, 9, threads, batches,
                            threads + " threads, seed " + seed);
                }
            }
        });
    }

    private static boolean anyAlive(Thread[] threads) {
        for (Thread t : threads) {
            if (t.isAlive()) {
                return true;
            }
        }
        return false;
    }

    /** Steps until the plan's stencil runs need their scratch arrays, then returns the plan. */
    private StepPlan parallelSheetWithRuns(int threads) {
        parallel = scene(60, 20);
        parallel.setThreads(threads);
        parallel.setParallelThreshold(0);
        parallel.step(4);
        StepPlan p = parallel.plan();
        assertTrue(p.stencilVecX != null, "the sheet should be stepped with stencil runs");
        return p;
    }

    // Was: an exception inside a kernel left the other threads spinning at the barrier for ever.
    @Test
    void aKernelThatThrowsOnAWorkerReachesTheCallerAndTheStepperStaysUsable() {
        StepPlan p = parallelSheetWithRuns(2);
        double[] scratch = p.stencilVecX;
        // the worker's half of the first run's range no longer fits the scratch array: it throws there only
        p.stencilVecX = new double[p.nMass / 4];
        long before = parallel.stepCount();
        assertTimeoutPreemptively(Duration.ofSeconds(60), () -> {
            assertThrows(ArrayIndexOutOfBoundsException.class, () -> parallel.step(10));
            p.stencilVecX = scratch;
            assertEquals(10, parallel.step(10), "the stepper must run again after the failure");
        });
        assertEquals(before + 10, parallel.stepCount(), "the failed batch counts no completed step");
    }

    @Test
    void aSerialKernelThatThrowsReachesTheCallerAndTheStepperStaysUsable() {
        StepPlan p = parallelSheetWithRuns(3);
        LinkBatch ropes = p.batch(LinkKind.ROPE3D);
        int slot = ropes.a[0];
        ropes.a[0] = Integer.MAX_VALUE;
        assertTimeoutPreemptively(Duration.ofSeconds(60), () -> {
            assertThrows(ArrayIndexOutOfBoundsException.class, () -> parallel.step(10));
            ropes.a[0] = slot;
            assertEquals(10, parallel.step(10));
        });
    }

    @Test
    void closeStopsTheWorkerThreadsAndIsIdempotent() throws InterruptedException {
        parallel = scene(40, 10);
        parallel.setThreads(4);
        parallel.setParallelThreshold(0);
        Thread[] workers = parallel.stepperThreads();
        assertEquals(3, workers.length);
        parallel.step(50);
        for (Thread t : workers) {
            assertTrue(t.isAlive() && t.isDaemon(), t.getName() + " should be a live daemon thread");
        }
        parallel.close();
        for (Thread t : workers) {
            assertEquals(Thread.State.TERMINATED, t.getState(), t.getName() + " after close()");
        }
        parallel.close();
        assertEquals(1, parallel.threads());
        assertEquals(0, parallel.stepperThreads().length);
        Engine serial = scene(40, 10);
        serial.step(50);
        assertEquals(serial.step(20), parallel.step(20), "a closed engine steps on the calling thread");
        double[] a = new double[3];
        double[] b = new double[3];
        serial.position(123, a);
        parallel.position(123, b);
        assertEquals(a[0], b[0], 0.0);
    }

    @Test
    void workersOfAnUnreachableEngineStop() throws InterruptedException {
        Thread[] workers = startAndDropParallelEngine();
        for (int i = 0; i < 200 && anyAlive(workers); i++) {
            System.gc();
            Thread.sleep(50);
        }
        assertFalse(anyAlive(workers), "the worker threads of an unreachable engine should end");
    }

    private static Thread[] startAndDropParallelEngine() {
        Engine e = scene(40, 10);
        e.setThreads(3);
        e.setParallelThreshold(0);
        e.step(100);
        return e.stepperThreads();
    }
}
