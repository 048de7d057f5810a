package tactus;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.locks.Lock;
import org.junit.jupiter.api.Test;
import tactus.internal.realtime.Ownership;

/**
 * The realtime command queue survives the mistakes a sketch makes in its first hour (issue 15): a queued change whose
 * target the audio thread removed, a ramp over a subset that loses a member, calls made while holding
 * {@link PhysicalModel#getLock()}, {@link PhysicalModel#endRealtimeStepping()} from a divergence listener, an owner
 * stuck in a listener, and the undo of a refused structural change under THROW.
 */
class OwnershipTest {
    private static final Duration BOUND = Duration.ofSeconds(30);

    /** A mass "x" on an unstable spring "s" (it diverges within some hundred steps) and a stable one "y" on "s2". */
    static PhysicalModel divergingModel() {
        PhysicalModel pm = new PhysicalModel(44100, 60);
        pm.setStabilityPolicy(StabilityPolicy.OFF);
        pm.addGround3D("g0", new Vect3D(0, 0, 0));
        pm.addMass3D("x", 1, new Vect3D(1, 0.01, 0), new Vect3D());
        pm.addSpringDamper3D("s", 1, 5.0, 0.0, "g0", "x");
        pm.addMass3D("y", 1, new Vect3D(0, 2, 0), new Vect3D());
        pm.addSpringDamper3D("s2", 1, 0.01, 0.0, "g0", "y");
        pm.setDivergenceCheckInterval(8);
        return pm;
    }

    /**
     * A divergence listener (on the stepping thread) removes the mass that blew up while a change of its spring, made
     * by another thread, waits in the queue: the change is dropped and counted, nothing is thrown on the stepping
     * thread, every later call steps, and another thread's setter and getter return.
     */
    @Test
    void aQueuedChangeWhoseTargetTheOwnerRemovedIsDroppedAndCounted() {
        assertTimeoutPreemptively(BOUND, () -> {
            PhysicalModel pm = divergingModel();
            CountDownLatch inListener = new CountDownLatch(1);
            CountDownLatch queued = new CountDownLatch(1);
            pm.setDivergenceListener(e -> {
                inListener.countDown();
                try {
                    queued.await(5, TimeUnit.SECONDS);
                } catch (InterruptedException ie) {
                    Thread.currentThread().interrupt();
                }
                pm.removeMatAndConnectedLinks(e.getMassName());
                pm.clearDivergence();
            });
            pm.init();
            pm.beginRealtimeStepping();
            OwnerLoop owner = new OwnerLoop(pm, 64, 200_000L, "audio").begin();
            assertTrue(inListener.await(10, TimeUnit.SECONDS), "the model diverged");
            pm.setLinkStiffness("s", 3.0); // queued while the owner is inside the listener that removes "s"
            queued.countDown();
            assertTrue(owner.awaitCalls(5));
            long zeroBefore = owner.zeroStepCalls.get();
            assertTrue(owner.awaitCalls(20));
            assertEquals(zeroBefore, owner.zeroStepCalls.get(), "every later stepping call stepped");
            assertNull(owner.firstError.get(), () -> "thrown on the stepping thread: " + owner.firstError.get());
            assertEquals(1, pm.getDroppedCommands(), "the change of the removed spring was dropped and counted");
            pm.setLinkStiffness("s2", 0.02);
            assertEquals(0.02, pm.getLinkStiffness("s2"));
            assertFalse(pm.linkExists("s"));
            assertTrue(owner.halt());
            Ownership own = pm.gate.mode();
            assertTrue(own.gateFree(), "the gate is released");
            assertEquals(own.postedSeq(), own.completedCount() + own.droppedCount(), "applied + dropped == posted");
            pm.endRealtimeStepping();
            assertEquals(1, pm.getDroppedCommands(), "still readable after the mode ended");
        });
    }

    /**
     * The owner is stuck inside a stepping call (a listener that blocks): a getter on another thread that must wait
     * for the queue gives up after the wait limit with an exception naming the owner thread, instead of waiting for
     * ever; once the owner goes on, the same getter sees the change.
     */
    @Test
    void aGetterWaitingForAStuckOwnerGivesUpInsteadOfWaitingForEver() {
        assertTimeoutPreemptively(BOUND, () -> {
            PhysicalModel pm = divergingModel();
            CountDownLatch inListener = new CountDownLatch(1);
            CountDownLatch release = new CountDownLatch(1);
            pm.setDivergenceListener(e -> {
                inListener.countDown();
                try {
                    release.await(20, TimeUnit.SECONDS);
                } catch (InterruptedException ie) {
                    Thread.currentThread().interrupt();
                }
                pm.removeMatAndConnectedLinks(e.getMassName());
                pm.clearDivergence();
            });
            pm.init();
            pm.beginRealtimeStepping();
            pm.gate.mode().waitLimitNanos = 300_000_000L;
            OwnerLoop owner = new OwnerLoop(pm, 64, 200_000L, "stuck audio").begin();
            assertTrue(inListener.await(10, TimeUnit.SECONDS));
            pm.setLinkStiffness("s2", 0.02);
            IllegalStateException e = assertThrows(IllegalStateException.class, () -> pm.getLinkStiffness("s2"));
            assertTrue(e.getMessage().contains("stuck audio"), e.getMessage());
            release.countDown();
            assertEquals(0.02, pm.getLinkStiffness("s2"));
            assertTrue(owner.halt());
            assertNull(owner.firstError.get());
            pm.endRealtimeStepping();
        });
    }

    /** A chain of 20 masses whose 21 springs form the subset "springs", ramped by controller "k" over two seconds. */
    static PhysicalModel rampedChain() {
        PhysicalModel pm = new PhysicalModel(44100, 60);
        pm.addGround3D("g0", new Vect3D(0, 0, 0));
        pm.createLinkSubset("springs");
        String prev = "g0";
        for (int i = 1; i <= 20; i++) {
            pm.addMass3D("m" + i, 1, new Vect3D(i, 0, 0), new Vect3D());
            pm.addSpringDamper3D("s" + i, 1, 0.01, 0.001, prev, "m" + i);
            pm.addLinkToSubset("s" + i, "springs");
            prev = "m" + i;
        }
        pm.addGround3D("g1", new Vect3D(21, 0, 0));
        pm.addSpringDamper3D("s21", 1, 0.01, 0.001, prev, "g1");
        pm.addLinkToSubset("s21", "springs");
        pm.addParamController("k", "springs", "stiffness", 2.0f);
        pm.init();
        return pm;
    }

    /**
     * A mass of a chain is removed (with its two springs, members of the ramped subset) in the middle of a realtime
     * ramp: the stepping thread never throws, the two removed members are dropped from the ramp and counted, and the
     * ramp ends as planned with every remaining spring at the target.
     */
    @Test
    void removingAMemberOfARampedSubsetLetsTheRampEndNormally() {
        assertTimeoutPreemptively(BOUND, () -> {
            PhysicalModel pm = rampedChain();
            pm.getParamController("k").init(0.01f);
            pm.beginRealtimeStepping();
            OwnerLoop owner = new OwnerLoop(pm, 64, 200_000L, "audio").begin();
            pm.getParamController("k").triggerRamp(0.5f);
            long until = System.nanoTime() + 10_000_000_000L;
            while (pm.getLinkStiffness("s1") == 0.01 && System.nanoTime() < until) {
                Thread.sleep(1);
            }
            pm.removeMatAndConnectedLinks("m5");
            double midRamp = pm.getLinkStiffness("s1");
            assertTrue(midRamp > 0.01 && midRamp < 0.5, "removed during the ramp (s1 at " + midRamp + ")");
            while (pm.getLinkStiffness("s1") != 0.5 && System.nanoTime() < until + 10_000_000_000L) {
                Thread.sleep(5);
            }
            assertTrue(owner.awaitCalls(5));
            assertTrue(owner.halt());
            assertNull(owner.firstError.get(), () -> "thrown on the stepping thread: " + owner.firstError.get());
            assertFalse(pm.getParamController("k").isRamping(), "the ramp ended");
            assertEquals(2, pm.gate.mode().droppedRampMembers, "s5 and s6 dropped from the ramp");
            for (int i = 1; i <= 21; i++) {
                if (i != 5 && i != 6) {
                    assertEquals(0.5, pm.getLinkStiffness("s" + i), 1e-6, "s" + i);
                }
            }
            pm.endRealtimeStepping();
        });
    }

    /** A string "s" and a free mass "free" at rest, with gravity and friction off. */
    static PhysicalModel springAndFreeMass() {
        PhysicalModel pm = new PhysicalModel(44100, 60);
        pm.setStabilityPolicy(StabilityPolicy.OFF);
        pm.addGround3D("g", new Vect3D(0, 0, 0));
        pm.addMass3D("m", 1, new Vect3D(1, 0, 0), new Vect3D());
        pm.addSpringDamper3D("s", 1, 0.01, 0.0001, "g", "m");
        pm.addMass3D("free", 1, new Vect3D(5, 0, 0), new Vect3D(44.1, 0, 0));
        pm.init();
        return pm;
    }

    /**
     * Calls made while holding {@link PhysicalModel#getLock()} go through the queue like any other, in call order:
     * a stiffness set before the lock and then again inside it ends at the second value, and a position set inside
     * the lock on a moving mass is never lost. Twenty rounds, with the owner stepping in buffers of 256.
     */
    @Test
    void callsMadeWhileHoldingTheModelLockAreQueuedInCallOrder() {
        assertTimeoutPreemptively(BOUND, () -> {
            PhysicalModel pm = springAndFreeMass();
            pm.beginRealtimeStepping();
            OwnerLoop owner = new OwnerLoop(pm, 256, 2_000_000L, "audio").begin();
            Ownership own = pm.gate.mode();
            Lock l = pm.getLock();
            for (int round = 0; round < 20; round++) {
                pm.setLinkStiffness("s", 0.1);
                l.lock();
                try {
                    long posted = own.postedSeq();
                    pm.setLinkStiffness("s", 0.2);
                    assertEquals(posted + 1, own.postedSeq(), "the call inside the lock was queued");
                    pm.setMatPosition("free", new Vect3D(100 + round, 0, 0));
                } finally {
                    l.unlock();
                }
                assertEquals(0.2, pm.getLinkStiffness("s"), "round " + round);
                pm.setFriction(0); // a queued parameter change: the getter below waits for it and every earlier poke
                assertEquals(100 + round, pm.getMatPosition("free").x, 1e-9, "round " + round);
            }
            assertTrue(owner.halt());
            assertNull(owner.firstError.get());
            pm.endRealtimeStepping();
            assertEquals(0.2, pm.getLinkStiffness("s"));
            assertEquals(119, pm.getMatPosition("free").x, 1e-9);
        });
    }

    /**
     * A divergence listener calls {@link PhysicalModel#endRealtimeStepping()} on the stepping thread: it returns at
     * once, the stepping thread goes on (no deadlock), the mode has ended when that call returns, and the model is
     * usable from another thread.
     */
    @Test
    void endRealtimeSteppingFromADivergenceListenerDoesNotDeadlock() {
        assertTimeoutPreemptively(BOUND, () -> {
            PhysicalModel pm = divergingModel();
            AtomicBoolean listenerReturned = new AtomicBoolean();
            pm.setDivergenceListener(e -> {
                pm.endRealtimeStepping();
                listenerReturned.set(true);
            });
            pm.init();
            pm.beginRealtimeStepping();
            Thread audio = new Thread(() -> {
                for (int i = 0; i < 300; i++) {
                    pm.computeNSteps(64);
                }
            }, "audio");
            audio.setDaemon(true);
            audio.start();
            audio.join(10_000);
            assertFalse(audio.isAlive(), "the stepping thread finished");
            assertTrue(listenerReturned.get(), "the listener returned");
            assertFalse(pm.isRealtimeStepping(), "the mode ended after the listener's stepping call");
            assertNull(pm.getRealtimeOwner());
            pm.setLinkStiffness("s2", 0.03);
            assertEquals(0.03, pm.getLinkStiffness("s2"));
        });
    }

    /**
     * Under THROW, a structural change refused while a thread steps the model in realtime is undone with a plan
     * prepared by the calling thread, as the change itself was: each refused add installs two prepared plans (the
     * add's and the undo's), so the stepping thread compiled nothing; the model is back as it was.
     */
    @Test
    void underThrowTheUndoOfARefusedStructuralChangeIsCompiledByTheCaller() {
        assertTimeoutPreemptively(BOUND, () -> {
            PhysicalModel pm = new PhysicalModel(44100, 60);
            pm.setStabilityPolicy(StabilityPolicy.THROW);
            pm.addGround3D("g0", new Vect3D(0, 0, 0));
            String prev = "g0";
            for (int i = 1; i <= 200; i++) {
                pm.addMass3D("m" + i, 1, new Vect3D(i, 0, 0), new Vect3D());
                pm.addSpringDamper3D("s" + i, 1, 0.1, 0.001, prev, "m" + i);
                prev = "m" + i;
            }
            pm.init();
            pm.setDivergenceListener(e -> { });
            pm.beginRealtimeStepping();
            OwnerLoop owner = new OwnerLoop(pm, 64, 200_000L, "audio").begin();
            int links = pm.getNumberOfLinks();
            long installs0 = EngineProbe.preparedInstalls(pm);
            for (int round = 0; round < 3; round++) {
                String name = "bad" + round;
                assertThrows(UnstableModelException.class,
                        () -> pm.addSpringDamper3D(name, 1, 1.95, 0.0, "m10", "m20"));
                assertEquals(links, pm.getNumberOfLinks(), "undone");
                assertFalse(pm.linkExists(name));
            }
            assertEquals(installs0 + 6, EngineProbe.preparedInstalls(pm),
                    "every refused add and every undo installed a plan the caller prepared");
            assertTrue(owner.halt());
            assertNull(owner.firstError.get());
            pm.endRealtimeStepping();
        });
    }
}
