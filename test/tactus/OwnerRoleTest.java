package tactus;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import tactus.internal.realtime.Ownership;

/**
 * The owner role of a realtime-stepped model ({@link PhysicalModel#beginRealtimeStepping()}): exactly one thread
 * steps it; the first stepping thread takes the role, {@link PhysicalModel#endRealtimeStepping()} gives it back, a
 * dead or idle owner's role is handed over explicitly, and a stepping call from another thread while the owner is
 * active does nothing and says so once.
 */
class OwnerRoleTest {
    private static final Duration BOUND = Duration.ofSeconds(30);

    static PhysicalModel oscillator() {
        PhysicalModel pm = new PhysicalModel(44100, 60);
        pm.setStabilityPolicy(StabilityPolicy.OFF);
        pm.addGround3D("g", new Vect3D(0, 0, 0));
        pm.addMass3D("m", 1, new Vect3D(1, 0.1, 0), new Vect3D());
        pm.addSpringDamper3D("s", 1, 0.01, 0.0001, "g", "m");
        pm.init();
        return pm;
    }

    @Test
    void theFirstSteppingThreadTakesTheRoleAndEndingTheModeGivesItBack() {
        assertTimeoutPreemptively(BOUND, () -> {
            PhysicalModel pm = oscillator();
            assertNull(pm.getRealtimeOwner(), "not realtime");
            pm.beginRealtimeStepping();
            assertNull(pm.getRealtimeOwner(), "nobody has stepped yet");
            pm.setLinkStiffness("s", 0.02); // no owner: applied at once by the calling thread
            assertEquals(0.02, pm.getLinkStiffness("s"));
            OwnerLoop owner = new OwnerLoop(pm, 64, 100_000L, "audio").begin();
            assertSame(owner, pm.getRealtimeOwner());
            assertTrue(owner.halt());
            pm.endRealtimeStepping();
            assertFalse(pm.isRealtimeStepping());
            assertNull(pm.getRealtimeOwner());
            long before = pm.getStepCount();
            pm.computeNSteps(10); // locked mode again: any thread steps
            assertEquals(before + 10, pm.getStepCount());
        });
    }

    /**
     * While an owner steps, draw_physics(), computeStep() and computeNSteps() from another thread (a sketch that kept
     * draw_physics() in draw() after adding a PhyUGen) step nothing: the model's step count is exactly the owner's,
     * and one message, printed once, says what to do.
     */
    @Test
    void steppingCallsFromAnotherThreadDoNothingAndSaySoOnce() {
        assertTimeoutPreemptively(BOUND, () -> {
            PhysicalModel pm = oscillator();
            pm.beginRealtimeStepping();
            OwnerLoop owner = new OwnerLoop(pm, 64, 100_000L, "audio").begin();
            PrintStream err = System.err;
            ByteArrayOutputStream captured = new ByteArrayOutputStream();
            int[] drawReturns = new int[1];
            try {
                System.setErr(new PrintStream(captured, true, "UTF-8"));
                Thread draw = new Thread(() -> {
                    for (int frame = 0; frame < 50; frame++) {
                        drawReturns[0] += pm.draw_physics();
                        pm.computeStep();
                        pm.computeNSteps(100);
                    }
                }, "Animation Thread");
                draw.start();
                draw.join(20_000);
                assertFalse(draw.isAlive());
            } finally {
                System.setErr(err);
            }
            assertTrue(owner.halt());
            assertNull(owner.firstError.get());
            assertEquals(64 * owner.calls.get(), pm.getStepCount(), "only the owner stepped");
            assertEquals(0, drawReturns[0], "draw_physics() reports no step");
            assertEquals(150, pm.gate.mode().refusedCalls());
            String out = new String(captured.toByteArray(), StandardCharsets.UTF_8);
            int lines = out.split("this model is stepped in realtime", -1).length - 1;
            assertEquals(1, lines, "one message: " + out);
            assertTrue(out.contains("draw_physics(): this model is stepped in realtime by thread \"audio\""), out);
            assertTrue(out.contains("Remove draw_physics() from draw()"), out);
            pm.endRealtimeStepping();
        });
    }

    /** The owner thread ends (Minim's output closed): the next stepping thread takes the role at once. */
    @Test
    void aDeadOwnersRoleIsTakenByTheNextSteppingThread() {
        assertTimeoutPreemptively(BOUND, () -> {
            PhysicalModel pm = oscillator();
            pm.beginRealtimeStepping();
            Thread first = new Thread(() -> pm.computeNSteps(100), "first audio");
            first.start();
            first.join(10_000);
            assertSame(first, pm.getRealtimeOwner());
            long handOvers = pm.gate.mode().handOvers();
            pm.computeNSteps(50);
            assertEquals(150, pm.getStepCount());
            assertSame(Thread.currentThread(), pm.getRealtimeOwner());
            assertEquals(handOvers + 1, pm.gate.mode().handOvers());
            pm.endRealtimeStepping(); // from the owner, between two calls: never waits for itself
            assertFalse(pm.isRealtimeStepping());
        });
    }

    /**
     * The owner stops stepping without ending the mode (audio paused): a getter that must wait for the queue sets the
     * role free after the idle time and applies the queue itself; the owner, when it steps again, takes the role back
     * and every one of its calls steps (none is skipped).
     */
    @Test
    void anIdleOwnersRoleIsSetFreeByAWaitingThreadAndTakenBackWhenItSteps() {
        assertTimeoutPreemptively(BOUND, () -> {
            PhysicalModel pm = oscillator();
            pm.beginRealtimeStepping();
            Ownership own = pm.gate.mode();
            own.idleNanos = 30_000_000L;
            CountDownLatch paused = new CountDownLatch(1);
            CountDownLatch resume = new CountDownLatch(1);
            long[] steps = new long[2];
            Thread audio = new Thread(() -> {
                for (int i = 0; i < 10; i++) {
                    pm.computeNSteps(64);
                }
                paused.countDown();
                try {
                    resume.await(20, TimeUnit.SECONDS);
                } catch (InterruptedException e) {
                    return;
                }
                for (int i = 0; i < 10; i++) {
                    long before = pm.getStepCount();
                    pm.computeNSteps(64);
                    steps[1] += pm.getStepCount() - before;
                }
            }, "audio");
            audio.start();
            assertTrue(paused.await(10, TimeUnit.SECONDS));
            assertSame(audio, pm.getRealtimeOwner());
            Thread.sleep(60);
            long handOvers = own.handOvers();
            pm.setLinkStiffness("s", 0.03);
            assertEquals(0.03, pm.getLinkStiffness("s"), "applied by this thread for the idle owner");
            assertNull(pm.getRealtimeOwner(), "the role was set free");
            assertEquals(handOvers + 1, own.handOvers());
            resume.countDown();
            audio.join(10_000);
            assertEquals(640, steps[1], "no stepping call was skipped");
            assertSame(audio, pm.getRealtimeOwner(), "the owner took its role back");
            assertEquals(1280, pm.getStepCount());
            assertTrue(own.gateFree());
            pm.endRealtimeStepping();
        });
    }
}
