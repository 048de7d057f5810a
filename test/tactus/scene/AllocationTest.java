package tactus.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.management.ManagementFactory;
import org.junit.jupiter.api.Test;
import tactus.PhysicalModel;
import tactus.Vect3D;

/**
 * Stepping allocates nothing. A 1,000-element model (500 Mass3D chained by 500 SpringDamper3D, with gravity,
 * friction, contacts and a plane) runs 10^5 steps through computeNSteps while the JVM's per-thread allocation
 * counter (com.sun.management.ThreadMXBean) is read around the loop. Reading the counter can itself
 * allocate, so an empty measurement is taken as a baseline and subtracted; the result must be exactly 0.
 * A one-off JIT event (deoptimisation, a late class load) could add bytes once, so the measurement is
 * repeated up to three times: any real per-step allocation would show in every repetition (10^5 steps).
 */
class AllocationTest {

    private static PhysicalModel bigModel() {
        PhysicalModel pm = new PhysicalModel(1000, 30);
        pm.setGravity(1e-7);
        pm.setFriction(1e-4);
        pm.addGround3D("m0", new Vect3D(0, 0, 0));
        for (int i = 1; i <= 500; i++) {
            pm.addMass3D("m" + i, 1, new Vect3D(0.1 * i, 0.001 * (i % 7), 0), new Vect3D(0, 0, (i % 5) - 2));
            pm.addSpringDamper3D("s" + i, 0.1, 0.1, 0.01, "m" + (i - 1), "m" + i);
        }
        for (int i = 1; i <= 5; i++) {
            pm.addContact3D("c" + i, 0.15, 0.05, 0.005, "m" + (10 * i), "m" + (10 * i + 2));
        }
        pm.addPlaneContact("floor", 0, 0.05, 0.005, 2, -0.01, "m250");
        pm.init();
        return pm;
    }

    @Test
    void computeNStepsAllocatesNothing() {
        PhysicalModel pm = bigModel();
        assertEquals(501, pm.getNumberOfMats());
        com.sun.management.ThreadMXBean mx = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        assertTrue(mx.isThreadAllocatedMemorySupported() && mx.isThreadAllocatedMemoryEnabled());
        long tid = Thread.currentThread().getId();
        // warm-up: let the JIT compile the kernels and the stepping loop
        for (int i = 0; i < 100; i++) {
            pm.computeNSteps(1000);
        }
        long[] measured = {-1, -1, -1};
        long last = -1;
        for (int attempt = 0; attempt < 3 && last != 0; attempt++) {
            long b0 = mx.getThreadAllocatedBytes(tid);
            long b1 = mx.getThreadAllocatedBytes(tid);
            long baseline = b1 - b0;
            long a0 = mx.getThreadAllocatedBytes(tid);
            for (int i = 0; i < 100; i++) {
                pm.computeNSteps(1000);
            }
            long a1 = mx.getThreadAllocatedBytes(tid);
            measured[attempt] = (a1 - a0) - baseline;
            last = measured[attempt];
        }
        assertEquals(0, last, "bytes allocated by 10^5 steps of 1,000 elements: " + measured[0] + ", "
                + measured[1] + ", " + measured[2]);
        assertTrue(pm.getMatPosition("m250").isFinite());
    }
}
