package tactus.internal.read;

import java.util.ArrayList;
import java.util.List;
import processing.core.PVector;
import tactus.engine.Engine;
import tactus.engine.LinkKind;
import tactus.Vect3D;
import tactus.internal.edit.ParamEditor;
import tactus.internal.model.ModuleTypes;
import tactus.internal.model.PaperLeniency;
import tactus.internal.model.Registry;
import tactus.internal.model.UnitScale;
import tactus.matModuleType;
import tactus.internal.edit.SubsetBook;
import tactus.internal.model.ModelBase;
import tactus.internal.stability.StabilityGuard;

/**
 * The index-based queries and name-pattern edits of the paper's engine, for sketches written against it: link
 * ends, delayed positions, oscillator displacement, plane parameters, arrays of positions per module type, and
 * parameter changes by name pattern or along x. The caller holds the model's lock.
 */
public final class PaperQueries {
    private final ModelBase c;
    private final ParamEditor params;
    private final SubsetBook subsets;
    private final StabilityGuard guard;
    private final Engine engine;
    /** Scratch vectors, one for the realtime owner and one for lock holders. */
    private final RoleScratch scratch;

    public PaperQueries(ModelBase core, ParamEditor params, SubsetBook subsets, StabilityGuard guard) {
        this.params = params;
        this.subsets = subsets;
        this.guard = guard;
        this.c = core;
        this.engine = core.engine;
        this.scratch = new RoleScratch(core);
    }

    /** @return true when the link's second end is the plane, not a mass. */
    private boolean isPlane(int linkId) {
        return engine.linkKind(linkId) == LinkKind.PLANE_CONTACT3D;
    }

    /**
     * Writes the position of one end of a link into {@code out}. The second end of a plane contact is the foot of
     * the mass on the plane.
     */
    public Vect3D linkEnd(int linkId, boolean first, Vect3D out) {
        double[] tmp = scratch.get();
        engine.position(engine.linkMassA(linkId), tmp);
        if (!first) {
            if (isPlane(linkId)) {
                tmp[engine.linkAxis(linkId)] = engine.planePosition(linkId);
            } else {
                engine.position(engine.linkMassB(linkId), tmp);
            }
        }
        return out.set(tmp[0], tmp[1], tmp[2]);
    }

    /** @return the mass index of one end of a link, or -1 for the plane end of a plane contact. */
    public int linkEndIndex(int linkId, boolean first) {
        if (!first && isPlane(linkId)) {
            return -1;
        }
        return c.dir.mats.indexOf(first ? engine.linkMassA(linkId) : engine.linkMassB(linkId));
    }

    /** @return the mass name of one end of a link, or "" for the plane end of a plane contact. */
    public String linkEndName(int linkId, boolean first) {
        if (!first && isPlane(linkId)) {
            return "";
        }
        return c.dir.massName(first ? engine.linkMassA(linkId) : engine.linkMassB(linkId));
    }

    /** Writes the position a mass had one step before into {@code out}. */
    public Vect3D delayedPosition(int massId, Vect3D out) {
        double[] tmp = scratch.get();
        engine.position(massId, tmp);
        double x = tmp[0], y = tmp[1], z = tmp[2];
        engine.displacement(massId, tmp);
        return out.set(x - tmp[0], y - tmp[1], z - tmp[2]);
    }

    /** @return the distance of an oscillator from its rest point, in length units. */
    public double oscDisplacement(String op, int massId) {
        params.requireOsc(op, massId);
        double[] tmp = scratch.get();
        engine.position(massId, tmp);
        double dx = tmp[0] - engine.restPosition(massId, 0);
        double dy = tmp[1] - engine.restPosition(massId, 1);
        double dz = tmp[2] - engine.restPosition(massId, 2);
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }

    /**
     * Fills {@code pos} (and {@code vel} unless null) with the positions (and per-step displacements, X - X⁻) of
     * every mass of one type, in index order; {@code clear} empties the lists first, otherwise their first
     * entries are overwritten.
     */
    public void massesOfType(String op, List<PVector> pos, List<PVector> vel, matModuleType type, boolean clear) {
        if (pos == null || (vel == null && !op.equals("getAllMatsOfType")) || type == null) {
            throw new IllegalArgumentException(op + ": the lists and the type must not be null");
        }
        int n = c.dir.mats.size();
        if (!clear) {
            int matches = 0;
            for (int i = 0; i < n; i++) {
                if (ModuleTypes.of(engine.massKind(c.dir.mats.idAt(i))) == type) {
                    matches++;
                }
            }
            if (pos.size() < matches || (vel != null && vel.size() < matches)) {
                throw new IllegalArgumentException(op + "(" + type + "): the lists hold " + pos.size()
                        + (vel != null ? " and " + vel.size() : "") + " entries for " + matches
                        + " masses; create them with createPosSpeedArraysForModType first");
            }
        } else {
            pos.clear();
            if (vel != null) {
                vel.clear();
            }
        }
        int k = 0;
        double[] tmp = scratch.get();
        for (int i = 0; i < n; i++) {
            int id = c.dir.mats.idAt(i);
            if (ModuleTypes.of(engine.massKind(id)) != type) {
                continue;
            }
            engine.position(id, tmp);
            PVector p = new PVector((float) tmp[0], (float) tmp[1], (float) tmp[2]);
            PVector d = null;
            if (vel != null) {
                engine.displacement(id, tmp);
                d = new PVector((float) tmp[0], (float) tmp[1], (float) tmp[2]);
            }
            if (clear) {
                pos.add(p);
                if (vel != null) {
                    vel.add(d);
                }
            } else {
                pos.set(k, p);
                if (vel != null) {
                    vel.set(k, d);
                }
            }
            k++;
        }
    }

    /** @return the ids of the live modules whose name contains {@code tag}, in index order. */
    private static List<Integer> matching(Registry r, String tag) {
        List<Integer> ids = new ArrayList<>();
        for (int i = 0; i < r.size(); i++) {
            int id = r.idAt(i);
            if (r.name(id).contains(tag)) {
                ids.add(id);
            }
        }
        return ids;
    }

    /** Sets the inertia of every mass whose name contains {@code tag}; checked first, analysed once. */
    public void setMassForName(String op, String tag, double mass) {
        subsets.changeParamOf(op, true, subsets.lenientMembers(op, true, matching(c.dir.mats, tag), "mass"), "mass",
                mass);
    }

    /**
     * Sets K, Z and the length of every interaction whose name contains {@code tag}, each where the kind has it (a
     * spring takes no damping, a damper no stiffness or length); checked first, analysed once.
     */
    public void setLinkParamsForName(String op, String tag, double K, double Z, double dist) {
        List<Integer> ids = matching(c.dir.links, tag);
        for (int id : ids) {
            LinkKind k = engine.linkKind(id);
            if (k.hasLength()) {
                ParamEditor.checkLength(op, c.dir.linkName(id), k, dist);
            }
        }
        List<Runnable> undo = new ArrayList<>();
        UnitScale u = c.units();
        guard.defer();
        try {
            for (int id : ids) {
                LinkKind kind = engine.linkKind(id);
                undo.add(subsets.snapshot(false, id));
                c.writes().setLinkParams(id, kind.hasStiffness() ? u.stiffnessIn(K) : Double.NaN,
                        kind.hasDamping() ? u.dampingIn(Z) : Double.NaN, kind.hasLength() ? dist : Double.NaN);
            }
        } finally {
            guard.resume();
        }
        guard.afterChange(() -> undo.forEach(Runnable::run));
    }

    /**
     * Lines the masses of a mass subset up along x, {@code d} apart and centred on {@code center} (y and z taken
     * from it), at rest, in subset order.
     */
    public void spaceAlongX(String op, Vect3D center, double d, String subset) {
        if (subset != null && !subsets.isMatSubset(subset)) {
            c.lenient.forgive(PaperLeniency.Kind.NO_SUCH_SUBSET, op, subset, "no such mass subset",
                    "nothing was moved");
            return;
        }
        int[] ids = subsets.memberIds(subsets.requireMatSubset(op, subset));
        int n = ids.length;
        for (int k = 0; k < n; k++) {
            c.writes().setPosition(ids[k], center.x + d * (k - (n - 1) / 2.0), center.y, center.z);
        }
    }
}
