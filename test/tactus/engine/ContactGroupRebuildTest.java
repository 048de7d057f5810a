package tactus.engine;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/**
 * The rebuild rate of a contact group's neighbour list. The list holds the pairs closer than threshold + skin
 * (skin = {@link ContactGroupSpec#SKIN} x threshold) and must be rebuilt exactly when some member has moved more
 * than skin / 2 since the last build: no sooner (the broad phase would cost a grid pass per step) and no later (a
 * pair could come within the threshold unseen). With every member drifting at v per step the rebuild period is
 * therefore P = floor(skin / (2v)) + 1 steps, and a model at rest builds its list once.
 */
class ContactGroupRebuildTest {

    /** A row of n free masses 1 apart (no pair within reach), all drifting along x at v per step. */
    private static Engine drifting(int n, double threshold, double v) {
        Engine e = new Engine();
        int[] ids = new int[n];
        for (int i = 0; i < n; i++) {
            ids[i] = e.addMass(MassKind.MASS3D, 1, i, 0.5 * (i % 3), 0, v, 0, 0);
        }
        e.addContactGroup(ids, threshold, 0.01, 0.001);
        return e;
    }

    private static long rebuilds(Engine e) {
        long r = 0;
        for (ContactGroupKernel g : e.plan().groups) {
            r += g.rebuilds();
        }
        return r;
    }

    @Test
    void driftingMembersRebuildOncePerHalfSkinTravelled() {
        double threshold = 0.1;
        double skin = ContactGroupSpec.SKIN * threshold;
        for (double v : new double[] {7e-4, 1.1e-3, 2.3e-4}) {
            double ratio = skin / (2 * v);
            int period = (int) Math.floor(ratio) + 1;
            Engine e = drifting(20, threshold, v);
            int steps = 2000;
            e.step(steps);
            // built at the first step, then once per period: at steps 1, 1 + P, 1 + 2P, ...
            long expected = 1 + (steps - 1) / period;
            assertEquals(expected, rebuilds(e), "v = " + v + " per step, skin/2v = " + ratio);
        }
    }

    @Test
    void aGroupAtRestBuildsItsListOnce() {
        Engine e = drifting(30, 0.2, 0.0);
        e.step(5000);
        assertEquals(1, rebuilds(e));
    }

    @Test
    void jitterBelowHalfTheSkinNeverRebuilds() {
        double threshold = 0.1;
        double skin = ContactGroupSpec.SKIN * threshold;
        Engine e = drifting(10, threshold, 0.0);
        e.step(1);
        double[] p = new double[3];
        for (int s = 0; s < 400; s++) {
            for (int id = 0; id < 10; id++) {
                e.position(id, p);
                // each member is put back within 0.45 skin of where it started (x = id), in a random-looking pattern
                double off = 0.45 * skin * Math.sin(0.37 * s + id);
                e.setPosition(id, id + off, p[1], p[2]);
            }
            e.step(1);
        }
        assertEquals(1, rebuilds(e), "no member left the skin/2 ball around its position at the build");
        // one more member pushed just beyond skin/2 forces exactly one rebuild
        e.position(3, p);
        e.setPosition(3, 3 + 0.51 * skin, p[1], p[2]);
        e.step(1);
        assertEquals(2, rebuilds(e));
    }
}
