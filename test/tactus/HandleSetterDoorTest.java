package tactus;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicReference;
import java.util.concurrent.locks.LockSupport;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * A setter on a handle enters the model the way the same setter on the model does: while a stand-in audio thread
 * steps the model in bursts, a run of setters through handles returns while the stepping thread is in the middle of
 * a burst (it never waits for the audio thread), and each change reaches the stepping thread between the same two
 * samples as the change made through {@link PhysicalModel}: the two stepped trajectories are equal bit for bit.
 * Getters still see the setters made before them. Varied: the burst size, the number of setters, and the kind of
 * handle (masses or interactions).
 */
class HandleSetterDoorTest {
    private static final Duration BOUND = Duration.ofSeconds(60);
    /** How long the stand-in audio thread holds its burst open for the setters (far more than they need). */
    private static final long HOLD_SECONDS = 3;
    /** The bound on a run of setters in the free-running test: about a third of one 1,024-step burst's wait today. */
    private static final long SETTERS_BOUND_NANOS = 150_000_000L;
    private static final int BURSTS = 3;

    /** How the changes are made: through handles, through the model's calls by name, or not at all. */
    private enum Way { HANDLES, MODEL, NONE }

    private static PhysicalModel model() {
        PhysicalModel pm = new PhysicalModel(44100, 60);
        pm.addGround3D("g", new Vect3D(0, 0, 0));
        pm.addOsc3D("o", 1, 0.01, 0.001, new Vect3D(1, 0, 0), new Vect3D(0.002, 0, 0));
        pm.addMass3D("m", 1, new Vect3D(2, 0, 0), new Vect3D(0, 0.001, 0));
        pm.addSpringDamper3D("s", 1, 0.05, 0.01, "o", "m");
        pm.addSpring3D("t", 1.5, 0.02, "g", "m");
        pm.init();
        return pm;
    }

    /** The handles of the model's modules, looked up before the setters (a look-up is a read). */
    private static final class Handles {
        final Osc3D o;
        final Mass3D m;
        final SpringDamper3D s;
        final Spring3D t;

        Handles(PhysicalModel pm) {
            o = (Osc3D) pm.getMass("o");
            m = (Mass3D) pm.getMass("m");
            s = (SpringDamper3D) pm.getInteraction("s");
            t = (Spring3D) pm.getInteraction("t");
        }
    }

    /** Setter number {@code i} of a run (a value that differs from one setter to the next). */
    private static void change(PhysicalModel pm, Handles h, Way way, boolean masses, int i) {
        double f = 1 + 0.01 * (i + 1);
        if (masses) {
            switch (i % 3) {
                case 0:
                    if (way == Way.HANDLES) h.o.setStiffness(0.01 * f);
                    else pm.setMatStiffness("o", 0.01 * f);
                    break;
                case 1:
                    if (way == Way.HANDLES) h.o.setDamping(0.001 * f);
                    else pm.setMatDamping("o", 0.001 * f);
                    break;
                default:
                    if (way == Way.HANDLES) h.m.setMass(f);
                    else pm.setMatMass("m", f);
                    break;
            }
        } else {
            switch (i % 3) {
                case 0:
                    if (way == Way.HANDLES) h.s.setStiffness(0.05 * f);
                    else pm.setLinkStiffness("s", 0.05 * f);
                    break;
                case 1:
                    if (way == Way.HANDLES) h.s.setDamping(0.01 * f);
                    else pm.setLinkDamping("s", 0.01 * f);
                    break;
                default:
                    if (way == Way.HANDLES) h.t.setLength(1.5 * f);
                    else pm.setLinkDRest("t", 1.5 * f);
                    break;
            }
        }
    }

    /** What one run of the held-burst stepper saw. */
    private static final class Run {
        long[] trajectory;
        boolean returnedMidBurst;
        long setterNanos;
    }

    /**
     * A stand-in audio thread steps {@link #BURSTS} bursts of {@code burst} samples, each burst one run of the
     * owner's calls (as a PhyUGen's buffer would hold the model); in the middle of the second burst it holds
     * still until this thread has made its {@code setters} changes (at most {@link #HOLD_SECONDS}). It records the
     * positions of the two moving masses after every sample.
     */
    private static Run heldBurst(Way way, boolean masses, int burst, int setters) throws Exception {
        PhysicalModel pm = model();
        pm.beginRealtimeStepping();
        Handles h = new Handles(pm);
        Osc3D o = h.o;
        Mass3D m = h.m;
        int samples = BURSTS * burst;
        double[] xs = new double[samples * 4];
        CountDownLatch mid = new CountDownLatch(1);
        CountDownLatch done = new CountDownLatch(1);
        AtomicBoolean pastMid = new AtomicBoolean();
        AtomicReference<Throwable> error = new AtomicReference<>();
        Vect3D p = new Vect3D();
        Thread audio = new Thread(() -> {
            try {
                int k = 0;
                for (int b = 0; b < BURSTS; b++) {
                    assertTrue(pm.beginRealtimeCalls(), "the stand-in audio thread owns the model");
                    try {
                        for (int i = 0; i < burst; i++) {
                            pm.computeStep();
                            o.getPosition(p);
                            xs[k++] = p.x;
                            xs[k++] = p.y;
                            m.getPosition(p);
                            xs[k++] = p.x;
                            xs[k++] = p.y;
                            if (b == 1 && i == burst / 2) {
                                mid.countDown();
                                done.await(HOLD_SECONDS, TimeUnit.SECONDS);
                                pastMid.set(true);
                            }
                        }
                    } finally {
                        pm.endRealtimeCalls();
                    }
                }
            } catch (Throwable t) {
                error.set(t);
                mid.countDown();
            }
        }, "stand-in audio");
        audio.setDaemon(true);
        audio.start();
        assertTrue(mid.await(10, TimeUnit.SECONDS), "the stand-in audio thread reached the middle of a burst");
        Run r = new Run();
        long t0 = System.nanoTime();
        for (int i = 0; i < (way == Way.NONE ? 0 : setters); i++) {
            change(pm, h, way, masses, i);
        }
        r.setterNanos = System.nanoTime() - t0;
        r.returnedMidBurst = !pastMid.get();
        done.countDown();
        audio.join(20_000);
        assertFalse(audio.isAlive(), "the stand-in audio thread ended");
        assertNull(error.get(), "the stand-in audio thread threw");
        pm.endRealtimeStepping();
        r.trajectory = new long[xs.length];
        for (int i = 0; i < xs.length; i++) {
            r.trajectory[i] = Double.doubleToRawLongBits(xs[i]);
        }
        return r;
    }

    @ParameterizedTest(name = "burst {0}, {1} setters, masses {2}")
    @CsvSource({"64,1,true", "64,20,false", "256,20,true", "256,100,false", "1024,20,true", "1024,20,false",
            "1024,100,true", "256,1,false"})
    void handleSettersReturnMidBurstAndReachTheStepperBetweenTheSameSamplesAsTheModels(int burst, int setters,
                                                                                     boolean masses) {
        assertTimeoutPreemptively(BOUND, () -> {
            Run viaHandles = heldBurst(Way.HANDLES, masses, burst, setters);
            Run viaModel = heldBurst(Way.MODEL, masses, burst, setters);
            Run unchanged = heldBurst(Way.NONE, masses, burst, setters);
            assertTrue(viaHandles.returnedMidBurst, "the " + setters + " handle setters returned while the stepping "
                    + "thread was in the middle of its burst (they took " + viaHandles.setterNanos / 1_000_000
                    + " ms)");
            assertTrue(viaModel.returnedMidBurst, "the model's setters returned mid-burst");
            assertArrayEquals(viaModel.trajectory, viaHandles.trajectory,
                    "the trajectory with the changes made through handles is the one made through the model");
            int change = (burst + burst / 2 + 1) * 4; // the first sample after the held one
            long[] before = java.util.Arrays.copyOf(unchanged.trajectory, change);
            assertArrayEquals(before, java.util.Arrays.copyOf(viaHandles.trajectory, change),
                    "nothing changed before the sample the changes were made at");
            assertFalse(java.util.Arrays.equals(unchanged.trajectory, viaHandles.trajectory),
                    "the changes changed the trajectory (else the comparison proves nothing)");
        });
    }

    /**
     * A free-running stand-in audio thread: bursts of {@code burst} steps, each followed by the pause an audio
     * buffer of that size leaves at 44.1 kHz. A run of setters through handles takes far less than one burst's
     * period per setter (today's cost was one whole period per setter).
     */
    @ParameterizedTest(name = "burst {0}, {1} setters, masses {2}")
    @CsvSource({"1024,20,true", "1024,20,false", "1024,100,false", "256,100,true", "64,20,false"})
    void aRunOfHandleSettersDoesNotWaitForTheBursts(int burst, int setters, boolean masses) {
        assertTimeoutPreemptively(BOUND, () -> {
            PhysicalModel pm = model();
            pm.beginRealtimeStepping();
            Handles h = new Handles(pm);
            long pause = 23_000_000L * burst / 1024;
            AtomicBoolean stop = new AtomicBoolean();
            AtomicLong bursts = new AtomicLong();
            AtomicReference<Throwable> error = new AtomicReference<>();
            Thread audio = new Thread(() -> {
                try {
                    while (!stop.get()) {
                        pm.computeNSteps(burst);
                        bursts.incrementAndGet();
                        LockSupport.parkNanos(pause);
                    }
                } catch (Throwable t) {
                    error.set(t);
                }
            }, "stand-in audio");
            audio.setDaemon(true);
            audio.start();
            while (bursts.get() < 3 && audio.isAlive()) {
                Thread.sleep(1);
            }
            long best = Long.MAX_VALUE;
            for (int round = 0; round < 3; round++) {
                long t0 = System.nanoTime();
                for (int i = 0; i < setters; i++) {
                    change(pm, h, Way.HANDLES, masses, i);
                }
                best = Math.min(best, System.nanoTime() - t0);
                Thread.sleep(pause / 1_000_000 + 1);
            }
            // reads keep their meaning: a getter after a setter waits for the change and sees it
            for (int i = 0; i < 5; i++) {
                double k = 0.02 + 0.001 * i;
                h.s.setStiffness(k);
                h.o.setStiffness(k / 10);
                assertEquals(k, h.s.getStiffness(), "the handle's getter sees the handle's last setter");
                assertEquals(k, pm.getLinkStiffness("s"), "the model's getter sees the handle's last setter");
                assertEquals(k / 10, h.o.getStiffness(), "the oscillator's getter sees its last setter");
            }
            stop.set(true);
            audio.join(10_000);
            assertNull(error.get(), "the stand-in audio thread threw");
            pm.endRealtimeStepping();
            System.out.println("HandleSetterDoorTest: burst " + burst + ", " + setters + (masses ? " mass" : " link")
                    + " setters through handles: " + best / 1000 + " us (best of 3)");
            assertTrue(best < SETTERS_BOUND_NANOS, setters + " setters through handles took " + best / 1_000_000
                    + " ms while the stepping thread stepped bursts of " + burst);
        });
    }
}
