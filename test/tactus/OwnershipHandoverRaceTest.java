package tactus;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicReference;
import java.util.concurrent.locks.LockSupport;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import tactus.internal.realtime.Ownership;

/**
 * The stepping role of a realtime model moves between threads many times a second
 * ({@link PhysicalModel#takeRealtimeStepping()}) while each of them steps, draws frames and makes facade calls,
 * nested ones included (a divergence listener on the stepping thread reads, moves a mass, clears the divergence
 * and steps again). Rounds vary the thread count (2 to 4), the batch sizes and the timing (back to back,
 * {@code Thread.yield()}, short parks), and end in three ways: every thread dies, every thread goes idle, or the
 * last owner gives the role up with {@link PhysicalModel#endRealtimeStepping()}. After each round the gate must be
 * free, a structural change (adding a mass) from a third thread must return within a bound, no divergence
 * listener may have run on two threads at once, and no thread may have thrown.
 *
 * <p>Regression test of commit 8d2f445: a thread that had just lost the role still passed "do I hold the gate?"
 * (asked with the new owner's nesting depth), made its facade call beside the new owner's step and left that
 * depth one too high, so the gate stayed held after the owner died ({@code PhyUGenTakesRoleTest} on CI).
 */
@Timeout(90)
class OwnershipHandoverRaceTest {
    /** How long the rounds run in all; each round races for {@link #ROUND_NANOS}. */
    private static final long BUDGET_NANOS = 10_000_000_000L;
    private static final long ROUND_NANOS = 40_000_000L;
    private static final int MIN_ROUNDS = 8;
    /** A race-free gate is never held for long; a leaked one makes every wait end after this limit (the default: 10 s). */
    private static final long WAIT_LIMIT_NANOS = 3_000_000_000L;
    private static final Vect3D X0 = new Vect3D(1, 0.01, 0);

    private enum Ending { DIES, IDLES, RELEASES }

    @Test
    void theGateIsFreeAndAThirdThreadsEditReturnsAfterTheRoleMovedBetweenThreads() {
        assertTimeoutPreemptively(Duration.ofSeconds(80), () -> {
            long seed = System.nanoTime();
            Random rnd = new Random(seed);
            PrintStream err = System.err;
            ByteArrayOutputStream printed = new ByteArrayOutputStream();
            long hooks = 0;
            long handOvers = 0;
            int rounds = 0;
            try {
                System.setErr(new PrintStream(printed, true, "UTF-8"));
                long end = System.nanoTime() + BUDGET_NANOS;
                while (rounds < MIN_ROUNDS || System.nanoTime() < end) {
                    int threads = 2 + rnd.nextInt(3);
                    Ending ending = Ending.values()[rounds % 3];
                    Round r = new Round(rounds, threads, ending, rnd.nextLong());
                    r.run();
                    hooks += r.hooks.get();
                    handOvers += r.handOvers;
                    rounds++;
                }
            } finally {
                System.setErr(err);
            }
            System.out.println("OwnershipHandoverRaceTest: " + rounds + " rounds, " + handOvers + " hand-overs, "
                    + hooks + " listener calls (seed " + seed + ")");
            String out = new String(printed.toByteArray(), StandardCharsets.UTF_8);
            for (String line : out.split("\n")) {
                assertTrue(line.isEmpty() || line.contains("this model is stepped in realtime"),
                        "seed " + seed + ": nothing but the refusal message is printed, got: " + out);
            }
            assertTrue(hooks > 0, "seed " + seed + ": the divergence listener (the probe) ran");
            assertTrue(handOvers >= rounds, "seed " + seed + ": the role moved (" + handOvers + " hand-overs in "
                    + rounds + " rounds)");
        });
    }

    /** One model, {@code threads} stepping threads racing for the role, then an ending and the checks. */
    private static final class Round {
        final int index, threads;
        final Ending ending;
        final long seed;
        final PhysicalModel pm = model();
        final Ownership own;
        final AtomicBoolean stop = new AtomicBoolean();
        final AtomicInteger inside = new AtomicInteger();
        final AtomicInteger maxInside = new AtomicInteger();
        final AtomicLong hooks = new AtomicLong();
        final AtomicReference<Throwable> error = new AtomicReference<>();
        final CountDownLatch quiet;
        final CountDownLatch resume = new CountDownLatch(1);
        long handOvers;

        Round(int index, int threads, Ending ending, long seed) {
            this.index = index;
            this.threads = threads;
            this.ending = ending;
            this.seed = seed;
            this.quiet = new CountDownLatch(threads);
            pm.setDivergenceListener(e -> {
                int n = inside.incrementAndGet();
                maxInside.accumulateAndGet(n, Math::max);
                try {
                    hooks.incrementAndGet();
                    pm.getMatPosition("m"); // nested facade calls on the stepping thread
                    pm.setMatPosition("x", X0);
                    pm.clearDivergence();
                    pm.computeNSteps(1); // a nested stepping call
                } finally {
                    inside.decrementAndGet();
                }
            });
            pm.beginRealtimeStepping();
            own = pm.gate.mode();
            own.idleNanos = 20_000_000L;
            own.waitLimitNanos = WAIT_LIMIT_NANOS;
        }

        /** A stable mass "m" and a mass "x" on a spring too stiff to be stable: it diverges every few steps. */
        private static PhysicalModel model() {
            PhysicalModel pm = new PhysicalModel(44100, 60);
            pm.setStabilityPolicy(StabilityPolicy.OFF);
            pm.addGround3D("g", new Vect3D(0, 0, 0));
            pm.addMass3D("m", 1, new Vect3D(1, 0.1, 0), new Vect3D());
            pm.addSpringDamper3D("s", 1, 0.01, 0.0001, "g", "m");
            pm.addMass3D("x", 1, X0, new Vect3D());
            pm.addSpringDamper3D("sx", 1, 5.0, 0.0, "g", "x");
            pm.setDivergenceLimit(1e3);
            pm.setDivergenceCheckInterval(4);
            pm.init();
            return pm;
        }

        private String what() {
            return "round " + index + " (" + threads + " threads, ends: " + ending + ", seed " + seed + ", "
                    + own.handOvers() + " hand-overs)";
        }

        void run() throws Exception {
            List<Thread> workers = new ArrayList<>();
            for (int t = 0; t < threads; t++) {
                int id = t;
                long s = seed + t;
                Thread w = new Thread(() -> work(id, new Random(s)), "stepper " + t);
                w.setDaemon(true);
                workers.add(w);
            }
            workers.forEach(Thread::start);
            Thread.sleep(ROUND_NANOS / 1_000_000);
            stop.set(true);
            if (ending == Ending.IDLES) {
                assertTrue(quiet.await(20, TimeUnit.SECONDS), what() + ": the threads went idle");
                checkGateAndEdit();
                resume.countDown(); // each steps once more: takes the role back
            }
            for (Thread w : workers) {
                w.join(20_000);
                assertFalse(w.isAlive(), what() + ": " + w.getName() + " ended");
            }
            assertNull(error.get(), () -> what() + ": a stepping thread threw " + error.get());
            if (ending == Ending.RELEASES) {
                assertFalse(pm.isRealtimeStepping(), what() + ": the last owner ended the mode");
                assertNull(own.owner(), what() + ": nobody holds the role");
            }
            checkGateAndEdit();
            assertTrue(maxInside.get() <= 1,
                    what() + ": the divergence listener ran on two threads at once (two steps at once)");
            handOvers = own.handOvers();
        }

        /** The gate is free, and a structural change from a third thread returns (and is applied). */
        private void checkGateAndEdit() {
            assertTrue(own.gateFree(), () -> what() + ": the gate is held with no stepping thread in a call (owner "
                    + own.owner() + ")");
            String probe = "probe" + pm.getNumberOfMats();
            try {
                assertTimeoutPreemptively(Duration.ofSeconds(10),
                        () -> pm.addMass3D(probe, 1, new Vect3D(0, -1, 0), new Vect3D()),
                        () -> what() + ": adding a mass from a third thread");
            } catch (IllegalStateException e) {
                fail(what() + ": adding a mass from a third thread threw " + e, e);
            }
            assertTrue(pm.matExists(probe), what() + ": the mass was added");
            assertTrue(own.gateFree(), () -> what() + ": the gate is free after the edit");
        }

        private void work(int id, Random rnd) {
            int jitter = rnd.nextInt(3); // 0: back to back, 1: Thread.yield(), 2: parks of up to 30 µs
            int batch = 1 + rnd.nextInt(128);
            boolean idle = false;
            try {
                while (!stop.get()) {
                    switch (rnd.nextInt(6)) {
                        case 0:
                            pm.takeRealtimeStepping();
                            break;
                        case 1:
                            pm.takeRealtimeStepping();
                            pm.computeNSteps(batch);
                            break;
                        case 2:
                            pm.draw_physics();
                            break;
                        case 3:
                            pm.computeNSteps(1 + rnd.nextInt(batch));
                            break;
                        case 4:
                            pm.getMatPosition("m");
                            break;
                        default:
                            pm.setLinkStiffness("s", 0.01 + 0.01 * rnd.nextDouble());
                            break;
                    }
                    if (jitter == 1) {
                        Thread.yield();
                    } else if (jitter == 2) {
                        LockSupport.parkNanos(rnd.nextInt(30_000));
                    }
                }
                if (ending == Ending.IDLES) {
                    idle = true;
                    quiet.countDown();
                    resume.await(20, TimeUnit.SECONDS);
                    pm.computeNSteps(8);
                } else if (ending == Ending.RELEASES && id == 0) {
                    pm.takeRealtimeStepping();
                    pm.computeNSteps(4);
                    pm.endRealtimeStepping(); // the owner between two calls gives the role up and ends the mode
                }
            } catch (Throwable t) {
                error.compareAndSet(null, t);
                if (!idle) {
                    quiet.countDown();
                }
            }
        }
    }
}
