package tactus.engine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.HashSet;
import java.util.Set;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * The neighbour list against brute force: for random groups of 2 to 2,000 members (compact, strung out, in far-apart
 * clumps, with a far-away, an infinite and a NaN member), moved at random between rebuilds, every rebuild must list
 * exactly the pairs closer than the reach, in lexicographic member order (the order in which the contact group sums
 * its forces), whichever search it used (every pair, the dense grid or the hashed grid); between rebuilds every pair
 * closer than the threshold must still be listed.
 */
@Timeout(120)
class NeighbourListTest {
    private static final double THRESHOLD = 0.1;
    private static final double SKIN = ContactGroupSpec.SKIN * THRESHOLD;
    private static final double REACH = THRESHOLD + SKIN;

    /** The layouts of the members, and the volume a relocated member may jump to. */
    private enum Layout { CUBE, LINE, CLUMPS, OUTLIERS }

    /** Random positions of n members in a layout. */
    private static double[][] positions(Layout layout, int n, SplittableRandom rnd) {
        double[][] pos = new double[n][3];
        double side = REACH * Math.cbrt(n);
        for (int i = 0; i < n; i++) {
            double[] q = pos[i];
            switch (layout) {
                case LINE:
                    q[0] = 0.4 * REACH * i;
                    q[1] = 0.5 * REACH * rnd.nextDouble();
                    q[2] = 0.5 * REACH * rnd.nextDouble();
                    break;
                case CLUMPS:
                    // clumps of 6 members within one reach, the clumps 40 reaches apart on a sparse lattice
                    int clump = i / 6;
                    q[0] = 40 * REACH * (clump % 7) + REACH * rnd.nextDouble();
                    q[1] = 40 * REACH * ((clump / 7) % 7) + REACH * rnd.nextDouble();
                    q[2] = 40 * REACH * (clump / 49) + REACH * rnd.nextDouble();
                    break;
                default:
                    for (int c = 0; c < 3; c++) {
                        q[c] = side * rnd.nextDouble();
                    }
            }
        }
        if (layout == Layout.OUTLIERS && n >= 4) {
            pos[n / 3] = new double[] {1e7, -3e6, 2.5};
            pos[n / 2] = new double[] {Double.POSITIVE_INFINITY, 0, 0};
            pos[n - 1] = new double[] {0.01, Double.NaN, 0};
        }
        return pos;
    }

    /** The masses of a group in an engine, in a shuffled member order; returns the members' slots in its plan. */
    private static int[] members(Engine e, double[][] pos, SplittableRandom rnd) {
        int n = pos.length;
        int[] ids = new int[n];
        for (int i = 0; i < n; i++) {
            ids[i] = e.addMass(MassKind.MASS3D, 1, pos[i][0], pos[i][1], pos[i][2], 0, 0, 0);
        }
        for (int i = n - 1; i > 0; i--) {
            int j = rnd.nextInt(i + 1);
            int t = ids[i];
            ids[i] = ids[j];
            ids[j] = t;
        }
        e.addContactGroup(ids, THRESHOLD, 0, 0);
        return e.plan().groups[0].members().clone();
    }

    /** Asserts the list holds exactly the pairs (member m, member o), m &lt; o, closer than the reach, in that order. */
    private static void assertBruteForce(NeighbourList list, StepPlan p, int[] slot, String what) {
        int q = 0;
        for (int m = 0; m < slot.length; m++) {
            int s = slot[m];
            for (int o = m + 1; o < slot.length; o++) {
                int os = slot[o];
                double dx = p.x[s] - p.x[os], dy = p.y[s] - p.y[os], dz = p.z[s] - p.z[os];
                if (dx * dx + dy * dy + dz * dz < REACH * REACH) {
                    assertTrue(q < list.pairs, what + ": pair (" + m + ", " + o + ") missing, only " + list.pairs + " listed");
                    assertEquals(s, list.pairI[q], what + ": first slot of pair " + q);
                    assertEquals(os, list.pairJ[q], what + ": second slot of pair " + q);
                    q++;
                }
            }
        }
        assertEquals(q, list.pairs, what + ": pairs listed");
    }

    /** Asserts every pair closer than the threshold is listed (what a list must hold between rebuilds). */
    private static void assertComplete(NeighbourList list, StepPlan p, int[] slot, String what) {
        Set<Long> listed = new HashSet<>();
        for (int q = 0; q < list.pairs; q++) {
            listed.add(((long) list.pairI[q] << 32) | list.pairJ[q]);
        }
        for (int m = 0; m < slot.length; m++) {
            for (int o = m + 1; o < slot.length; o++) {
                int s = slot[m], os = slot[o];
                double dx = p.x[s] - p.x[os], dy = p.y[s] - p.y[os], dz = p.z[s] - p.z[os];
                if (dx * dx + dy * dy + dz * dz < THRESHOLD * THRESHOLD) {
                    assertTrue(listed.contains(((long) s << 32) | os), what + ": engaged pair (" + m + ", " + o + ") missing");
                }
            }
        }
    }

    /**
     * Moves every finite member by up to {@code step} on each axis, and relocates one in 40 to a random place in
     * the cube around the origin.
     */
    private static void move(StepPlan p, int[] slot, double step, double side, SplittableRandom rnd) {
        for (int s : slot) {
            if (!Double.isFinite(p.x[s]) || !Double.isFinite(p.y[s]) || Math.abs(p.x[s]) > 1e6) {
                continue;
            }
            if (rnd.nextInt(40) == 0) {
                p.x[s] = side * rnd.nextDouble();
                p.y[s] = side * rnd.nextDouble();
                p.z[s] = side * rnd.nextDouble();
            } else {
                p.x[s] += step * (2 * rnd.nextDouble() - 1);
                p.y[s] += step * (2 * rnd.nextDouble() - 1);
                p.z[s] += step * (2 * rnd.nextDouble() - 1);
            }
        }
    }

    @Test
    void everyRebuildListsExactlyThePairsWithinReachInMemberOrder() {
        int[] sizes = {2, 3, 7, 16, 31, 48, 63, 64, 65, 100, 200, 500, 2000};
        SplittableRandom rnd = new SplittableRandom(2027);
        Set<Integer> largeSearches = new HashSet<>();
        for (int n : sizes) {
            for (Layout layout : Layout.values()) {
                String what = n + " members, " + layout;
                Engine e = new Engine();
                int[] slot = members(e, positions(layout, n, rnd), rnd);
                StepPlan p = e.plan();
                NeighbourList list = new NeighbourList(p, slot, THRESHOLD, SKIN);
                int rounds = n >= 1000 ? 8 : 30;
                int rebuilt = 0;
                for (int r = 0; r < rounds; r++) {
                    // small moves (within half the skin: the list is kept) alternate with large ones (rebuilt)
                    boolean large = r % 3 != 1;
                    if (r > 0) {
                        move(p, slot, large ? 0.4 * REACH : 0.2 * SKIN / Math.sqrt(3), REACH * Math.cbrt(n), rnd);
                    }
                    boolean rebuild = list.refresh();
                    if (rebuild) {
                        rebuilt++;
                        assertBruteForce(list, p, slot, what + ", round " + r);
                        if (n <= NeighbourList.ALL_PAIRS_MAX) {
                            assertEquals(NeighbourList.ALL_PAIRS, list.lastSearch, what + ": search");
                        } else {
                            largeSearches.add(list.lastSearch);
                        }
                    } else {
                        assertComplete(list, p, slot, what + ", round " + r + " (kept)");
                    }
                }
                assertTrue(rebuilt >= rounds / 2, what + ": rebuilt " + rebuilt + " times in " + rounds + " rounds");
            }
        }
        assertEquals(Set.of(NeighbourList.DENSE, NeighbourList.HASHED), largeSearches,
                "the groups larger than " + NeighbourList.ALL_PAIRS_MAX + " exercised both grids");
    }

    @Test
    void aGroupSearchedPairByPairNeverGrowsItsListWhenRebuilt() {
        int n = NeighbourList.ALL_PAIRS_MAX;
        double[][] pos = new double[n][3];
        SplittableRandom rnd = new SplittableRandom(11);
        for (double[] q : pos) {
            for (int c = 0; c < 3; c++) {
                q[c] = 0.5 * THRESHOLD * rnd.nextDouble(); // every pair within the threshold
            }
        }
        Engine e = new Engine();
        int[] slot = members(e, pos, rnd);
        NeighbourList list = new NeighbourList(e.plan(), slot, THRESHOLD, SKIN);
        int[] pi = list.pairI;
        int[] pj = list.pairJ;
        list.rebuild();
        assertEquals(n * (n - 1) / 2, list.pairs, "every pair listed");
        assertTrue(pi == list.pairI && pj == list.pairJ, "the arrays made by the constructor hold every pair");
        assertBruteForce(list, e.plan(), slot, "a dense group of " + n);
    }

    @Test
    void aRebuildCostsInProportionToTheMembersNotToTheVolumeTheySpan() {
        // 16 members strung out over 4,000 reaches: the old dense grid spanned up to 4,096 cells for them
        Engine e = new Engine();
        double[][] pos = new double[16][3];
        for (int i = 0; i < 16; i++) {
            pos[i] = new double[] {250 * REACH * i, 0, 0};
        }
        int[] slot = members(e, pos, new SplittableRandom(5));
        NeighbourList list = new NeighbourList(e.plan(), slot, THRESHOLD, SKIN);
        list.rebuild();
        assertEquals(NeighbourList.ALL_PAIRS, list.lastSearch);
        // 100 members in a line 5,000 reaches long: more cells than max(4,096, 32 n) -> hashed
        Engine f = new Engine();
        double[][] line = new double[100][3];
        for (int i = 0; i < 100; i++) {
            line[i] = new double[] {50 * REACH * i + 0.5 * REACH, 0.5 * REACH, 0.5 * REACH};
        }
        int[] lineSlots = members(f, line, new SplittableRandom(6));
        NeighbourList sparse = new NeighbourList(f.plan(), lineSlots, THRESHOLD, SKIN);
        sparse.rebuild();
        assertEquals(NeighbourList.HASHED, sparse.lastSearch);
        assertBruteForce(sparse, f.plan(), sparse.members(), "sparse line");
    }
}
