package tactus;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.management.ManagementFactory;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.Consumer;
import java.util.concurrent.locks.LockSupport;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.api.Test;
import tactus.internal.realtime.Ownership;

/**
 * Realtime stepping ({@link PhysicalModel#beginRealtimeStepping()}): the stepping thread takes no lock, other threads'
 * changes (parameters, subsets, the medium, positions, velocities, impulses, controller ramps) are queued and applied
 * between two stepping calls, in order, each exactly once; the result is bit for bit
 * the one of applying the same changes synchronously at the same step; and the stepping thread neither waits nor
 * allocates while changes arrive.
 */
class RealtimeSteppingTest {
    static final int MASSES = 20;

    /** A string of Mass3D between two fixed points, with an oscillator hanging off its middle, plucked. */
    static PhysicalModel build() {
        PhysicalModel pm = new PhysicalModel(44100, 60);
        pm.addGround3D("g0", new Vect3D(0, 0, 0));
        for (int i = 0; i < MASSES; i++) {
            pm.addMass3D("m" + i, 1, new Vect3D(i + 1, i == 5 ? 0.3 : 0, 0), new Vect3D());
        }
        pm.addGround3D("g1", new Vect3D(MASSES + 1, 0, 0));
        pm.createLinkSubset("half");
        for (int i = 0; i <= MASSES; i++) {
            String a = i == 0 ? "g0" : "m" + (i - 1);
            String b = i == MASSES ? "g1" : "m" + i;
            pm.addSpringDamper3D("s" + i, 1, 0.1, 0.001, a, b);
            if (i < 10) {
                pm.addLinkToSubset("s" + i, "half");
            }
        }
        pm.addOsc3D("osc", 1, 0.05, 0.0001, new Vect3D(11, 1, 0), new Vect3D());
        pm.addSpringDamper3D("so", 1, 0.02, 0.0001, "osc", "m10");
        // gravity and friction stay on: switching either on or off changes the step plan (a recompilation)
        pm.setGravity(1e-6);
        pm.setFriction(1e-6);
        pm.createLinkSubset("tail");
        for (int i = 15; i <= MASSES; i++) {
            pm.addLinkToSubset("s" + i, "tail");
        }
        pm.addHapticInput3D("avatar", new Vect3D(5, 0.5, 0), 30);
        pm.addContact3D("touch", 1, 0.05, 0.001, "avatar", "m4");
        pm.addParamController("ramp", "tail", "stiffness", 0.005f);
        pm.getParamController("ramp").init(0.1f);
        pm.init();
        return pm;
    }

    /** One facade call with its random values fixed, so that it can be made on two models. */
    static List<Consumer<PhysicalModel>> changes(long seed, int count) {
        Random r = new Random(seed);
        List<Consumer<PhysicalModel>> list = new ArrayList<>();
        for (int i = 0; i < count; i++) {
            double v = r.nextDouble();
            switch (r.nextInt(13)) {
                case 0: list.add(pm -> pm.setLinkStiffness("s3", 0.05 + 0.1 * v)); break;
                case 1: list.add(pm -> pm.setLinkDamping("s3", 0.0005 + 0.001 * v)); break;
                case 2: list.add(pm -> pm.setMatMass("m5", 0.8 + 0.4 * v)); break;
                case 3: list.add(pm -> pm.changeParamOfSubset(0.05 + 0.1 * v, "half", "stiffness")); break;
                case 4: list.add(pm -> pm.setGravity(1e-6 + 1e-5 * v)); break;
                case 5: list.add(pm -> pm.setFriction(1e-6 + 1e-5 * v)); break;
                case 6: list.add(pm -> pm.setMatPosition("m7", new Vect3D(8, 0.2 * v, 0))); break;
                case 7: list.add(pm -> pm.setMatVelocity("m8", new Vect3D(0, 10 * v, 0))); break;
                case 8: list.add(pm -> pm.triggerForceImpulse("m9", 0, 0.01 * v, 0)); break;
                case 9: list.add(pm -> pm.setLinkParamsForName("s1", 0.05 + 0.1 * v, 0.001, 1)); break;
                case 10: list.add(pm -> pm.setMatStiffness("osc", 0.02 + 0.05 * v)); break;
                case 11: list.add(pm -> pm.setLinkDRest("s12", 0.9 + 0.2 * v)); break;
                default: list.add(pm -> pm.getParamController("ramp").triggerRamp((float) (0.05 + 0.1 * v))); break;
            }
        }
        return list;
    }

    /**
     * An owner thread steps the model in calls of {@code batch} steps while the test thread makes random changes at
     * random moments (bursts of up to {@code burst} calls back to back). From the sequence numbers, each change is
     * assigned the stepping call that applied it; a second model, stepped without realtime mode, gets the same
     * changes synchronously at those steps, and both trajectories must agree bit for bit.
     */
    @ParameterizedTest
    @CsvSource({"1, 1, 11", "1, 5, 12", "7, 3, 13", "64, 1, 14", "64, 8, 15", "256, 4, 16"})
    void queuedChangesMatchSynchronousChangesAtTheSameStep(int batch, int burst, long seed) throws Exception {
        PhysicalModel live = build();
        live.beginRealtimeStepping();
        List<Consumer<PhysicalModel>> ops = changes(seed, 240);
        Race race = Race.run(live, ops, batch, burst, seed);
        assertEquals(ops.size(), live.gate.mode().postedSeq(), "every call posted exactly one command");
        PhysicalModel ref = race.replayMatches(ops, batch);
        assertEquals(ref.getLinkStiffness("s3"), live.getLinkStiffness("s3"));
        assertEquals(ref.getLinkDamping("s3"), live.getLinkDamping("s3"));
        assertEquals(ref.getMatMass("m5"), live.getMatMass("m5"));
        live.endRealtimeStepping();
    }

    /**
     * The random changes of {@link #changes} with structural ones mixed in (about one call in six), each a single
     * facade call: a new mass near the string, a spring from it to the string, the removal of that spring, the
     * removal of the mass, in that order, again and again.
     */
    static List<Consumer<PhysicalModel>> changesWithStructure(long seed, int count) {
        Random r = new Random(seed ^ 0x5eed);
        List<Consumer<PhysicalModel>> params = changes(seed, count);
        List<Consumer<PhysicalModel>> list = new ArrayList<>();
        int phase = 0;
        for (int i = 0; i < count; i++) {
            if (r.nextInt(6) != 0) {
                list.add(params.get(i));
                continue;
            }
            int k = phase / 4;
            int at = 2 + k % (MASSES - 4);
            double v = r.nextDouble();
            switch (phase++ % 4) {
                case 0: list.add(pm -> pm.addMass3D("x" + k, 1, new Vect3D(at + 1, 1 + 0.1 * v, 0), new Vect3D()));
                    break;
                case 1: list.add(pm -> pm.addSpringDamper3D("lx" + k, 1, 0.05 + 0.05 * v, 0.001, "x" + k,
                        "m" + at));
                    break;
                case 2: list.add(pm -> pm.removeLink("lx" + k)); break;
                default: list.add(pm -> pm.removeMatAndConnectedLinks("x" + k)); break;
            }
        }
        return list;
    }

    /**
     * Structural changes made while the owner steps (batches of 1 to 256 steps, varied timing): the editor compiles
     * the new plan on its own thread while the owner keeps stepping the old one, and the owner only swaps it in.
     * Every change, structural or not, gives bit for bit the trajectory of the same change applied synchronously at
     * the step where it took effect (for a structural change: where the new plan was installed), and every
     * structural change was installed from a plan prepared by the editor (the owner compiled nothing).
     */
    @ParameterizedTest
    @CsvSource({"1, 1, 21", "1, 4, 22", "7, 2, 23", "64, 1, 24", "64, 6, 25", "256, 3, 26"})
    void structuralChangesMatchSynchronousChangesAtTheInstallStep(int batch, int burst, long seed) throws Exception {
        PhysicalModel live = build();
        live.beginRealtimeStepping();
        List<Consumer<PhysicalModel>> ops = changesWithStructure(seed, 160);
        long installs0 = live.core.engine.preparedInstalls();
        Race race = Race.run(live, ops, batch, burst, seed);
        assertTrue(race.structural >= 10, "structural changes made: " + race.structural);
        assertEquals(race.structural, live.core.engine.preparedInstalls() - installs0,
                "every structural change installed a plan prepared by the editor");
        PhysicalModel ref = race.replayMatches(ops, batch);
        assertEquals(ref.getNumberOfMats(), live.getNumberOfMats());
        assertEquals(ref.getNumberOfLinks(), live.getNumberOfLinks());
        live.endRealtimeStepping();
    }

    /**
     * One race of the two tests above: an owner thread steps {@code live} in calls of {@code batch} steps while the
     * test thread makes the changes at random moments (bursts of up to {@code burst} calls back to back), then
     * {@link #replayMatches} replays them synchronously on a second model at the steps where they took effect.
     */
    static final class Race {
        final PhysicalModel live;
        final long[] seqOf;
        /** {step count before the call, applied seq after it}, one per stepping call of the owner. */
        final List<long[]> calls = new ArrayList<>();
        /** m5's y after each stepping call. */
        final List<Double> trace = new ArrayList<>();
        /** Calls that posted more than one command (a structural call posts its run and its install). */
        int structural;

        private Race(PhysicalModel live, int changes) {
            this.live = live;
            this.seqOf = new long[changes];
        }

        static Race run(PhysicalModel live, List<Consumer<PhysicalModel>> ops, int batch, int burst, long seed)
                throws InterruptedException {
            Ownership own = live.gate.mode();
            Race r = new Race(live, ops.size());
            AtomicBoolean editorDone = new AtomicBoolean();
            AtomicReference<Throwable> failure = new AtomicReference<>();
            Thread owner = new Thread(() -> {
                try {
                    int after = 0;
                    while (after < 20) {
                        if (editorDone.get()) {
                            after++;
                        }
                        long before = live.getStepCount();
                        live.computeNSteps(batch);
                        r.calls.add(new long[] {before, own.appliedSeq()});
                        r.trace.add(live.getMatPosition("m5").y);
                        if ((r.calls.size() & 7) == 0) {
                            LockSupport.parkNanos(20_000L); // let the editor in at varied points
                        }
                    }
                } catch (Throwable t) {
                    failure.set(t);
                }
            }, "test owner");
            owner.start();
            Random timing = new Random(seed * 31);
            for (int i = 0; i < ops.size(); i++) {
                long before = own.postedSeq();
                ops.get(i).accept(live);
                r.seqOf[i] = own.postedSeq(); // for a structural call, its install: where it took effect
                r.structural += r.seqOf[i] - before > 1 ? 1 : 0;
                if (timing.nextInt(burst) == 0) {
                    LockSupport.parkNanos(timing.nextInt(300_000));
                }
            }
            editorDone.set(true);
            owner.join(60_000);
            assertNull(failure.get(), () -> "owner failed: " + failure.get());
            assertEquals(own.postedSeq(), own.appliedSeq(), "every command applied");
            return r;
        }

        /**
         * Gives each change the step where it took effect (the start of the first stepping call whose applied seq
         * covers it), applies it synchronously at that step to a new model stepped in the same calls, and asserts
         * that both trajectories agree bit for bit, after every call and for every string mass at the end.
         *
         * @return the reference model, for the caller's own comparisons
         */
        PhysicalModel replayMatches(List<Consumer<PhysicalModel>> ops, int batch) {
            long[] stepOf = new long[ops.size()];
            int c = 0;
            for (int i = 0; i < ops.size(); i++) {
                while (calls.get(c)[1] < seqOf[i]) {
                    c++;
                }
                stepOf[i] = calls.get(c)[0];
            }
            PhysicalModel ref = build();
            int next = 0;
            for (int k = 0; k < calls.size(); k++) {
                long start = calls.get(k)[0];
                while (next < ops.size() && stepOf[next] == start) {
                    ops.get(next++).accept(ref);
                }
                ref.computeNSteps(batch);
                assertEquals(trace.get(k), ref.getMatPosition("m5").y, "m5 after stepping call " + k + " (step "
                        + (start + batch) + ")");
            }
            assertEquals(ops.size(), next);
            for (int i = 0; i < MASSES; i++) {
                Vect3D a = live.getMatPosition("m" + i);
                Vect3D b = ref.getMatPosition("m" + i);
                assertEquals(b.x, a.x, "m" + i + ".x");
                assertEquals(b.y, a.y, "m" + i + ".y");
                assertEquals(b.z, a.z, "m" + i + ".z");
            }
            return ref;
        }
    }

    /**
     * Three threads: the owner steps, two editors each raise their own parameter through 1..N (one a link stiffness
     * set by name, one a subset's damping). Every value read back by its editor right after the call is the one it
     * set (getters see queued changes); the owner, reading the engine between its calls, sees each parameter only
     * rise (no reordering) and, at the end, at N (nothing lost).
     */
    @Test
    void noLostOrReorderedCommandsUnderThreeThreads() throws Exception {
        PhysicalModel pm = build();
        pm.setStabilityPolicy(StabilityPolicy.OFF);
        pm.setLinkStiffness("s7", 0);
        pm.changeDampingParamOfSubset(0, "half");
        pm.beginRealtimeStepping();
        final int n = 3000;
        AtomicBoolean stop = new AtomicBoolean();
        AtomicReference<Throwable> failure = new AtomicReference<>();
        AtomicLong observations = new AtomicLong();
        Thread owner = new Thread(() -> {
            double lastK = 0;
            double lastZ = 0;
            try {
                while (!stop.get()) {
                    pm.computeNSteps(16);
                    double k = pm.getLinkStiffness("s7") * 1e4;
                    double z = pm.getLinkDamping("s2") * 1e5;
                    if (k < lastK || z < lastZ) {
                        throw new AssertionError("a parameter went back: " + lastK + " -> " + k + ", " + lastZ + " -> "
                                + z);
                    }
                    lastK = k;
                    lastZ = z;
                    observations.incrementAndGet();
                }
            } catch (Throwable t) {
                failure.set(t);
            }
        }, "test owner");
        Thread editorK = new Thread(() -> {
            try {
                for (int i = 1; i <= n; i++) {
                    pm.setLinkStiffness("s7", i * 1e-4);
                    if (i % 10 == 0) {
                        assertEquals(i * 1e-4, pm.getLinkStiffness("s7"), "read back after " + i);
                    }
                }
            } catch (Throwable t) {
                failure.compareAndSet(null, t);
            }
        }, "editor K");
        Thread editorZ = new Thread(() -> {
            try {
                for (int i = 1; i <= n; i++) {
                    pm.changeDampingParamOfSubset(i * 1e-5, "half");
                    if (i % 10 == 0) {
                        assertEquals(i * 1e-5, pm.getParamValueOfSubset("half", "damping"), "read back after " + i);
                    }
                }
            } catch (Throwable t) {
                failure.compareAndSet(null, t);
            }
        }, "editor Z");
        owner.start();
        editorK.start();
        editorZ.start();
        editorK.join(120_000);
        editorZ.join(120_000);
        pm.getStepCount(); // waits until everything queued is applied
        Thread.sleep(20);
        stop.set(true);
        owner.join(60_000);
        assertNull(failure.get(), () -> String.valueOf(failure.get()));
        assertTrue(observations.get() > 0);
        assertEquals(n * 1e-4, pm.getLinkStiffness("s7"));
        for (int i = 0; i < 10; i++) {
            assertEquals(n * 1e-5, pm.getLinkDamping("s" + i), "s" + i);
        }
        assertEquals(pm.gate.mode().postedSeq(), pm.gate.mode().appliedSeq());
        pm.endRealtimeStepping();
    }

    /**
     * An editor holds the model's lock for 200 ms (as a long stability analysis of a big model would); the owner keeps
     * stepping the whole time, and a change queued just before is applied meanwhile.
     */
    @Test
    void theSteppingThreadNeverWaitsForTheLock() throws Exception {
        PhysicalModel pm = build();
        pm.beginRealtimeStepping();
        AtomicLong steps = new AtomicLong();
        AtomicBoolean stop = new AtomicBoolean();
        Thread owner = new Thread(() -> {
            while (!stop.get()) {
                pm.computeStep();
                steps.incrementAndGet();
            }
        }, "test owner");
        owner.start();
        while (steps.get() < 1000) {
            Thread.sleep(1);
        }
        pm.setLinkStiffness("s4", 0.123);
        long posted = pm.gate.mode().postedSeq();
        pm.getLock().lock();
        long during;
        try {
            long before = steps.get();
            Thread.sleep(200);
            during = steps.get() - before;
            assertTrue(pm.gate.mode().appliedSeq() >= posted, "the queued change was applied while the lock was held");
        } finally {
            pm.getLock().unlock();
        }
        stop.set(true);
        owner.join(10_000);
        assertTrue(during > 100, "the owner stepped while another thread held the lock: " + during + " steps");
        assertEquals(0.123, pm.getLinkStiffness("s4"));
        pm.endRealtimeStepping();
    }

    /**
     * The owner allocates nothing per step while an editor queues parameter and state changes every few hundred
     * microseconds (it allocates the commands; the owner only applies them). Six rounds of 100,000 steps: less than a
     * byte per 50 steps in every round after the first (the JIT settling), and at least one round with none at all.
     */
    @Test
    void theSteppingThreadAllocatesNothingWhileChangesArrive() throws Exception {
        com.sun.management.ThreadMXBean mx = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        PhysicalModel pm = build();
        pm.beginRealtimeStepping();
        long[] bytes = new long[6];
        AtomicBoolean stop = new AtomicBoolean();
        AtomicLong applied = new AtomicLong();
        Thread editor = new Thread(() -> {
            Random r = new Random(5);
            List<Consumer<PhysicalModel>> ops = changes(7, 4000);
            int i = 0;
            while (!stop.get()) {
                ops.get(i++ % ops.size()).accept(pm);
                LockSupport.parkNanos(200_000L + r.nextInt(200_000));
            }
        }, "editor");
        AtomicReference<Throwable> failure = new AtomicReference<>();
        Thread owner = new Thread(() -> {
            try {
                long id = Thread.currentThread().getId();
                for (int round = 0; round < bytes.length; round++) {
                    long seq0 = pm.gate.mode().appliedSeq();
                    long a0 = mx.getThreadAllocatedBytes(id);
                    for (int s = 0; s < 100_000; s++) {
                        pm.computeStep();
                    }
                    bytes[round] = mx.getThreadAllocatedBytes(id) - a0;
                    applied.addAndGet(pm.gate.mode().appliedSeq() - seq0);
                }
            } catch (Throwable t) {
                failure.set(t);
            }
        }, "test owner");
        owner.start();
        editor.start();
        owner.join(120_000);
        stop.set(true);
        editor.join(10_000);
        assertNull(failure.get(), () -> String.valueOf(failure.get()));
        assertTrue(applied.get() > 10, "changes were applied during the measurement: " + applied.get());
        // an allocation per step, even of one 16-byte object, would show as 1.6 MB per round; what the JIT may still
        // do (a deoptimization materialising an eliminated object, about a kilobyte once) stays far below that
        boolean someRoundClean = false;
        for (int round = 1; round < bytes.length; round++) {
            assertTrue(bytes[round] < 100_000 / 50, "bytes allocated by the owner in round " + round + " of "
                    + java.util.Arrays.toString(bytes));
            someRoundClean |= bytes[round] == 0;
        }
        assertTrue(someRoundClean, "no round without allocation: " + java.util.Arrays.toString(bytes));
        pm.endRealtimeStepping();
    }

    /**
     * A haptic thread reads the avatar's force about every millisecond while the owner steps: it never waits for the
     * owner, and the sum of its reads is the force summed over every step, the same (to rounding) as one read of the
     * same model stepped without realtime mode.
     */
    @Test
    void avatarForceReadByAnotherThreadIsConserved() throws Exception {
        PhysicalModel live = build();
        live.beginRealtimeStepping();
        final int calls = 1500;
        AtomicBoolean done = new AtomicBoolean();
        Thread owner = new Thread(() -> {
            for (int i = 0; i < calls; i++) {
                live.computeNSteps(64);
                if ((i & 15) == 0) {
                    LockSupport.parkNanos(100_000L);
                }
            }
            done.set(true);
        }, "test owner");
        double[] sum = new double[3];
        int reads = 0;
        owner.start();
        Vect3D f = new Vect3D();
        while (!done.get()) {
            live.getHapticForce("avatar", f);
            sum[0] += f.x;
            sum[1] += f.y;
            sum[2] += f.z;
            reads++;
            LockSupport.parkNanos(1_000_000L);
        }
        owner.join(60_000);
        live.getHapticForce("avatar", f);
        sum[0] += f.x;
        sum[1] += f.y;
        sum[2] += f.z;
        PhysicalModel ref = build();
        for (int i = 0; i < calls; i++) {
            ref.computeNSteps(64);
        }
        Vect3D total = ref.getHapticForce("avatar");
        assertTrue(reads > 10, "reads: " + reads);
        assertTrue(Math.abs(total.y) > 1e-3, "the contact pushes: " + total);
        assertEquals(total.x, sum[0], 1e-9 * Math.abs(total.y) + 1e-12);
        assertEquals(total.y, sum[1], 1e-9 * Math.abs(total.y));
        assertEquals(total.z, sum[2], 1e-9 * Math.abs(total.y) + 1e-12);
        live.endRealtimeStepping();
    }

    /**
     * Realtime stepping begun before the model is built (as a PhyUGen subclass does in its constructor): with no
     * owner stepping yet, every change (including a structural call made from inside another, addOsc3DTuned) is
     * applied at once by the calling thread, and the model steps like one built without realtime mode.
     */
    @Test
    void buildingWithNoOwnerYetAppliesEverythingAtOnce() {
        org.junit.jupiter.api.Assertions.assertTimeoutPreemptively(java.time.Duration.ofSeconds(20), () -> {
            PhysicalModel plain = new PhysicalModel(44100, 60);
            PhysicalModel rt = new PhysicalModel(44100, 60);
            rt.beginRealtimeStepping();
            for (PhysicalModel pm : new PhysicalModel[] {plain, rt}) {
                pm.addGround3D("g", new Vect3D(0, 0, 0));
                pm.addOsc3DTuned("o", 1, 440, 0.5, new Vect3D(1, 0.1, 0), new Vect3D());
                pm.addMass3D("m", 1, new Vect3D(2, 0, 0), new Vect3D());
                pm.addSpringDamper3D("s", 1, 0.05, 0.001, "o", "m");
                pm.createLinkSubset("all");
                pm.addLinkToSubset("s", "all");
                pm.init();
                pm.changeStiffnessParamOfSubset(0.04, "all");
                assertEquals(0.04, pm.getLinkStiffness("s"));
            }
            assertEquals(plain.getOscFrequency("o"), rt.getOscFrequency("o"));
            plain.computeNSteps(1000);
            rt.computeNSteps(1000);
            assertEquals(plain.getMatPosition("m").y, rt.getMatPosition("m").y);
            assertEquals(plain.getMatPosition("o").y, rt.getMatPosition("o").y);
            rt.endRealtimeStepping();
            assertTrue(!rt.isRealtimeStepping());
        });
    }
}
