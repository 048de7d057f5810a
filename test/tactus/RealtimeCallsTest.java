package tactus;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.Random;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicReference;
import java.util.concurrent.locks.LockSupport;
import java.util.concurrent.locks.ReentrantLock;
import org.junit.jupiter.api.Test;
import tactus.internal.realtime.Ownership;

/**
 * A run of the realtime owner's calls ({@link PhysicalModel#beginRealtimeCalls()}, what a PhyUGen's sample is): it
 * enters the model once, so other threads' changes apply when a run begins and when it steps, never at its reads, another thread cannot
 * end the mode or take the role while a run holds the model, a run is refused (and holds nothing) in locked mode and
 * while another thread owns the model, and a divergence listener that ends the mode inside a run ends it when the run
 * ends.
 */
class RealtimeCallsTest {
    private static final Duration BOUND = Duration.ofSeconds(30);

    private static PhysicalModel oneMass() {
        PhysicalModel pm = new PhysicalModel(44100, 60);
        pm.addMass3D("m", 1, new Vect3D(0, 0, 0), new Vect3D());
        pm.init();
        return pm;
    }

    @Test
    void inLockedModeARunIsNotBegunAndHoldsNothing() {
        assertTimeoutPreemptively(BOUND, () -> {
            PhysicalModel pm = oneMass();
            assertFalse(pm.beginRealtimeCalls());
            pm.endRealtimeCalls(); // allowed, does nothing
            assertFalse(((ReentrantLock) pm.getLock()).isLocked(), "the model's lock is free");
            pm.computeStep();
            assertEquals(1, pm.getStepCount());
        });
    }

    /**
     * Another thread moves the mass while the owner is inside a run: the owner's reads in that run all see the old
     * position (the change is queued, not applied by a read), and the next run, or a step of the run (a stepping call
     * applies what is queued before it steps), sees the new one. Without the run, the second read (a facade call of
     * the owner) would apply it.
     */
    @Test
    void anotherThreadsChangeAppliesBetweenRunsNeverInsideOne() {
        assertTimeoutPreemptively(BOUND, () -> {
            PhysicalModel pm = oneMass();
            pm.beginRealtimeStepping();
            Mass m = pm.getMass("m");
            SnapshotOnDemandTest.onThread("audio", () -> {
                assertTrue(pm.beginRealtimeCalls(), "the first run takes the role");
                try {
                    assertEquals(Thread.currentThread(), pm.getRealtimeOwner());
                    pm.computeStep();
                    double before = m.getPosition().x;
                    SnapshotOnDemandTest.onThread("sketch", () -> m.setPosition(new Vect3D(5, 0, 0)));
                    Ownership own = pm.gate.mode();
                    assertTrue(own.postedSeq() > own.appliedSeq(), "the change is queued");
                    assertEquals(before, m.getPosition().x, 0.0, "not applied inside the run");
                } finally {
                    pm.endRealtimeCalls();
                }
                assertTrue(pm.gate.mode().gateFree(), "the run released the gate");
                assertTrue(pm.beginRealtimeCalls());
                try {
                    assertEquals(5, m.getPosition().x, 0.0, "applied when the next run begins");
                    SnapshotOnDemandTest.onThread("sketch", () -> m.setPosition(new Vect3D(7, 0, 0)));
                    assertEquals(5, m.getPosition().x, 0.0, "a read inside the run applies nothing");
                    pm.computeStep();
                    assertEquals(7, m.getPosition().x, 0.0, "a step applies what is queued before it steps");
                } finally {
                    pm.endRealtimeCalls();
                }
            });
            pm.endRealtimeStepping();
            assertEquals(7, m.getPosition().x, 0.0);
        });
    }

    /** endRealtimeStepping() from another thread waits for the run in progress, then ends the mode. */
    @Test
    void anotherThreadCannotEndTheModeInsideARun() {
        assertTimeoutPreemptively(BOUND, () -> {
            PhysicalModel pm = oneMass();
            pm.beginRealtimeStepping();
            CountDownLatch inRun = new CountDownLatch(1);
            CountDownLatch release = new CountDownLatch(1);
            AtomicBoolean stillRealtimeAtRunEnd = new AtomicBoolean();
            Thread audio = new Thread(() -> {
                boolean held = pm.beginRealtimeCalls();
                try {
                    inRun.countDown();
                    release.await(10, TimeUnit.SECONDS);
                    pm.computeStep();
                    stillRealtimeAtRunEnd.set(held && pm.isRealtimeStepping());
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                } finally {
                    pm.endRealtimeCalls();
                }
            }, "audio");
            audio.start();
            assertTrue(inRun.await(10, TimeUnit.SECONDS));
            Thread ender = new Thread(pm::endRealtimeStepping, "ender");
            ender.start();
            ender.join(200);
            assertTrue(ender.isAlive(), "endRealtimeStepping waits for the run");
            assertTrue(pm.isRealtimeStepping());
            release.countDown();
            ender.join(10_000);
            audio.join(10_000);
            assertFalse(ender.isAlive(), "it ends the mode once the run is over");
            assertTrue(stillRealtimeAtRunEnd.get(), "the mode lasted until the end of the run");
            assertFalse(pm.isRealtimeStepping());
            assertEquals(1, pm.getStepCount());
        });
    }

    /** While another thread owns the model and steps it, a run is refused, holds nothing, and steps nothing. */
    @Test
    void aRunIsRefusedWhileAnotherActiveThreadOwnsTheModel() {
        assertTimeoutPreemptively(BOUND, () -> {
            PhysicalModel pm = oneMass();
            pm.beginRealtimeStepping();
            AtomicBoolean stop = new AtomicBoolean();
            Thread owner = new Thread(() -> {
                while (!stop.get()) {
                    pm.computeStep();
                    LockSupport.parkNanos(100_000L);
                }
            }, "owner");
            owner.start();
            while (pm.getRealtimeOwner() != owner) {
                Thread.sleep(1);
            }
            SnapshotOnDemandTest.onThread("other", () -> {
                assertFalse(pm.beginRealtimeCalls(), "refused: another thread owns the model");
                pm.endRealtimeCalls(); // holds nothing: does nothing
                assertEquals(owner, pm.getRealtimeOwner());
                assertTrue(pm.takeRealtimeStepping(), "it can still claim the model explicitly");
                assertTrue(pm.beginRealtimeCalls(), "and then run");
                pm.endRealtimeCalls();
            });
            stop.set(true);
            owner.join(10_000);
            assertTrue(pm.gate.mode().gateFree());
            pm.endRealtimeStepping();
        });
    }

    /**
     * A divergence listener ends the mode from inside a run's step: the run keeps the model until it ends (its later
     * reads work), then the mode is over and the same thread steps in locked mode.
     */
    @Test
    void aListenerThatEndsTheModeInsideARunEndsItWhenTheRunEnds() {
        assertTimeoutPreemptively(BOUND, () -> {
            PhysicalModel pm = OwnershipTest.divergingModel();
            pm.setDivergenceListener(e -> pm.endRealtimeStepping());
            pm.init();
            pm.beginRealtimeStepping();
            SnapshotOnDemandTest.onThread("audio", () -> {
                boolean ended = false;
                for (int i = 0; i < 100_000 && !ended; i++) {
                    assertTrue(pm.beginRealtimeCalls(), "sample " + i);
                    try {
                        pm.computeStep();
                        pm.getMass("y").getPosition(); // a read after the step, inside the run
                        ended = pm.isDiverged();
                        if (ended) {
                            assertTrue(pm.isRealtimeStepping(), "still realtime inside the run");
                        }
                    } finally {
                        pm.endRealtimeCalls();
                    }
                }
                assertTrue(ended, "the model diverged");
                assertFalse(pm.isRealtimeStepping(), "the mode ended with the run");
                assertFalse(pm.beginRealtimeCalls(), "locked mode: no run");
                pm.clearDivergence();
                long steps = pm.getStepCount();
                pm.computeStep();
                assertEquals(steps + 1, pm.getStepCount(), "it steps in locked mode");
            });
        });
    }

    /**
     * Exclusion under varied timing: a writer thread moves the mass to 1, 2, 3, ... (each a queued change) with random
     * pauses, while the owner runs samples of one step and several reads, with random pauses inside and between runs.
     * In every run all reads agree (nothing is applied inside a run), the positions never go back, every change is
     * applied in the end, and no thread throws.
     */
    @Test
    void readsInsideARunAgreeWhateverTheTiming() {
        assertTimeoutPreemptively(BOUND, () -> {
            for (long seed = 1; seed <= 4; seed++) {
                PhysicalModel pm = oneMass();
                pm.beginRealtimeStepping();
                Mass m = pm.getMass("m");
                int writes = 400;
                AtomicBoolean writing = new AtomicBoolean(true);
                AtomicReference<Throwable> error = new AtomicReference<>();
                Random rw = new Random(seed);
                Thread writer = new Thread(() -> {
                    try {
                        for (int k = 1; k <= writes; k++) {
                            m.setPosition(new Vect3D(k, 0, 0));
                            if (rw.nextInt(4) == 0) {
                                LockSupport.parkNanos(rw.nextInt(200_000));
                            }
                        }
                    } catch (Throwable e) {
                        error.compareAndSet(null, e);
                    } finally {
                        writing.set(false);
                    }
                }, "writer");
                Random ra = new Random(seed * 31);
                long[] runs = new long[1];
                Thread audio = new Thread(() -> {
                    try {
                        Vect3D p = new Vect3D();
                        double last = 0;
                        boolean tail = true;
                        while (writing.get() || tail) {
                            if (!writing.get()) {
                                tail = false; // one more run after the writer finished
                            }
                            if (!pm.beginRealtimeCalls()) {
                                throw new AssertionError("run refused");
                            }
                            try {
                                pm.computeStep(); // velocity 0: a step leaves x where it was set (and applies what is queued)
                                double first = m.getPosition(p).x;
                                for (int r = 0; r < 4; r++) {
                                    if (ra.nextInt(3) == 0) {
                                        LockSupport.parkNanos(ra.nextInt(50_000));
                                    }
                                    double again = m.getPosition(p).x;
                                    if (again != first) {
                                        throw new AssertionError("read " + again + " after " + first + " in one run");
                                    }
                                }
                                if (first < last) {
                                    throw new AssertionError("went back from " + last + " to " + first);
                                }
                                last = first;
                            } finally {
                                pm.endRealtimeCalls();
                            }
                            runs[0]++;
                            if (ra.nextInt(2) == 0) {
                                LockSupport.parkNanos(ra.nextInt(100_000));
                            }
                        }
                    } catch (Throwable e) {
                        error.compareAndSet(null, e);
                    }
                }, "audio");
                audio.start();
                writer.start();
                writer.join(20_000);
                audio.join(20_000);
                assertNull(error.get(), () -> "seed: " + error.get());
                assertTrue(runs[0] > 0);
                Ownership own = pm.gate.mode();
                assertTrue(own.gateFree());
                assertEquals(own.postedSeq(), own.completedCount() + own.droppedCount(), "every change applied");
                pm.endRealtimeStepping();
                assertEquals(writes, m.getPosition().x, 0.0, "the last change is the position");
            }
        });
    }
}
