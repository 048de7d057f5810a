package tactus;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicReference;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Defect 5 of issue 15: the energy getters rebuilt a contact group's neighbour list on the reader's thread while a
 * realtime owner stepped the model with it, so the owner threw ArrayIndexOutOfBoundsException or silently took
 * another trajectory. Here an owner thread steps a pile of colliding balls (the broad phase rebuilds often) while
 * 1 to 3 reader threads call the three energy getters as fast as they can; the owner's trajectory must be bitwise
 * the one of a run without readers, with no exception on any thread, whatever the owner's batch size.
 */
class EnergyReaderRaceTest {
    private static final int STEPS = 10000;

    @ParameterizedTest(name = "{0} reader(s), batches of {1} steps")
    @CsvSource({"1, 1", "2, 64", "3, 7", "1, 512"})
    @Timeout(60)
    void readersHammeringTheEnergiesNeverChangeTheOwnersTrajectory(int readers, int batch) throws Exception {
        double[] reference = run(0, batch, new AtomicReference<>(), new AtomicLong());
        AtomicReference<Throwable> error = new AtomicReference<>();
        AtomicLong reads = new AtomicLong();
        double[] raced = run(readers, batch, error, reads);
        assertNull(error.get(), () -> "an exception escaped a thread: " + error.get());
        assertTrue(reads.get() >= readers, "the readers never read while the owner stepped");
        assertArrayEquals(reference, raced, "the readers changed the owner's trajectory");
    }

    /** Steps the pile on an owner thread with {@code readers} energy readers beside it; returns the final state. */
    private static double[] run(int readers, int batch, AtomicReference<Throwable> error, AtomicLong reads)
            throws Exception {
        PhysicalModel m = pile();
        m.beginRealtimeStepping();
        AtomicBoolean done = new AtomicBoolean();
        CountDownLatch readersStarted = new CountDownLatch(readers);
        Thread[] rd = new Thread[readers];
        for (int r = 0; r < readers; r++) {
            int which = r;
            rd[r] = new Thread(() -> {
                readersStarted.countDown();
                try {
                    while (!done.get()) {
                        double e = which == 0 ? m.getTotalEnergy() : which == 1 ? m.getPotentialEnergy()
                                : m.getKineticEnergy() + m.getPotentialEnergy();
                        if (Double.isNaN(e)) {
                            throw new AssertionError("energy read as NaN");
                        }
                        reads.incrementAndGet();
                    }
                } catch (Throwable t) {
                    error.compareAndSet(null, t);
                }
            }, "energy reader " + r);
            rd[r].start();
        }
        Thread owner = new Thread(() -> {
            try {
                readersStarted.await();
                for (int s = 0; s < STEPS; s += batch) {
                    m.computeNSteps(Math.min(batch, STEPS - s));
                }
            } catch (Throwable t) {
                error.compareAndSet(null, t);
            } finally {
                done.set(true);
            }
        }, "owner");
        owner.start();
        owner.join();
        for (Thread t : rd) {
            t.join();
        }
        m.endRealtimeStepping();
        assertEquals(STEPS, m.getStepCount(), "the owner did not run every step");
        int n = m.getNumberOfMats();
        double[] s = new double[6 * n];
        for (int i = 0; i < n; i++) {
            Vect3D p = m.getMatPosAt(i);
            Vect3D v = m.getMatVelAt(i);
            s[6 * i] = p.x;
            s[6 * i + 1] = p.y;
            s[6 * i + 2] = p.z;
            s[6 * i + 3] = v.x;
            s[6 * i + 4] = v.y;
            s[6 * i + 5] = v.z;
        }
        return s;
    }

    /** 100 oscillators packed in a box, flying in random directions: many contacts and broad-phase rebuilds. */
    private static PhysicalModel pile() {
        PhysicalModel m = new PhysicalModel(44100, 60);
        m.setStabilityPolicy(StabilityPolicy.OFF);
        m.createMatSubset("balls");
        Random r = new Random(42);
        int i = 0;
        for (int x = 0; x < 5; x++) {
            for (int y = 0; y < 5; y++) {
                for (int z = 0; z < 4; z++) {
                    String n = "b" + i++;
                    Vect3D v = new Vect3D((r.nextDouble() - .5) * 4000, (r.nextDouble() - .5) * 4000,
                            (r.nextDouble() - .5) * 4000);
                    m.addOsc3D(n, 1, 0.01, 0.00001, new Vect3D(x * 0.3, y * 0.3, z * 0.3), v);
                    m.addMatToSubset(n, "balls");
                }
            }
        }
        m.addContactGroup("balls", 0.25, 0.05, 0.001);
        m.init();
        return m;
    }
}
