package tactus.audio;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.management.ManagementFactory;
import java.time.Duration;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicReference;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import tactus.DivergenceException;
import tactus.PhysicalModel;
import tactus.Vect3D;

/**
 * The audio thread's checks never wait for another thread (issue #27, section 4): the halted check of a
 * {@link PhysicalModelStepper} is a lock-free read of a published flag that follows divergence and
 * {@code clearDivergence()}, and a divergence's message is formatted where it is read, not on the stepping thread.
 */
@Timeout(value = 30, unit = TimeUnit.SECONDS)
class StepperNeverWaitsTest {

    private static PhysicalModel chain() {
        PhysicalModel m = PhyUGenMinimMistakesTest.chain(new PhysicalModel(44100, 60));
        m.init();
        return m;
    }

    /** A thread that holds the model's lock until released. */
    private static Thread holdLock(PhysicalModel m, CountDownLatch held, CountDownLatch release) {
        Thread t = new Thread(() -> {
            m.getLock().lock();
            try {
                held.countDown();
                release.await();
            } catch (InterruptedException ignored) {
                Thread.currentThread().interrupt();
            } finally {
                m.getLock().unlock();
            }
        }, "lock holder");
        t.setDaemon(true);
        t.start();
        return t;
    }

    @Test
    void theHaltedCheckDoesNotWaitForAThreadHoldingTheModelsLock() throws Exception {
        PhysicalModel m = chain();
        PhysicalModelStepper s = new PhysicalModelStepper(m);
        m.endRealtimeStepping(); // locked mode (the mode ended while played): every facade call takes the lock
        CountDownLatch held = new CountDownLatch(1);
        CountDownLatch release = new CountDownLatch(1);
        Thread holder = holdLock(m, held, release);
        try {
            assertTrue(held.await(5, TimeUnit.SECONDS), "the holder took the lock");
            // the scenario has teeth: the locking read does wait for the holder
            AtomicBoolean lockedReadReturned = new AtomicBoolean();
            Thread reader = new Thread(() -> {
                m.isDiverged();
                lockedReadReturned.set(true);
            }, "locked reader");
            reader.setDaemon(true);
            reader.start();
            reader.join(300);
            assertFalse(lockedReadReturned.get(), "isDiverged() waits for the lock's holder");
            boolean halted = assertTimeoutPreemptively(Duration.ofSeconds(2), s::isHalted,
                    "isHalted() waited for the thread holding the model's lock");
            assertFalse(halted);
            assertFalse(assertTimeoutPreemptively(Duration.ofSeconds(2), m::isDivergedNow));
        } finally {
            release.countDown();
            holder.join(5000);
        }
    }

    @Test
    void theFlagFollowsADivergenceAndItsClearingFromAnotherThread() throws Exception {
        PhysicalModel m = chain();
        PhysicalModelStepper s = new PhysicalModelStepper(m);
        AtomicReference<DivergenceException> seen = new AtomicReference<>();
        AtomicBoolean stop = new AtomicBoolean();
        AtomicBoolean haltedBeforeSeen = new AtomicBoolean();
        Thread audio = new Thread(() -> {
            while (!stop.get()) {
                s.beginSample();
                try {
                    if (s.isHalted()) {
                        if (seen.get() == null) {
                            haltedBeforeSeen.set(true);
                        }
                        continue;
                    }
                    try {
                        s.step();
                    } catch (DivergenceException e) {
                        seen.compareAndSet(null, e);
                    }
                } finally {
                    s.endSample();
                }
            }
        }, "audio");
        audio.setDaemon(true);
        audio.start();
        try {
            assertFalse(m.isDivergedNow());
            m.setLinkStiffness("s3", 5.0); // the default WARN policy keeps it: the model blows up
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
            while (seen.get() == null && System.nanoTime() < deadline) {
                Thread.sleep(1);
            }
            DivergenceException e = seen.get();
            assertNotNull(e, "the model diverged");
            assertFalse(haltedBeforeSeen.get(), "halted before the step that diverged returned");
            assertTrue(m.isDivergedNow(), "the flag is published once the diverging step returned");
            assertTrue(m.isDiverged());
            assertTrue(e.getMessage().matches("Mass3D \"m\\d+\" diverged at step " + e.getStep()
                    + ": position \\(.+, .+, .+\\); the model is frozen until clearDivergence\\(\\)"), e.getMessage());
            assertTrue(e.getMessage().contains("\"" + e.getMassName() + "\""), e.getMessage());
            m.setLinkStiffness("s3", 0.01);
            for (int i = 1; i <= 10; i++) {
                m.setMatPosition("m" + i, new Vect3D(i, 0, 0));
            }
            m.clearDivergence(); // applied by the audio thread between two samples; returns once applied
            assertFalse(m.isDivergedNow(), "the flag is cleared once clearDivergence() returned");
            assertFalse(m.isDiverged());
        } finally {
            stop.set(true);
            audio.join(5000);
        }
        assertTrue(!audio.isAlive(), "the audio thread ended");
    }

    @Test
    void theMessageIsFormattedWhereItIsReadNotOnTheSteppingThread() {
        PhysicalModel m = chain();
        AtomicReference<DivergenceException> told = new AtomicReference<>();
        m.setDivergenceListener(told::set);
        m.setLinkStiffness("s3", 5.0);
        for (int i = 0; i < 100_000 && told.get() == null; i++) {
            m.computeStep();
        }
        DivergenceException e = told.get();
        assertNotNull(e, "the listener was told");
        com.sun.management.ThreadMXBean mx = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        long tid = Thread.currentThread().getId();
        long a0 = mx.getThreadAllocatedBytes(tid);
        String first = e.getMessage();
        long a1 = mx.getThreadAllocatedBytes(tid);
        String again = e.getMessage();
        long a2 = mx.getThreadAllocatedBytes(tid);
        assertTrue(a1 - a0 > 0, "the first read formats the message (allocated " + (a1 - a0) + " bytes)");
        assertEquals(0, a2 - a1, "a second read returns the same text without formatting it again");
        assertSame(first, again);
        assertTrue(first.startsWith("Mass3D \"" + e.getMassName() + "\" diverged at step " + e.getStep() + ": position ("),
                first);
        assertTrue(e.toString().endsWith(first), e.toString());
    }
}
