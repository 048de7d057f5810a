package tactus.engine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * The broad phase of explicit Contact3D links ({@link ContactIndex}) must change nothing but the time a step takes:
 * the same model stepped with it and with every contact tested gives the same positions and the same damper
 * history, bit for bit, whatever the contacts' order, orientation, thresholds and duplicates, through hand moves,
 * parameter changes, a change of step duration, topology changes, non-finite positions and two threads.
 */
@Timeout(120)
class ContactIndexTest {
    private static final int MARBLES = 60;

    /** A pile of marbles with a contact for every pair, in shuffled order and orientation, some pairs twice. */
    private static Engine marbles(long seed, int threads) {
        SplittableRandom rnd = new SplittableRandom(seed);
        Engine e = new Engine();
        e.setGravity(0, 0, -1e-4);
        e.setFriction(1e-4);
        int[] ids = new int[MARBLES];
        for (int i = 0; i < MARBLES; i++) {
            ids[i] = e.addMass(MassKind.MASS3D, 1 + rnd.nextDouble(), 0.5 + rnd.nextDouble(), 0.5 + rnd.nextDouble(),
                    0.5 + rnd.nextDouble(), 0.004 * (rnd.nextDouble() - 0.5), 0.004 * (rnd.nextDouble() - 0.5), 0);
        }
        // a bowl: every marble inside a sphere of radius 0.9 around (1, 1, 1), so they pile up at its bottom
        int centre = e.addMass(MassKind.GROUND3D, 1, 1, 1, 1, 0, 0, 0);
        for (int i = 0; i < MARBLES; i++) {
            e.addLink(LinkKind.BUBBLE3D, centre, ids[i], 0.05, 0.01, 0.9);
        }
        List<int[]> pairs = new ArrayList<>();
        for (int i = 0; i < MARBLES; i++) {
            for (int j = i + 1; j < MARBLES; j++) {
                pairs.add(rnd.nextBoolean() ? new int[] {ids[i], ids[j]} : new int[] {ids[j], ids[i]});
                if (rnd.nextInt(40) == 0) {
                    pairs.add(new int[] {ids[j], ids[i]}); // a second contact on the same pair
                }
            }
        }
        Collections.shuffle(pairs, new java.util.Random(seed));
        for (int[] q : pairs) {
            e.addLink(LinkKind.CONTACT3D, q[0], q[1], 0.01 + 0.02 * rnd.nextDouble(), 0.002 * rnd.nextDouble(),
                    0.15 + 0.2 * rnd.nextDouble());
        }
        e.setThreads(threads);
        e.compile();
        return e;
    }

    /** The same model with the broad phase taken away: every contact tested every step. */
    private static void testEveryContact(Engine e) {
        e.compile();
        e.plan().batch(LinkKind.CONTACT3D).contactIndex = null;
    }

    /** The pile stepped both ways: {with the index, every contact tested}, one thread. */
    private static Engine[] twins(long seed) {
        Engine ref = marbles(seed, 1);
        testEveryContact(ref);
        return new Engine[] {marbles(seed, 1), ref};
    }

    /** Calls {@code action} with the id of every Contact3D among ids 0, stride, 2 stride, ... */
    private static void everyContact(Engine e, int stride, java.util.function.IntConsumer action) {
        for (int id = 0; id < e.linkIdCount(); id += stride) {
            if (e.isLink(id) && e.linkKind(id) == LinkKind.CONTACT3D) {
                action.accept(id);
            }
        }
    }

    private static ContactIndex indexOf(Engine e) {
        e.compile();
        return e.plan().batch(LinkKind.CONTACT3D).contactIndex;
    }

    private static void assertSame(Engine fast, Engine ref, String what) {
        double[] p = new double[3];
        double[] q = new double[3];
        for (int id = 0; id <= MARBLES + 1; id++) {
            if (fast.isMass(id)) {
                fast.position(id, p);
                ref.position(id, q);
                for (int c = 0; c < 3; c++) {
                    assertEquals(q[c], p[c], 0.0, what + ": mass " + id + " axis " + c);
                }
            }
        }
        LinkBatch bf = fast.plan().batch(LinkKind.CONTACT3D);
        LinkBatch br = ref.plan().batch(LinkKind.CONTACT3D);
        assertEquals(br.n, bf.n, what + ": contacts");
        for (int j = 0; j < bf.n; j++) {
            assertEquals(br.prev(j), bf.prev(j), 0.0, what + ": previous distance of contact " + j);
        }
    }

    /** Steps both in chunks, comparing after each, and returns how many contact-steps acted in all. */
    private static long stepBoth(Engine fast, Engine ref, int chunks, int steps, String what) {
        long engaged = 0;
        for (int c = 0; c < chunks; c++) {
            fast.step(steps);
            ref.step(steps);
            assertSame(fast, ref, what + ", chunk " + c);
            LinkBatch b = fast.plan().batch(LinkKind.CONTACT3D);
            for (int j = 0; j < b.n; j++) {
                engaged += b.prev(j) >= 0 ? 1 : 0;
            }
        }
        return engaged;
    }

    @Test
    void aPileSteppedWithTheIndexEqualsEveryContactTestedBitForBit() {
        for (long seed : new long[] {1, 2, 3}) {
            for (int threads : new int[] {1, 2}) {
                Engine fast = marbles(seed, threads);
                Engine ref = marbles(seed, threads);
                testEveryContact(ref);
                ContactIndex index = indexOf(fast);
                assertNotNull(index, "a pile of " + MARBLES + " marbles gets the broad phase");
                long engaged = stepBoth(fast, ref, 40, 50, "seed " + seed + ", " + threads + " thread(s)");
                assertTrue(engaged > 500, "the marbles touch (" + engaged + " contact-steps engaged)");
                assertTrue(index.rebuilds() > 1, "the candidates were rebuilt as the marbles moved: " + index.rebuilds());
                assertTrue(index.candidates < fast.plan().batch(LinkKind.CONTACT3D).n / 2,
                        "the index skips most contacts: " + index.candidates + " candidates");
                fast.close();
                ref.close();
            }
        }
    }

    @Test
    void handMovesParameterChangesAndANewStepDurationKeepBothEqual() {
        Engine[] both = twins(11);
        Engine fast = both[0];
        Engine ref = both[1];
        stepBoth(fast, ref, 5, 40, "before");
        for (Engine e : both) {
            e.setPosition(3, 1, 1, 0.2);                // into the pile, forgetting its links' history
            e.setPositionKeepingLinkHistory(7, 1.05, 1, 0.2);
        }
        stepBoth(fast, ref, 5, 40, "after the hand moves");
        for (Engine e : both) {
            // some thresholds larger than all others
            everyContact(e, 97, id -> e.setLinkParams(id, 0.05, 0.003, 0.9));
        }
        stepBoth(fast, ref, 5, 40, "after the parameter changes");
        for (Engine e : both) {
            e.rescaleTime(0.5);
        }
        stepBoth(fast, ref, 5, 40, "after the change of step duration");
        fast.close();
        ref.close();
    }

    @Test
    void topologyChangesCarryTheHistoryOverEqually() {
        Engine[] both = twins(21);
        Engine fast = both[0];
        Engine ref = both[1];
        stepBoth(fast, ref, 5, 40, "before");
        for (Engine e : both) {
            everyContact(e, 13, e::removeLink);
            int extra = e.addMass(MassKind.MASS3D, 1.5, 1, 1, 0.5, 0, 0, 0);
            for (int id = 0; id < MARBLES; id += 2) {
                e.addLink(LinkKind.CONTACT3D, extra, id, 0.02, 0.001, 0.3);
            }
        }
        testEveryContact(ref);
        assertNotNull(indexOf(fast), "the new plan gets a broad phase of its own");
        stepBoth(fast, ref, 10, 40, "after the topology change");
        fast.close();
        ref.close();
    }

    @Test
    void aNonFinitePositionFallsBackToTestingEveryContact() {
        Engine[] both = twins(31);
        Engine fast = both[0];
        Engine ref = both[1];
        fast.guard().setInterval(1 << 30); // no scan: the NaN stays in the state
        ref.guard().setInterval(1 << 30);
        stepBoth(fast, ref, 3, 40, "before");
        for (Engine e : both) {
            e.setPositionKeepingLinkHistory(5, Double.NaN, 1, 0.2);
        }
        ContactIndex index = indexOf(fast);
        assertNotNull(index);
        stepBoth(fast, ref, 3, 10, "with a NaN position");
        assertTrue(!index.refresh(), "a NaN position: every contact is tested");
        fast.close();
        ref.close();
    }

    @Test
    void sparseOrSmallBatchesGetNoIndex() {
        Engine chain = new Engine();
        int prev = chain.addMass(MassKind.MASS3D, 1, 0, 0, 0, 0, 0, 0);
        for (int i = 1; i < 3000; i++) {
            int m = chain.addMass(MassKind.MASS3D, 1, i, 0, 0, 0, 0, 0);
            chain.addLink(LinkKind.CONTACT3D, prev, m, 0.01, 0, 0.5);  // one contact per mass: too few per mass
            prev = m;
        }
        assertNull(indexOf(chain), "a chain of contacts (one per mass) is tested contact by contact");
        Engine few = new Engine();
        int[] ids = new int[20];
        for (int i = 0; i < ids.length; i++) {
            ids[i] = few.addMass(MassKind.MASS3D, 1, i, 0, 0, 0, 0, 0);
        }
        for (int i = 0; i < ids.length; i++) {
            for (int j = i + 1; j < ids.length; j++) {
                few.addLink(LinkKind.CONTACT3D, ids[i], ids[j], 0.01, 0, 0.5);
            }
        }
        assertNull(indexOf(few), "190 contacts: below the size where the index pays");
        chain.close();
        few.close();
    }
}
