package tactus;

/**
 * The members of a subset that a {@link ParamController} ramps, resolved once (on the thread that triggers the ramp,
 * under the model's lock) so that the thread stepping a realtime model applies each ramp step with plain engine
 * writes: no look-up, no check, no allocation. Members added to or removed from the subset during a ramp are taken
 * into account at the next trigger.
 */
final class RampTargets {
    private static final int MASS = 0, STIFFNESS = 1, DAMPING = 2, DIST = 3, DIST_X = 4;
    private final int[] ids;
    private final boolean mats;
    private final int param;
    private final double cx, cy, cz;

    private RampTargets(int[] ids, boolean mats, int param, Vect3D center) {
        this.ids = ids;
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
    static RampTargets resolve(ModelCore c, String subset, String param, float from, float target, Vect3D center) {
        String op = "triggerRamp";
        boolean mats = c.subsets.isMatSubset(subset);
        int p = "mass".equals(param) ? MASS : "stiffness".equals(param) ? STIFFNESS : "damping".equals(param)
                ? DAMPING : "dist".equals(param) ? DIST : DIST_X;
        int[] ids;
        if (p == DIST_X) {
            ids = c.subsets.memberIds(c.subsets.requireMatSubset(op, subset));
        } else {
            java.util.Set<Integer> m = c.subsets.members(op, subset);
            ids = m.stream().mapToInt(Integer::intValue).toArray();
            if (p != DIST_X && ids.length > 0) {
                // the same check as a direct change, on both ends of the ramp
                c.subsets.checkAll(op, mats, ids, param, from);
                c.subsets.checkAll(op, mats, ids, param, target);
            }
        }
        return new RampTargets(ids, mats, p, center);
    }

    /** Applies one ramp value (in the model's units) to every member. Runs on the stepping thread. */
    void apply(ModelCore c, double v) {
        EngineWrites w = c.direct;
        UnitScale u = c.units();
        int n = ids.length;
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
}
