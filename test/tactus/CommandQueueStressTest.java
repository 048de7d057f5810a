package tactus;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.locks.Lock;
import java.util.concurrent.locks.LockSupport;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import tactus.internal.realtime.Command;
import tactus.internal.realtime.Ownership;
import tactus.internal.ModelCore;

/**
 * A stress test of the realtime command queue and of the owner hand-over: 1 to 4 producer threads post commands
 * (markers that record their own application, parameter setters, state pokes of modules the owner removes meanwhile,
 * structural changes) while a succession of owner threads steps the model in calls of 1 to 512 steps with varied
 * pauses, goes idle (the role is then set free by a waiting producer and taken back), or ends (the next owner
 * thread takes the role). Asserts: every marker applied exactly once, in per-producer order, by the thread holding
 * the gate; applied + dropped == posted; markers made to fail were counted as dropped; every producer reads back
 * its own last value; nothing is thrown on the owners; the gate is free at the end; all within a bound.
 *
 * <p>Why not Lincheck: its model checker needs deterministic code and a sequential specification; the queue's
 * consumer is a thread identified by identity (the owner role), the hand-over depends on the clock (the idle time)
 * and the operations run the whole engine, so a hand-written stress test that varies threads, batch sizes and
 * timing checks the properties that matter here (per-producer FIFO, exactly once, counts, bounded waits).
 */
class CommandQueueStressTest {
    private static final int VICTIMS = 40;
    /** The victim mass the owners remove next (pokes at it are the likeliest to find it gone when applied). */
    private static final java.util.concurrent.atomic.AtomicInteger NEXT_VICTIM =
            new java.util.concurrent.atomic.AtomicInteger();

    /** A command that checks, when applied, that it comes right after the previous one of its producer. */
    static final class Marker extends Command {
        final Scoreboard board;
        final int producer;
        final int k;

        Marker(Scoreboard board, int producer, int k) {
            this.board = board;
            this.producer = producer;
            this.k = k;
        }

        @Override
        public boolean apply(ModelCore core) {
            board.applied(this, (Ownership) core.own);
            if (k % 13 == 12) {
                throw new IllegalStateException("marker " + k + " fails on purpose");
            }
            return k % 7 != 6; // as if its target were gone
        }
    }

    /** What the markers saw: the next expected number per producer, and any violation. */
    static final class Scoreboard {
        final int[] next;
        final ConcurrentLinkedQueue<String> violations = new ConcurrentLinkedQueue<>();

        Scoreboard(int producers) {
            next = new int[producers];
        }

        void applied(Marker m, Ownership own) {
            if (own == null || !own.isApplying()) {
                violations.add("marker " + m.producer + "/" + m.k + " applied by a thread that does not hold the gate");
            }
            if (next[m.producer] != m.k) {
                violations.add("producer " + m.producer + ": marker " + m.k + " applied, expected " + next[m.producer]);
            }
            next[m.producer] = m.k + 1;
        }
    }

    static PhysicalModel build(int producers) {
        PhysicalModel pm = new PhysicalModel(44100, 60);
        pm.setStabilityPolicy(StabilityPolicy.OFF);
        pm.addGround3D("g", new Vect3D(0, 0, 0));
        for (int p = 0; p < producers; p++) {
            pm.addMass3D("p" + p, 1, new Vect3D(1, p, 0), new Vect3D());
            pm.addSpringDamper3D("k" + p, 1, 0.01, 0.0001, "g", "p" + p);
        }
        for (int v = 0; v < VICTIMS; v++) {
            pm.addMass3D("v" + v, 1, new Vect3D(-1, v, 0), new Vect3D());
        }
        pm.init();
        return pm;
    }

    @ParameterizedTest
    @CsvSource({"1, 1, 1", "1, 64, 2", "1, 512, 3", "2, 1, 4", "2, 64, 5", "2, 512, 6", "3, 1, 7", "3, 64, 8",
            "3, 512, 9", "4, 1, 10", "4, 64, 11", "4, 512, 12"})
    void everyCommandIsAppliedOnceInPerProducerOrderThroughOwnerHandOvers(int producers, int batch, long seed) {
        assertTimeoutPreemptively(Duration.ofSeconds(40), () -> run(producers, batch, seed));
    }

    private static void run(int producers, int batch, long seed) throws Exception {
        PhysicalModel pm = build(producers);
        pm.beginRealtimeStepping();
        Ownership own = pm.gate.mode();
        own.idleNanos = 20_000_000L;
        Scoreboard board = new Scoreboard(producers);
        AtomicBoolean stop = new AtomicBoolean();
        ConcurrentLinkedQueue<Throwable> ownerErrors = new ConcurrentLinkedQueue<>();
        AtomicLong ownerThreads = new AtomicLong();
        Thread owners = new Thread(() -> runOwners(pm, batch, seed, stop, ownerErrors, ownerThreads), "owners");
        owners.setDaemon(true);
        owners.start();

        final int ops = 500;
        int[] markers = new int[producers];
        int[] failing = new int[producers];
        double[] lastK = new double[producers];
        List<Thread> threads = new ArrayList<>();
        ConcurrentLinkedQueue<Throwable> producerErrors = new ConcurrentLinkedQueue<>();
        for (int p = 0; p < producers; p++) {
            final int me = p;
            Thread t = new Thread(() -> {
                Random r = new Random(seed * 131 + me);
                Lock lock = pm.getLock();
                try {
                    for (int i = 0; i < ops; i++) {
                        int op = r.nextInt(20);
                        if (op < 9) {
                            int k = markers[me]++;
                            failing[me] += (k % 13 == 12 || k % 7 == 6) ? 1 : 0;
                            lock.lock();
                            try {
                                own.post(new Marker(board, me, k));
                            } finally {
                                lock.unlock();
                            }
                        } else if (op < 14) {
                            lastK[me] = 0.01 + 1e-5 * i;
                            pm.setLinkStiffness("k" + me, lastK[me]);
                        } else if (op < 16) {
                            assertEquals(lastK[me] == 0 ? 0.01 : lastK[me], pm.getLinkStiffness("k" + me),
                                    "producer " + me + " reads its own last value");
                        } else if (op < 19) {
                            try {
                                int v = r.nextBoolean() ? NEXT_VICTIM.get() : r.nextInt(VICTIMS);
                                pm.setMatPosition("v" + v, new Vect3D(-1, r.nextDouble(), 0));
                            } catch (IllegalArgumentException gone) {
                                // the owner removed it before this call validated the name
                            }
                        } else {
                            String name = "a" + me + "_" + i;
                            pm.addMass3D(name, 1, new Vect3D(2, me, 0), new Vect3D());
                            pm.removeMatAndConnectedLinks(name);
                        }
                        if (r.nextInt(8) == 0) {
                            LockSupport.parkNanos(r.nextInt(300_000));
                        }
                    }
                } catch (Throwable e) {
                    producerErrors.add(e);
                }
            }, "producer " + p);
            threads.add(t);
            t.start();
        }
        for (Thread t : threads) {
            t.join(30_000);
            assertTrue(!t.isAlive(), t.getName() + " finished");
        }
        stop.set(true);
        owners.join(10_000);
        assertTrue(!owners.isAlive(), "the owners ended");
        pm.getLock().lock();
        try {
            own.awaitAll(); // the last owner thread has ended: this thread applies what is left
        } finally {
            pm.getLock().unlock();
        }
        assertTrue(producerErrors.isEmpty(), () -> "producer failed: " + producerErrors.peek());
        assertTrue(ownerErrors.isEmpty(), () -> "thrown on an owner: " + ownerErrors.peek());
        assertTrue(board.violations.isEmpty(), () -> "order violations: " + board.violations);
        int expectedFailing = 0;
        for (int p = 0; p < producers; p++) {
            assertEquals(markers[p], board.next[p], "every marker of producer " + p + " applied exactly once");
            expectedFailing += failing[p];
            if (lastK[p] != 0) {
                assertEquals(lastK[p], pm.getLinkStiffness("k" + p));
            }
        }
        assertEquals(own.postedSeq(), own.appliedSeq(), "everything posted was consumed");
        assertEquals(own.postedSeq(), own.completedCount() + own.droppedCount(), "applied + dropped == posted");
        assertTrue(own.droppedCount() >= expectedFailing, "failing markers counted as dropped: "
                + own.droppedCount() + " < " + expectedFailing);
        assertTrue(own.gateFree(), "the gate is free");
        assertTrue(ownerThreads.get() >= 1);
        long before = pm.getStepCount();
        pm.computeNSteps(3); // the role is free or its holder is dead: this thread takes it and steps
        assertEquals(before + 3, pm.getStepCount());
        pm.endRealtimeStepping();
    }

    /**
     * Successive owner threads: each makes 20 to 200 stepping calls with varied pauses, sometimes goes idle (longer
     * than the idle time) in the middle, sometimes removes a victim mass itself between two calls, then ends.
     */
    private static void runOwners(PhysicalModel pm, int batch, long seed, AtomicBoolean stop,
            ConcurrentLinkedQueue<Throwable> errors, AtomicLong count) {
        Random r = new Random(seed * 7919);
        NEXT_VICTIM.set(0);
        while (!stop.get()) {
            int calls = 20 + r.nextInt(180);
            int idleAt = r.nextInt(3) == 0 ? r.nextInt(calls) : -1;
            long pause = new long[] {0, 20_000, 200_000, 1_000_000}[r.nextInt(4)];
            Thread owner = new Thread(() -> {
                try {
                    for (int c = 0; c < calls && !stop.get(); c++) {
                        pm.computeNSteps(batch);
                        if (c == idleAt) {
                            Thread.sleep(40);
                        }
                        if (c % 11 == 10 && NEXT_VICTIM.get() < VICTIMS) {
                            pm.removeMatAndConnectedLinks("v" + NEXT_VICTIM.getAndIncrement());
                        }
                        if (pause > 0) {
                            LockSupport.parkNanos(pause);
                        }
                    }
                } catch (Throwable t) {
                    errors.add(t);
                }
            }, "owner " + count.get());
            count.incrementAndGet();
            owner.start();
            try {
                owner.join(20_000);
            } catch (InterruptedException e) {
                return;
            }
        }
    }
}
