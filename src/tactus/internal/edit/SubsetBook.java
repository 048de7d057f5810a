package tactus.internal.edit;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Set;
import tactus.engine.Engine;
import tactus.engine.LinkKind;
import tactus.engine.MassKind;
import tactus.Vect3D;
import tactus.internal.model.Check;
import tactus.internal.model.PaperLeniency;
import tactus.internal.model.UnitScale;
import tactus.internal.model.ModelBase;
import tactus.internal.stability.StabilityGuard;

/**
 * Named subsets of masses and of interactions, grouped parameter changes on them, and the contact groups
 * attached to mass subsets. Subsets hold stable module ids, so they survive removals; a contact group follows
 * its subset's membership. The caller holds the model's lock.
 */
public final class SubsetBook {
    private static final String[] PARAMS = {"mass", "stiffness", "damping", "dist"};
    private final ModelBase c;
    private final ParamEditor params;
    private final TopologyEditor topology;
    private final StabilityGuard guard;
    private final Engine engine;
    private final Subsets mats = new Subsets();
    private final Subsets links = new Subsets();
    /** Contact groups by mass-subset name, in creation order, with their engine group ids. */
    private final LinkedHashMap<String, Integer> groups = new LinkedHashMap<>();

    public SubsetBook(ModelBase core, ParamEditor params, TopologyEditor topology, StabilityGuard guard) {
        this.params = params;
        this.topology = topology;
        this.guard = guard;
        this.c = core;
        this.engine = core.engine;
    }

    // ---------------------------------------------------------------- membership

    public void createMatSubset(String subset) {
        if (mats.exists(subset) || links.exists(subset)) {
            throw Check.fail("createMatSubset", subset, "a subset with this name already exists");
        }
        mats.create(subset);
    }

    public void createLinkSubset(String subset) {
        if (mats.exists(subset) || links.exists(subset)) {
            throw Check.fail("createLinkSubset", subset, "a subset with this name already exists");
        }
        links.create(subset);
    }

    public boolean isMatSubset(String subset) {
        return subset != null && mats.exists(subset);
    }

    public boolean isLinkSubset(String subset) {
        return subset != null && links.exists(subset);
    }

    public void addMat(String op, int id, String subset) {
        mats.add(requireMatSubset(op, subset), id);
        syncGroup(subset);
    }

    public void removeMat(String op, int id, String subset) {
        mats.remove(requireMatSubset(op, subset), id);
        syncGroup(subset);
    }

    public void addLink(String op, int id, String subset) {
        links.add(requireLinkSubset(op, subset), id);
    }

    public void removeLink(String op, int id, String subset) {
        links.remove(requireLinkSubset(op, subset), id);
    }

    /** @return the ids of a mass or link subset's members, in the order they were added. */
    public Set<Integer> members(String op, String subset) {
        if (isMatSubset(subset)) {
            return mats.members(subset);
        }
        return links.members(requireLinkSubset(op, subset));
    }

    /** @return the names of a subset's members, in the order they were added. */
    public String[] memberNames(String op, String subset) {
        if (isMatSubset(subset)) {
            return mats.members(subset).stream().map(c.dir::massName).toArray(String[]::new);
        }
        return links.members(requireLinkSubset(op, subset)).stream().map(c.dir::linkName).toArray(String[]::new);
    }

    public String requireMatSubset(String op, String subset) {
        if (!isMatSubset(subset)) {
            throw Check.fail(op, String.valueOf(subset), "no such mass subset");
        }
        return subset;
    }

    public String requireLinkSubset(String op, String subset) {
        if (!isLinkSubset(subset)) {
            throw Check.fail(op, String.valueOf(subset), "no such subset");
        }
        return subset;
    }

    /** A mass left the model: drop it from every subset and contact group. */
    public void forgetMass(int id) {
        mats.forget(id);
        for (String g : groups.keySet()) {
            syncGroup(g);
        }
    }

    /** An interaction left the model: drop it from every subset. */
    public void forgetLink(int id) {
        links.forget(id);
    }

    public void clear() {
        mats.clear();
        links.clear();
        groups.clear();
    }

    // ---------------------------------------------------------------- grouped parameters

    /**
     * Sets one parameter ("mass", "stiffness", "damping" or "dist") on every member of a subset. Every member
     * is checked before any is changed, and the whole change is analysed (and undone under THROW) as one.
     */
    public void changeParam(String op, double value, String subset, String param) {
        boolean isMat = isMatSubset(subset);
        if (!isMat && !isLinkSubset(subset) && subset != null && isStiffnessOrDamping(param)) {
            // the paper's engine changed stiffness and damping only of subsets it found (mass and dist threw)
            c.lenient.forgive(PaperLeniency.Kind.NO_SUCH_SUBSET, op, subset, "no such subset", "nothing was changed");
            return;
        }
        if (!isMat) {
            requireLinkSubset(op, subset);
        }
        if (!java.util.Arrays.asList(PARAMS).contains(param)) {
            c.lenient.forgive(PaperLeniency.Kind.UNKNOWN_PARAMETER_NAME, op, subset, "param must be \"mass\", "
                    + "\"stiffness\", \"damping\" or \"dist\", got \"" + param + "\"", "nothing was changed");
            return;
        }
        Check.finite(op, subset, param, value);
        Set<Integer> members = isMat ? mats.members(subset) : links.members(subset);
        changeParamOf(op, isMat, lenientMembers(op, isMat, members, param), param, value);
    }

    private static boolean isStiffnessOrDamping(String param) {
        return "stiffness".equals(param) || "damping".equals(param);
    }

    /**
     * @return the members that have {@code param}; the others (a ground in a mass change, a Mass3D in a stiffness
     *     change, a Spring3D in a damping change ...) are left alone, as the paper's engine did, with one warning,
     *     or, in strict mode, make this throw. Returns {@code members} itself when all of them have it.
     */
    public java.util.Collection<Integer> lenientMembers(String op, boolean isMat, java.util.Collection<Integer> members,
                                                 String param) {
        List<Integer> kept = new ArrayList<>(members.size());
        for (int id : members) {
            String lacks = lacks(isMat, id, param);
            if (lacks == null) {
                kept.add(id);
            } else {
                c.lenient.forgive(PaperLeniency.Kind.NO_SUCH_PARAMETER, op, isMat ? c.dir.massName(id)
                        : c.dir.linkName(id), lacks, "it was left alone and the other members were changed");
            }
        }
        return kept.size() == members.size() ? members : kept;
    }

    /** @return the error for a member that has no such parameter ("a Ground3D has no mass parameter"), or null. */
    private String lacks(boolean isMat, int id, String param) {
        if (isMat) {
            MassKind k = engine.massKind(id);
            boolean ok = "mass".equals(param) ? k.isInertial()
                    : ("stiffness".equals(param) || "damping".equals(param)) && k.isOscillator();
            return ok ? null : "a " + k.label() + " has no " + param + " parameter";
        }
        LinkKind k = engine.linkKind(id);
        boolean ok = "stiffness".equals(param) ? k.hasStiffness()
                : "damping".equals(param) ? k.hasDamping()
                : "dist".equals(param) && k.hasLength();
        return ok ? null : "a " + k.label() + " has no " + param + " parameter";
    }

    /**
     * Sets one parameter on the given masses (or interactions): every one is checked before any is changed, and
     * the whole change is analysed (and undone under THROW) as one.
     */
    public void changeParamOf(String op, boolean isMat, java.util.Collection<Integer> members, String param, double value) {
        for (int id : members) {
            checkMember(op, isMat, id, param, value);
        }
        List<Runnable> undo = new ArrayList<>();
        guard.defer();
        try {
            for (int id : members) {
                undo.add(snapshot(isMat, id));
                apply(op, isMat, id, param, value);
            }
        } finally {
            guard.resume();
        }
        guard.afterChange(() -> undo.forEach(Runnable::run));
    }

    /** @return the value of a parameter for the first member of a subset, in model units. */
    public double paramValue(String op, String subset, String param) {
        boolean isMat = isMatSubset(subset);
        if (!isMat && !isLinkSubset(subset) && subset != null) {
            c.lenient.forgive(PaperLeniency.Kind.NO_SUCH_SUBSET, op, subset, "no such subset", "-1 was returned");
            return -1;
        }
        Set<Integer> members = members(op, subset);
        if (members.isEmpty()) {
            if (!isMat) { // the paper's engine answered -1 for an empty link subset (and threw for a mass subset)
                c.lenient.forgive(PaperLeniency.Kind.NO_SUCH_SUBSET, op, subset, "the subset is empty",
                        "-1 was returned");
                return -1;
            }
            throw Check.fail(op, subset, "the subset is empty");
        }
        int id = members.iterator().next();
        String lacks = lacks(isMat, id, param);
        if (lacks != null) {
            if (!java.util.Arrays.asList(PARAMS).contains(param)) {
                lacks = "param must be \"mass\", \"stiffness\", \"damping\" or \"dist\", got \"" + param + "\"";
            }
            // what the paper's engine answered: a ground's nominal mass 1, 0 for the missing stiffness or damping of
            // an interaction, -1 otherwise
            double answer = isMat ? ("mass".equals(param) ? 1 : -1) : (isStiffnessOrDamping(param) ? 0 : -1);
            c.lenient.forgive(PaperLeniency.Kind.NO_SUCH_PARAMETER, op, isMat ? c.dir.massName(id)
                    : c.dir.linkName(id), lacks, answer + " was returned");
            return answer;
        }
        UnitScale u = c.units();
        if (isMat) {
            return "mass".equals(param) ? engine.mass(id)
                    : "stiffness".equals(param) ? u.stiffnessOut(engine.oscStiffness(id))
                    : u.dampingOut(engine.oscDamping(id));
        }
        return "stiffness".equals(param) ? u.stiffnessOut(engine.linkStiffness(id))
                : "damping".equals(param) ? u.dampingOut(engine.linkDamping(id)) : engine.linkLength(id);
    }

    /** Checks that {@code value} suits parameter {@code param} of every given member (see {@link #changeParam}). */
    public void checkAll(String op, boolean isMat, int[] ids, String param, double value) {
        for (int id : ids) {
            checkMember(op, isMat, id, param, value);
        }
    }

    private void checkMember(String op, boolean isMat, int id, String param, double value) {
        String lacks = lacks(isMat, id, param);
        if (lacks != null) {
            throw Check.fail(op, isMat ? c.dir.massName(id) : c.dir.linkName(id), lacks);
        }
        if (isMat && "mass".equals(param)) {
            Check.positive(op, c.dir.massName(id), "mass", value);
        } else if (!isMat && "dist".equals(param)) {
            ParamEditor.checkLength(op, c.dir.linkName(id), engine.linkKind(id), value);
        }
    }

    private void apply(String op, boolean isMat, int id, String param, double value) {
        if (isMat) {
            if ("mass".equals(param)) {
                params.setMass(op, id, value);
            } else {
                params.setOsc(op, id, "stiffness".equals(param) ? value : Double.NaN,
                        "damping".equals(param) ? value : Double.NaN);
            }
        } else {
            params.setLink(op, id, "stiffness".equals(param) ? value : Double.NaN,
                    "damping".equals(param) ? value : Double.NaN, "dist".equals(param) ? value : Double.NaN);
        }
    }

    /** @return an undo that restores the parameters a mass or interaction has now. */
    public Runnable snapshot(boolean isMat, int id) {
        if (isMat) {
            double m = engine.mass(id);
            if (engine.massKind(id).isOscillator()) {
                double k = engine.oscStiffness(id), z = engine.oscDamping(id);
                return () -> {
                    engine.setMass(id, m);
                    engine.setOscillator(id, k, z);
                };
            }
            return () -> engine.setMass(id, m);
        }
        double k = engine.linkStiffness(id), z = engine.linkDamping(id), l = engine.linkLength(id);
        return () -> engine.setLinkParams(id, k, z, l);
    }

    /** @return the mean position of a mass subset's members. */
    public Vect3D barycenter(String op, String subset, double[] tmp) {
        Set<Integer> members = mats.members(requireMatSubset(op, subset));
        if (members.isEmpty()) {
            throw Check.fail(op, subset, "the subset is empty");
        }
        double sx = 0, sy = 0, sz = 0;
        for (int id : members) {
            engine.position(id, tmp);
            sx += tmp[0];
            sy += tmp[1];
            sz += tmp[2];
        }
        int n = members.size();
        return new Vect3D(sx / n, sy / n, sz / n);
    }

    // ---------------------------------------------------------------- contact groups

    public void addContactGroup(String op, String subset, double threshold, double K, double Z) {
        requireMatSubset(op, subset);
        if (groups.containsKey(subset)) {
            throw Check.fail(op, subset, "this subset already has a contact group");
        }
        UnitScale u = c.units();
        int gid = engine.addContactGroup(memberIds(subset), threshold, u.stiffnessIn(K), u.dampingIn(Z));
        groups.put(subset, gid);
        guard.afterChange(() -> {
            engine.removeContactGroup(gid);
            groups.remove(subset);
        });
        topology.compileIfRunning();
    }

    public void setContactGroupParams(String op, String subset, double threshold, double K, double Z) {
        int gid = requireGroup(op, subset);
        double[] old = engine.contactGroupParams(gid);
        UnitScale u = c.units();
        engine.setContactGroupParams(gid, threshold, u.stiffnessIn(K), u.dampingIn(Z));
        guard.afterChange(() -> engine.setContactGroupParams(gid, old[0], old[1], old[2]));
        topology.compileIfRunning();
    }

    public void removeContactGroup(String op, String subset) {
        engine.removeContactGroup(requireGroup(op, subset));
        groups.remove(subset);
        topology.compileIfRunning();
    }

    public boolean hasContactGroup(String subset) {
        return groups.containsKey(subset);
    }

    /** @return the names of the subsets that have a contact group, in creation order. */
    public String[] contactGroupSubsets() {
        return groups.keySet().toArray(new String[0]);
    }

    /** @return the engine ids of the live contact groups, in creation order. */
    public int[] groupIds() {
        return groups.values().stream().mapToInt(Integer::intValue).toArray();
    }

    /** @return the subset names of the live contact groups, in the engine's compiled order. */
    public String[] groupNames() {
        return groups.keySet().toArray(new String[0]);
    }

    private int requireGroup(String op, String subset) {
        Integer gid = groups.get(subset);
        if (gid == null) {
            throw Check.fail(op, String.valueOf(subset), "this subset has no contact group");
        }
        return gid;
    }

    /** @return the ids of a mass subset's members, in subset order. */
    public int[] memberIds(String subset) {
        return mats.members(subset).stream().mapToInt(Integer::intValue).toArray();
    }

    /** Pushes a mass subset's current members to its contact group, if it has one. */
    private void syncGroup(String subset) {
        Integer gid = groups.get(subset);
        if (gid != null) {
            engine.setContactGroupMembers(gid, memberIds(subset));
            topology.compileIfRunning();
        }
    }
}
