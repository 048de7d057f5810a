package tactus;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicReference;
import org.junit.jupiter.api.Test;

/** The render snapshot: consistent, never torn, published at the documented moments. */
class SnapshotTest {
    private static final int RATE = 1024;
    private static final double V = 1.0 / RATE;   // one unit per second: 2^-10 per step, exact in binary

    /** n free masses at x = i, all moving at 1 unit/s along x: at step s every x_i is exactly i + s * 2^-10. */
    static PhysicalModel drifting(int n) {
        PhysicalModel m = new PhysicalModel(RATE, 64);
        for (int i = 0; i < n; i++) {
            m.addMass3D("m" + i, 1, new Vect3D(i, -i, 0), new Vect3D(1, 0, 0));
        }
        m.addGround3D("g", new Vect3D(0, 5, 0));
        m.addSpringDamper3D("s", 1, 0.0, 0.0, "m0", "g");   // K = Z = 0: a link that exerts no force
        m.init();
        return m;
    }

    @Test
    void theSnapshotMatchesTheModelAfterAFrame() {
        PhysicalModel m = drifting(10);
        ModelSnapshot before = m.getSnapshot();
        assertEquals(0, before.getStep());
        m.draw_physics();
        ModelSnapshot s = m.getSnapshot();
        assertEquals(m.getStepCount(), s.getStep());
        assertEquals(11, s.getNumberOfMats());
        assertEquals(1, s.getNumberOfLinks());
        for (int i = 0; i < 10; i++) {
            Vect3D p = m.getMatPosAt(i);
            assertEquals(p.x, s.x(i), 0.0);
            assertEquals(p.y, s.y(i), 0.0);
            assertEquals(matModuleType.Mass3D, s.getMatType(i));
        }
        assertEquals(matModuleType.Ground3D, s.getMatType(10));
        assertEquals(0, s.getLinkMat1Idx(0));
        assertEquals(10, s.getLinkMat2Idx(0));
        assertEquals(linkModuleType.SpringDamper3D, s.getLinkType(0));
        assertEquals(m.getLinkElongationAt(0), s.getLinkElongation(0), 0.0);
    }

    @Test
    void topologyEditsArePublishedAtOnce() {
        PhysicalModel m = drifting(3);
        m.removeMatAndConnectedLinks("m0");
        ModelSnapshot s = m.getSnapshot();
        assertEquals(3, s.getNumberOfMats());
        assertEquals(0, s.getNumberOfLinks());
        assertEquals(1.0, s.x(0), 0.0, "m1 is now at index 0");
    }

    @Test
    void inLockedModeAReadWithTheLockFreeIsTheCurrentStep() {
        PhysicalModel m = drifting(2);   // 1024 Hz, 64 fps: a frame is 16 steps
        for (int i = 1; i <= 7; i++) {
            m.computeStep();
            assertEquals(i, m.getSnapshot().getStep());
        }
        m.computeNSteps(20);
        assertEquals(27, m.getSnapshot().getStep());
        assertEquals(m.getMatPosAt(1).x, m.getSnapshot().x(1), 0.0);
    }

    /**
     * One thread steps sample by sample (as audio does), one changes parameters, one reads snapshots: every
     * snapshot read must be one step's state, exactly.
     */
    @Test
    void snapshotsAreNeverTornUnderThreeThreads() throws Exception {
        int n = 64;
        PhysicalModel m = drifting(n);
        AtomicBoolean stop = new AtomicBoolean();
        AtomicReference<Throwable> error = new AtomicReference<>();
        AtomicLong reads = new AtomicLong();
        Thread stepper = new Thread(() -> {
            try {
                while (!stop.get() && m.getStepCount() < 2_000_000) {
                    m.computeStep();
                }
            } catch (Throwable t) {
                error.compareAndSet(null, t);
            }
        });
        Thread editor = new Thread(() -> {
            try {
                for (int k = 0; !stop.get(); k++) {
                    m.setMatMass("m" + (k % n), 1 + (k % 7));
                    m.setLinkDamping("s", 0.0);
                }
            } catch (Throwable t) {
                error.compareAndSet(null, t);
            }
        });
        stepper.start();
        editor.start();
        long deadline = System.nanoTime() + 3_000_000_000L;
        long lastStep = -1;
        while (System.nanoTime() < deadline && error.get() == null) {
            ModelSnapshot s = m.getSnapshot();
            long step = s.getStep();
            assertTrue(step >= lastStep, "snapshots go forward in time");
            lastStep = step;
            double drift = step * V;
            for (int i = 0; i < n; i++) {
                if (s.x(i) != i + drift || s.y(i) != -i) {
                    stop.set(true);
                    throw new AssertionError("torn snapshot at step " + step + ": mass " + i + " at " + s.x(i)
                            + " instead of " + (i + drift));
                }
            }
            reads.incrementAndGet();
        }
        stop.set(true);
        stepper.join();
        editor.join();
        assertNull(error.get());
        assertTrue(reads.get() > 100, "reads " + reads.get());
        assertTrue(lastStep > 1000, "the stepper ran: " + lastStep);
    }
}
