package tactus.engine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

/**
 * Parallel stepping must be bit-identical to single-threaded stepping, including the irregular links and
 * contacts that run serially between the parallel phases, and the divergence guard must still stop the
 * batch at the right step.
 */
class ParallelStepTest {
    private Engine parallel;

    @AfterEach
    void stopThreads() {
        if (parallel != null) {
            parallel.setThreads(1);
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
}
