package tactus;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.CountDownLatch;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicReference;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * Smoke test of the paper's threading: a simulation thread steps the model while a haptic thread sets
 * the avatar position and reads the force, and a render thread reads positions.
 */
class ThreadSafetyTest {
    static final Vect3D PARK = new Vect3D(5, 5, 0.5);
    static final double PARK_K = 0.25;
    static final double PARK_L0 = 0.5;
    /** Force of the tether on the parked avatar in each step: -K (d - l0) along +z, d = 1 (all binary fractions). */
    static final double PARK_FORCE_Z = -PARK_K * (1 - PARK_L0);

    static PhysicalModel chain() {
        PhysicalModel m = new PhysicalModel(1000, 60);
        m.setFriction(1e-3);
        m.addHapticInput3D("h", new Vect3D(0, 0, 0), 10);
        m.addGround3D("g", new Vect3D(0, 0, -1));
        // a parked avatar held by a spring to a ground: a constant, exactly representable force per step
        m.addHapticInput3D("park", PARK, 10);
        m.addGround3D("anchor", new Vect3D(PARK.x, PARK.y, PARK.z - 1));
        m.addSpring3D("tether", PARK_L0, PARK_K, "park", "anchor");
        for (int i = 0; i < 20; i++) {
            m.addMass3D("m" + i, 10, new Vect3D(0.1 * i, 0, 0), new Vect3D(0, 0, 0));
            m.addSpringDamper3D("s" + i, 0.1, 0.01, 0.05, "m" + i, i == 0 ? "g" : "m" + (i - 1));
            m.addContact3D("c" + i, 0.3, 0.05, 0.01, "h", "m" + i);
        }
        m.init();
        return m;
    }

    @Test
    @Timeout(20)
    void steppingWhileAnotherThreadDrivesTheAvatarAndReadsState() throws Exception {
        PhysicalModel m = chain();
        AtomicReference<Throwable> error = new AtomicReference<>();
        AtomicBoolean stop = new AtomicBoolean();
        CountDownLatch started = new CountDownLatch(1);
        long[] simSteps = new long[1];
        Thread sim = new Thread(() -> {
            try {
                started.countDown();
                for (int batch = 0; !stop.get(); batch++) {
                    // batch sizes 1..7 and single steps, so reads land at every phase of a batch
                    int n = 1 + batch % 7;
                    if (n == 7) {
                        m.computeStep();
                        n = 1;
                    } else {
                        m.computeNSteps(n);
                    }
                    simSteps[0] += n;
                }
            } catch (Throwable t) {
                error.compareAndSet(null, t);
            }
        }, "sim");
        double[] forceSum = new double[1];
        double[] parkSum = new double[1];
        Thread haptic = new Thread(() -> {
            try {
                started.await();
                Vect3D p = new Vect3D();
                for (int i = 0; i < 10_000; i++) {
                    double t = i * 1e-3;
                    p.set(0.5 + Math.sin(t) * 0.5, 0.05 * Math.cos(3 * t), 0);
                    m.setHapticPosition("h", p);
                    Vect3D f = m.getHapticForce("h");
                    if (!f.isFinite()) {
                        throw new AssertionError("non-finite haptic force " + f + " at " + i);
                    }
                    forceSum[0] += Math.abs(f.x) + Math.abs(f.y);
                    m.setHapticPosition("park", PARK);   // the device does not move: the EWMA stays put exactly
                    Vect3D fp = m.getHapticForce("park");
                    if (fp.x != 0 || fp.y != 0) {
                        throw new AssertionError("the tether is vertical, got " + fp + " at " + i);
                    }
                    parkSum[0] += fp.z;
                    Vect3D pos = m.getMatPosition("m" + (i % 20));
                    if (!pos.isFinite()) {
                        throw new AssertionError("non-finite position " + pos + " at " + i);
                    }
                }
            } catch (Throwable t) {
                error.compareAndSet(null, t);
            }
        }, "haptic");
        Thread render = new Thread(() -> {
            try {
                started.await();
                while (!stop.get()) {
                    for (int i = 0; i < m.getNumberOfMats(); i++) {
                        if (!m.getMatPosAt(i).isFinite()) {
                            throw new AssertionError("non-finite position at index " + i);
                        }
                    }
                    Thread.yield();
                }
            } catch (Throwable t) {
                error.compareAndSet(null, t);
            }
        }, "render");
        sim.start();
        haptic.start();
        render.start();
        haptic.join();
        stop.set(true);
        sim.join();
        render.join();
        assertNull(error.get(), () -> "a thread failed: " + error.get());
        // the step counter saw every step exactly once (no lost updates)
        assertEquals(simSteps[0], m.getStepCount());
        assertTrue(simSteps[0] > 0, "the simulation thread ran");
        for (int i = 0; i < m.getNumberOfMats(); i++) {
            assertTrue(m.getMatPosAt(i).isFinite());
            assertTrue(m.getMatVelAt(i).isFinite());
        }
        assertTrue(Double.isFinite(forceSum[0]));
        assertTrue(forceSum[0] > 0, "the moving avatar touched the chain: " + forceSum[0]);
        // Every step added exactly PARK_FORCE_Z to the parked avatar's accumulator, and every read took what was
        // there and cleared it: the reads plus what is left must sum to PARK_FORCE_Z per step, exactly (all
        // partial sums are multiples of 1/8 far below 2^53). A lost or doubled step, or a read racing with an
        // accumulation, shows up here.
        parkSum[0] += m.getHapticForce("park").z;
        assertEquals(PARK_FORCE_Z * m.getStepCount(), parkSum[0], 0.0, "force summed over " + m.getStepCount()
                + " steps");
        assertEquals(-0.125, PARK_FORCE_Z, 0.0);
    }

    @Test
    @Timeout(20)
    void externalSynchronisationOnTheLockExcludesSteps() throws Exception {
        PhysicalModel m = chain();
        AtomicBoolean stop = new AtomicBoolean();
        AtomicReference<Throwable> error = new AtomicReference<>();
        Thread sim = new Thread(() -> {
            try {
                while (!stop.get()) {
                    m.computeStep();
                }
            } catch (Throwable t) {
                error.compareAndSet(null, t);
            }
        });
        sim.start();
        try {
            for (int i = 0; i < 200; i++) {
                m.getLock().lock();
                try {
                    long before = m.getStepCount();
                    Vect3D a = m.getMatPosition("m19");
                    Thread.onSpinWait();
                    Vect3D b = m.getMatPosition("m19");
                    assertEquals(before, m.getStepCount(), "no step may run while the lock is held");
                    assertEquals(a.x, b.x, 0.0);
                    assertEquals(a.z, b.z, 0.0);
                } finally {
                    m.getLock().unlock();
                }
            }
        } finally {
            stop.set(true);
            sim.join();
        }
        assertNull(error.get());
    }
}
