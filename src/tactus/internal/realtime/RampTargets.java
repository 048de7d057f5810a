package tactus.internal.realtime;

import tactus.Vect3D;
import tactus.internal.model.EngineWrites;
import tactus.internal.model.PaperLeniency;
import tactus.internal.model.UnitScale;
import tactus.internal.ModelCore;
import tactus.internal.model.RealtimeMode;

/**
 * The members of a subset that a {@link ParamController} ramps, resolved once (on the thread that triggers the ramp,
 * under the model's lock) so that the thread stepping a realtime model applies each ramp step with plain engine
 * writes: no look-up, no allocation, one liveness check per member. Members added to the subset during a ramp join
 * at the next trigger; a member removed during a ramp is dropped from it at the next ramp step (and counted, {@link
 * Ownership#droppedRampMembers}), and the ramp goes on with the others and ends as planned.
 */
public final class RampTargets {
    private static final int MASS = 0, STIFFNESS = 1, DAMPING = 2, DIST = 3, DIST_X = 4;
    /** The live members in {@code ids[0..n)}; a removed one is taken out in place. Touched by the stepping thread. */
    private final int[] ids;
    private int n;
    private final boolean mats;
    private final int param;
    private final double cx, cy, cz;

    private RampTargets(int[] ids, boolean mats, int param, Vect3D center) {
        this.ids = ids;
        this.n = ids.length;
        this.mats = mats;
        this.param = param;
        this.cx = center == null ? 0 : center.x;
        this.cy = center == null ? 0 : center.y;
        this.cz = center == null ? 0 : center.z;
    }

    /**
     * Resolves a controller's subset and checks that the ramp's target suits every member (the values in between lie
     * between two checked values). The caller holds the model's lock.
     */
    public static RampTargets resolve(ModelCore c, String subset, String param, float from, float target, Vect3D center) {
        String op = "triggerRamp";
        boolean mats = c.subsets.isMatSubset(subset);
        int p = "mass".equals(param) ? MASS : "stiffness".equals(param) ? STIFFNESS : "damping".equals(param)
                ? DAMPING : "dist".equals(param) ? DIST : DIST_X;
        int[] ids;
        if (subset != null && !mats && !c.subsets.isLinkSubset(subset) && p != MASS && p != DIST) {
            // a subset never created: the paper's engine changed nothing (it threw for mass and dist)
            c.lenient.forgive(PaperLeniency.Kind.NO_SUCH_SUBSET, op, subset, "no such subset", "nothing was changed");
            ids = new int[0];
        } else if (p == DIST_X) {
            ids = c.subsets.memberIds(c.subsets.requireMatSubset(op, subset));
        } else {
            java.util.Collection<Integer> m = c.subsets.lenientMembers(op, mats, c.subsets.members(op, subset),
                    param);
            ids = m.stream().mapToInt(Integer::intValue).toArray();
            if (p != DIST_X && ids.length > 0) {
                // the same check as a direct change, on both ends of the ramp
                c.subsets.checkAll(op, mats, ids, param, from);
                c.subsets.checkAll(op, mats, ids, param, target);
            }
        }
        return new RampTargets(ids, mats, p, center);
    }

    /**
     * Applies one ramp value (in the model's units) to every live member; a member removed since the last step is
     * dropped and counted. Runs on the stepping thread.
     */
    public void apply(ModelCore c, double v) {
        dropRemoved(c);
        EngineWrites w = c.direct;
        UnitScale u = c.units();
        int n = this.n;
        for (int k = 0; k < n; k++) {
            int id = ids[k];
            switch (param) {
                case MASS:
                    w.setMass(id, v);
                    break;
                case STIFFNESS:
                    if (mats) {
                        w.setOscillator(id, u.stiffnessIn(v), Double.NaN);
                    } else {
                        w.setLinkParams(id, u.stiffnessIn(v), Double.NaN, Double.NaN);
                    }
                    break;
                case DAMPING:
                    if (mats) {
                        w.setOscillator(id, Double.NaN, u.dampingIn(v));
                    } else {
                        w.setLinkParams(id, Double.NaN, u.dampingIn(v), Double.NaN);
                    }
                    break;
                case DIST:
                    w.setLinkParams(id, Double.NaN, Double.NaN, v);
                    break;
                default:
                    w.setPosition(id, cx + v * (k - (n - 1) / 2.0), cy, cz);
                    break;
            }
        }
    }

    /** Takes the members that are no longer in the model out of the ramp, in place, counting each once. */
    private void dropRemoved(ModelCore c) {
        tactus.engine.Engine e = c.engine;
        boolean links = !mats; // the ids are those of the subset: masses or links
        int kept = 0;
        for (int k = 0; k < n; k++) {
            int id = ids[k];
            if (links ? e.isLink(id) : e.isMass(id)) {
                ids[kept++] = id;
            }
        }
        if (kept < n) {
            RealtimeMode o = c.own;
            if (o != null) {
                o.countDroppedRampMembers(n - kept);
            }
            n = kept;
        }
    }

    /** @return the number of members still ramped. */
    public int size() {
        return n;
    }
}
