package tactus.engine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * A contact group must behave exactly like the equivalent explicit Contact3D links (forces and potential
 * energy, also right after a mass was moved by hand), must survive members spread over any distance, and must
 * rebuild its neighbour list only when a member has moved more than half the skin.
 */
class ContactGroupKernelTest {
    private static final double K = 0.02;
    private static final double Z = 0.001;

    /** Two engines with the same masses: one with a contact group, one with a Contact3D for every pair i &lt; j. */
    private static Engine[] twins(double[][] pos, double threshold) {
        Engine group = new Engine();
        Engine explicit = new Engine();
        int n = pos.length;
        int[] ids = new int[n];
        for (int i = 0; i < n; i++) {
            ids[i] = group.addMass(MassKind.MASS3D, 1 + 0.25 * (i % 3), pos[i][0], pos[i][1], pos[i][2], 0, 0, 0);
            explicit.addMass(MassKind.MASS3D, 1 + 0.25 * (i % 3), pos[i][0], pos[i][1], pos[i][2], 0, 0, 0);
        }
        group.addContactGroup(ids, threshold, K, Z);
        for (int i = 0; i < n; i++) {
            for (int j = i + 1; j < n; j++) {
                explicit.addLink(LinkKind.CONTACT3D, ids[i], ids[j], K, Z, threshold);
            }
        }
        return new Engine[] {group, explicit};
    }

    private static void assertSameState(Engine a, Engine b, int n, String what) {
        double[] p = new double[3];
        double[] q = new double[3];
        for (int id = 0; id < n; id++) {
            a.position(id, p);
            b.position(id, q);
            for (int c = 0; c < 3; c++) {
                assertEquals(q[c], p[c], 0.0, what + ": mass " + id + " axis " + c);
            }
        }
    }

    // Was: the dense grid's cell count nx * ny * nz overflowed a long when one member was ~27 km away with a
    // 0.01 threshold, and the grid was indexed out of bounds (ArrayIndexOutOfBoundsException).
    @Test
    void aFarAwayMemberFallsBackToTheHashedGrid() {
        for (double far : new double[] {2.7e4, 3e4, 1e9, 1e300}) {
            double[][] pos = {{0, 0, 0}, {0.005, 0, 0}, {0.003, 0.004, 0}, {0.001, 0.002, 0.003}, {far, far, far}};
            Engine[] e = twins(pos, 0.01);
            for (int b = 0; b < 20; b++) {
                e[0].step(5);
                e[1].step(5);
                assertSameState(e[0], e[1], pos.length, "member at " + far + ", batch " + b);
            }
            assertEquals(EnergyMeter.potential(e[1].plan()), EnergyMeter.potential(e[0].plan()), 0.0);
        }
    }

    // Was: the group's energy used the neighbour list of the last step: after setPosition (and before a step) a
    // pair moved into contact was missing and the energy differed from the explicit contacts; energy() could also
    // run into the grid overflow above.
    @Test
    void potentialEnergyEqualsExplicitContactsAfterSetPosition() {
        SplittableRandom rnd = new SplittableRandom(7);
        int n = 40;
        double[][] pos = new double[n][3];
        for (double[] p : pos) {
            for (int c = 0; c < 3; c++) {
                p[c] = 3 * rnd.nextDouble();
            }
        }
        Engine[] e = twins(pos, 0.6);
        for (int round = 0; round < 50; round++) {
            for (int m = 0; m < 3; m++) {
                int id = rnd.nextInt(n);
                double x = 3 * rnd.nextDouble(), y = 3 * rnd.nextDouble(), z = 3 * rnd.nextDouble();
                e[0].setPosition(id, x, y, z);
                e[1].setPosition(id, x, y, z);
            }
            double explicit = EnergyMeter.potential(e[1].plan());
            assertEquals(explicit, EnergyMeter.potential(e[0].plan()), 0.0, "after setPosition, round " + round);
            if (round == 0) {
                assertEquals(true, explicit > 0, "some pairs are engaged");
            }
            e[0].step(3);
            e[1].step(3);
            assertEquals(EnergyMeter.potential(e[1].plan()), EnergyMeter.potential(e[0].plan()), 0.0,
                    "after stepping, round " + round);
            assertSameState(e[0], e[1], n, "round " + round);
        }
    }

    /**
     * Groups of 2 to 200 members, moving fast enough to rebuild their list at most steps, through every search of
     * the neighbour list (every pair up to {@link NeighbourList#ALL_PAIRS_MAX} members, then the grids): positions
     * equal to those under explicit contacts in member order, bit for bit, at every step.
     */
    @Test
    @Timeout(120)
    void movingGroupsOfEverySizeMatchExplicitContactsStepByStep() {
        SplittableRandom rnd = new SplittableRandom(4242);
        double threshold = 0.2;
        for (int n : new int[] {2, 5, 16, 64, 65, 120, 200}) {
            double side = threshold * Math.cbrt(n);
            double[][] pos = new double[n][3];
            for (double[] p : pos) {
                for (int c = 0; c < 3; c++) {
                    p[c] = side * rnd.nextDouble();
                }
            }
            Engine[] e = twins(pos, threshold);
            for (int id = 0; id < n; id++) {
                // 0.02 to 0.06 per step towards the middle, against a half skin of 0.03: the list is rebuilt often
                double[] v = new double[3];
                for (int c = 0; c < 3; c++) {
                    v[c] = (0.5 * side - pos[id][c]) * 0.04 / side + 0.02 * (rnd.nextDouble() - 0.5);
                }
                for (Engine x : e) {
                    x.setState(id, pos[id][0], pos[id][1], pos[id][2], pos[id][0] - v[0], pos[id][1] - v[1],
                            pos[id][2] - v[2]);
                }
            }
            double engaged = 0;
            for (int step = 0; step < 150; step++) {
                e[0].step();
                e[1].step();
                assertSameState(e[0], e[1], n, n + " members, step " + step);
                engaged = Math.max(engaged, EnergyMeter.potential(e[1].plan()));
            }
            long rebuilds = e[0].contactGroupRebuilds();
            assertTrue(rebuilds > 20, n + " members: the list was rebuilt " + rebuilds + " times in 150 steps");
            assertTrue(engaged > 0, n + " members: some pairs came into contact");
        }
    }

    @Test
    void theNeighbourListIsRebuiltOnlyWhenAMemberMovedMoreThanHalfTheSkin() {
        double threshold = 1.0;
        double halfSkin = 0.5 * ContactGroupSpec.SKIN * threshold;
        Engine e = new Engine();
        int n = 5;
        int[] ids = new int[n];
        for (int i = 0; i < n; i++) {
            // 3 apart: beyond threshold + skin, so nothing moves by itself
            ids[i] = e.addMass(MassKind.MASS3D, 1, 3 * i, 0, 0, 0, 0, 0);
        }
        e.addContactGroup(ids, threshold, K, Z);
        e.step(10);
        assertEquals(1, e.contactGroupRebuilds(), "the first step builds the list");
        e.setPosition(ids[2], 6 + 0.9 * halfSkin, 0, 0);
        e.step(10);
        assertEquals(1, e.contactGroupRebuilds(), "a move within half the skin keeps the list");
        e.setPosition(ids[4], 12, 0.6 * halfSkin, 0.6 * halfSkin);
        e.step(10);
        assertEquals(1, e.contactGroupRebuilds(), "0.85 of half the skin (diagonal) keeps the list");
        e.setPosition(ids[2], 6 + 1.1 * halfSkin, 0, 0);
        e.step(1);
        assertEquals(2, e.contactGroupRebuilds(), "a move beyond half the skin rebuilds it");
        e.step(10);
        assertEquals(2, e.contactGroupRebuilds(), "and the new list holds while nothing moves");
        // a member driven across by its velocity
        e.setState(ids[0], 0, 0, 0, -0.01 * halfSkin, 0, 0);
        e.step(99);
        assertEquals(2, e.contactGroupRebuilds(), "0.99 of half the skin after 99 steps");
        e.step(2);
        assertEquals(3, e.contactGroupRebuilds(), "1.01 of half the skin after 101 steps");
    }
}
