package tactus.internal.calls;

import tactus.Vect3D;
import tactus.linkModuleType;
import tactus.engine.LinkKind;
import tactus.engine.MassKind;
import tactus.internal.edit.ModuleBuilder;
import tactus.internal.edit.OscTuning;
import tactus.internal.model.Check;
import tactus.internal.model.PaperLeniency;
import tactus.internal.realtime.ModelLock;
import tactus.internal.ModelCore;

/**
 * The facade calls that build and edit a model: adding masses and interactions, tuning oscillators, removals,
 * subsets and their grouped parameters, contact groups. Each enters the model once and hands the work to its room.
 * Not API.
 */
public final class BuildCalls extends Calls {
    public BuildCalls(ModelCore core, ModelLock gate) {
        super(core, gate);
    }

    public int addMass3D(String name, double mass, Vect3D initPos, Vect3D initVel) {
        return addMass("addMass3D", MassKind.MASS3D, name, mass, initPos, initVel, 0, 0, 1);
    }

    public int addMass3DSimple(String name, double mass, Vect3D initPos, Vect3D initVel) {
        return addMass("addMass3DSimple", MassKind.MASS3D_SIMPLE, name, mass, initPos, initVel, 0, 0,
                1);
    }

    public int addMass2DPlane(String name, double mass, Vect3D initPos, Vect3D initVel) {
        return addMass("addMass2DPlane", MassKind.MASS2D_PLANE, name, mass, initPos, initVel, 0, 0, 1);
    }

    public int addMass1D(String name, double mass, Vect3D initPos, Vect3D initVel) {
        return addMass("addMass1D", MassKind.MASS1D, name, mass, initPos, initVel, 0, 0, 1);
    }

    public int addGround3D(String name, Vect3D initPos) {
        return addMass("addGround3D", MassKind.GROUND3D, name, 1, initPos, new Vect3D(), 0, 0, 1);
    }

    public int addGround1D(String name, Vect3D initPos) {
        return addMass("addGround1D", MassKind.GROUND1D, name, 1, initPos, new Vect3D(), 0, 0, 1);
    }

    public int addOsc3D(String name, double mass, double K, double Z, Vect3D initPos, Vect3D initVel) {
        return addMass("addOsc3D", MassKind.OSC3D, name, mass, initPos, initVel, K, Z, 1);
    }

    public int addOsc1D(String name, double mass, double K, double Z, Vect3D initPos, Vect3D initVel) {
        return addMass("addOsc1D", MassKind.OSC1D, name, mass, initPos, initVel, K, Z, 1);
    }

    public int addOsc3DTuned(String name, double mass, double freqHz, double t60, Vect3D initPos, Vect3D initVel) {
        return addTunedOsc("addOsc3DTuned", MassKind.OSC3D, name, mass, freqHz, t60, initPos, initVel);
    }

    public int addOsc1DTuned(String name, double mass, double freqHz, double t60, Vect3D initPos, Vect3D initVel) {
        return addTunedOsc("addOsc1DTuned", MassKind.OSC1D, name, mass, freqHz, t60, initPos, initVel);
    }

    private int addTunedOsc(String op, MassKind kind, String name, double mass, double freqHz, double t60, Vect3D pos, Vect3D vel) {
        return structural(() -> {
            double[] kz = OscTuning.coefficients(core, core.params, op, name, mass, freqHz, t60);
            return addMass(op, kind, name, mass, pos, vel, kz[0], kz[1], 1);
        });
    }

    public void tuneOsc(String name, double freqHz, double t60) {
        enterChange();
        try {
            OscTuning.tune(core, core.params, "tuneOsc", core.dir.massId("tuneOsc", name), freqHz, t60);
        } finally {
            exit();
        }
    }

    public double getOscFrequency(String name) {
        enter();
        try {
            return OscTuning.frequency(core, core.params, "getOscFrequency", core.dir.massId("getOscFrequency", name));
        } finally {
            exit();
        }
    }

    public double getOscT60(String name) {
        enter();
        try {
            return OscTuning.t60(core, core.params, "getOscT60", core.dir.massId("getOscT60", name));
        } finally {
            exit();
        }
    }

    public int addHapticInput3D(String name, Vect3D initPos, int smoothing) {
        return addMass("addHapticInput3D", MassKind.HAPTIC_INPUT3D, name, 1, initPos,
                new Vect3D(), 0, 0, smoothing);
    }

    public int addPosInput3D(String name, Vect3D initPos, int smoothing) {
        return addMass("addPosInput3D", MassKind.POS_INPUT3D, name, 1, initPos,
                new Vect3D(), 0, 0, smoothing);
    }

    private int addMass(String op, MassKind kind, String name, double m, Vect3D pos, Vect3D vel, double K, double Z, int smoothing) {
        ModuleBuilder.checkMassArgs(op, kind, name, m, pos, vel, K, Z, smoothing);
        return structural(() -> {
            int added = core.builder.addMass(op, kind, name, m, pos, vel, K, Z, smoothing);
            core.gravityNote.afterMassAdded(kind, name);
            return added;
        });
    }

    public int addSpring3D(String name, double dist, double K, String m1, String m2) {
        return addLink("addSpring3D", LinkKind.SPRING3D, name, m1, m2, K, 0, dist, 0, 0);
    }


    public int addDamper3D(String name, double Z, String m1, String m2) {
        return addLink("addDamper3D", LinkKind.DAMPER3D, name, m1, m2, 0, Z, 0, 0, 0);
    }


    public int addSpringDamper3D(String name, double dist, double K, double Z, String m1, String m2) {
        return addLink("addSpringDamper3D", LinkKind.SPRING_DAMPER3D, name, m1, m2, K, Z, dist, 0, 0);
    }


    public int addSpringDamper1D(String name, double dist, double K, double Z, String m1, String m2) {
        return addLink("addSpringDamper1D", LinkKind.SPRING_DAMPER1D, name, m1, m2, K, Z, dist, 0, 0);
    }


    public int addRope3D(String name, double dist, double K, double Z, String m1, String m2) {
        return addLink("addRope3D", LinkKind.ROPE3D, name, m1, m2, K, Z, dist, 0, 0);
    }


    public int addContact3D(String name, double dist, double K, double Z, String m1, String m2) {
        return addLink("addContact3D", LinkKind.CONTACT3D, name, m1, m2, K, Z, dist, 0, 0);
    }


    public int addBubble3D(String name, double dist, double K, double Z, String m1, String m2) {
        return addLink("addBubble3D", LinkKind.BUBBLE3D, name, m1, m2, K, Z, dist, 0, 0);
    }


    public int addPlaneContact(String name, double l0, double K, double Z, int orientation, double pos, String m1) {
        return addLink("addPlaneContact", LinkKind.PLANE_CONTACT3D, name, m1, null, K, Z, l0,
                pos, orientation);
    }


    public int addAttractor3D(String name, double dLim, double attr, String m1, String m2) {
        return addLink("addAttractor3D", LinkKind.ATTRACTOR3D, name, m1, m2, 0, 0, dLim, attr, 0);
    }


    private int addLink(String op, LinkKind kind, String name, String m1, String m2, double K, double Z, double len, double aux, int axis) {
        ModuleBuilder.checkLinkArgs(op, kind, name, K, Z, len, aux, axis);
        if (!kind.isSingleMass() && m1 != null && m1.equals(m2) && !core.lenient.strict() && matExists(m1)) {
            // the paper's engine added a link that never acted (or, on a moving mass, made it NaN): add nothing
            core.lenient.forgive(PaperLeniency.Kind.SELF_LINK, op, name, "cannot link mass \"" + m1 + "\" to itself",
                    "the interaction was not added and null was returned");
            return -1;
        }
        return structural(() -> {
            int a = core.dir.endMass(op, name, m1);
            int b = kind.isSingleMass() ? a : core.dir.endMass(op, name, m2);
            return core.builder.addLink(op, kind, name, a, b, K, Z, len, aux, axis);
        });
    }

    // ---- mi.lib's nonlinear interactions: kinds with parameters beyond K, Z and the length

    public int addQuadraticSpringDamper3D(String name, double dist, double K, double Z, double Q, String m1,
            String m2) {
        return addLinkWithAux("addQuadraticSpringDamper3D", LinkKind.QUADRATIC_SPRING_DAMPER3D, name, m1, m2, K, Z,
                dist, Q);
    }

    public int addQuadraticSpringDamper1D(String name, double dist, double K, double Z, double Q, String m1,
            String m2) {
        return addLinkWithAux("addQuadraticSpringDamper1D", LinkKind.QUADRATIC_SPRING_DAMPER1D, name, m1, m2, K, Z,
                dist, Q);
    }

    public int addCubicSpringDamper3D(String name, double dist, double K, double Z, double Q, String m1, String m2) {
        return addLinkWithAux("addCubicSpringDamper3D", LinkKind.CUBIC_SPRING_DAMPER3D, name, m1, m2, K, Z, dist, Q);
    }

    public int addCubicSpringDamper1D(String name, double dist, double K, double Z, double Q, String m1, String m2) {
        return addLinkWithAux("addCubicSpringDamper1D", LinkKind.CUBIC_SPRING_DAMPER1D, name, m1, m2, K, Z, dist, Q);
    }

    public int addClippedSpringDamper3D(String name, double dist, double K, double Z, double C, double Kmax, String m1,
            String m2) {
        return addLinkWithAux("addClippedSpringDamper3D", LinkKind.CLIPPED_SPRING_DAMPER3D, name, m1, m2, K, Z, dist, C,
                Kmax);
    }

    public int addClippedSpringDamper1D(String name, double dist, double K, double Z, double C, double Kmax, String m1,
            String m2) {
        return addLinkWithAux("addClippedSpringDamper1D", LinkKind.CLIPPED_SPRING_DAMPER1D, name, m1, m2, K, Z, dist, C,
                Kmax);
    }

    public int addPluck3D(String name, double dist, double K, double Z, double scale, String m1, String m2) {
        return addLinkWithAux("addPluck3D", LinkKind.PLUCK3D, name, m1, m2, K, Z, dist, scale);
    }

    public int addPluck1D(String name, double dist, double K, double Z, double scale, String m1, String m2) {
        return addLinkWithAux("addPluck1D", LinkKind.PLUCK1D, name, m1, m2, K, Z, dist, scale);
    }

    public int addBow3D(String name, double Z, double scale, int profile, String m1, String m2) {
        return addLinkWithAux("addBow3D", LinkKind.BOW3D, name, m1, m2, 0, Z, 0, scale, profile);
    }

    public int addBow1D(String name, double Z, double scale, int profile, String m1, String m2) {
        return addLinkWithAux("addBow1D", LinkKind.BOW1D, name, m1, m2, 0, Z, 0, scale, profile);
    }

    public int addClippedContact3D(String name, double dist, double K, double Z, double C, double Kmax, String m1,
            String m2) {
        return addLinkWithAux("addClippedContact3D", LinkKind.CLIPPED_CONTACT3D, name, m1, m2, K, Z, dist, C, Kmax);
    }

    public int addClippedContact1D(String name, double dist, double K, double Z, double C, double Kmax, String m1,
            String m2) {
        return addLinkWithAux("addClippedContact1D", LinkKind.CLIPPED_CONTACT1D, name, m1, m2, K, Z, dist, C, Kmax);
    }

    public int addInteraction(linkModuleType type, String name, double dist, double K, double Z, double[] extra,
                              String m1, String m2) {
        LinkKind kind = type == null ? null : LinkKind.byLabel(type.name());
        if (kind == null || !kind.isNonlinear()) {
            throw new IllegalArgumentException("addInteraction(" + type + ", \"" + name + "\"): only the nonlinear"
                    + " types are added by type; use the add call of " + type);
        }
        if (extra == null || extra.length != kind.auxCount()) {
            throw new IllegalArgumentException("addInteraction(" + type + ", \"" + name + "\"): a " + type
                    + " takes the extra parameters " + java.util.Arrays.toString(kind.auxNames()));
        }
        return addLinkWithAux("addInteraction", kind, name, m1, m2, kind.hasStiffness() ? K : 0, Z,
                kind.hasLength() ? dist : 0, extra.clone());
    }

    private int addLinkWithAux(String op, LinkKind kind, String name, String m1, String m2, double K, double Z,
                               double len, double... aux) {
        Check.name(op, name);
        Check.finite(op, name, "K", K);
        Check.finite(op, name, "Z", Z);
        tactus.internal.edit.ParamEditor.checkLength(op, name, kind, len);
        return structural(() -> {
            int a = core.dir.endMass(op, name, m1);
            int b = core.dir.endMass(op, name, m2);
            return core.builder.addLinkWithAux(op, kind, name, a, b, K, Z, len, aux);
        });
    }

    public void removeLink(String name) {
        structuralDo(() -> {
            core.topology.removeLink(core.dir.linkId("removeLink", name));
        });
    }

    public void removeLink(int i) {
        structuralDo(() -> {
            core.topology.removeLink(core.dir.linkAt("removeLink", i));
        });
    }

    public void removeMatAndConnectedLinks(String name) {
        structuralDo(() -> {
            core.topology.removeMass(core.dir.massId("removeMatAndConnectedLinks", name));
        });
    }

    public void removeMatAndConnectedLinks(int i) {
        structuralDo(() -> {
            core.topology.removeMass(core.dir.massAt("removeMatAndConnectedLinks", i));
        });
    }

    public int changeToFixedPoint(String name) {
        return structural(() -> {
            int id = core.dir.massId("changeToFixedPoint", name);
            core.topology.makeFixed(id);
            return id;
        });
    }

    public void clearModel() {
        structuralDo(() -> {
            core.topology.clear();
        });
    }

    public void createMatSubset(String subset) {
        Check.name("createMatSubset", subset);
        if (!core.lenient.strict() && hasSubset(subset, true)) {
            core.lenient.forgive(PaperLeniency.Kind.SUBSET_EXISTS, "createMatSubset", subset,
                    "a subset with this name already exists", "the subset was kept as it is");
            return;
        }
        structuralDo(() -> {
            core.subsets.createMatSubset(subset);
        });
    }

    public void createLinkSubset(String subset) {
        Check.name("createLinkSubset", subset);
        if (!core.lenient.strict() && hasSubset(subset, false)) {
            core.lenient.forgive(PaperLeniency.Kind.SUBSET_EXISTS, "createLinkSubset", subset,
                    "a subset with this name already exists", "the subset was kept as it is");
            return;
        }
        structuralDo(() -> {
            core.subsets.createLinkSubset(subset);
        });
    }

    public void addMatToSubset(String mass, String subset) {
        if (!core.lenient.strict() && !matExists(mass)) {
            core.lenient.forgive(PaperLeniency.Kind.NO_SUCH_MODULE, "addMatToSubset", String.valueOf(mass),
                    "no mass with this name", "nothing was added to subset \"" + subset + "\"");
            return;
        }
        structuralDo(() -> {
            core.subsets.addMat("addMatToSubset", core.dir.massId("addMatToSubset", mass), subset);
        });
    }

    public void addMatToSubset(int i, String subset) {
        if (i == -1 && !core.lenient.strict()) { // getMatIndex's answer for a name that is not in the model
            core.lenient.forgive(PaperLeniency.Kind.NO_SUCH_MODULE, "addMatToSubset", "-1",
                    "mass index out of range", "nothing was added to subset \"" + subset + "\"");
            return;
        }
        structuralDo(() -> {
            core.subsets.addMat("addMatToSubset", core.dir.massAt("addMatToSubset", i), subset);
        });
    }

    public void addLinkToSubset(String link, String subset) {
        if (!core.lenient.strict() && !linkExists(link)) {
            core.lenient.forgive(PaperLeniency.Kind.NO_SUCH_MODULE, "addLinkToSubset", String.valueOf(link),
                    "no interaction with this name", "nothing was added to subset \"" + subset + "\"");
            return;
        }
        structuralDo(() -> {
            core.subsets.addLink("addLinkToSubset", core.dir.linkId("addLinkToSubset", link), subset);
        });
    }

    public void addLinkToSubset(int i, String subset) {
        if (i == -1 && !core.lenient.strict()) { // getLinkIndex's answer for a name that is not in the model
            core.lenient.forgive(PaperLeniency.Kind.NO_SUCH_MODULE, "addLinkToSubset", "-1",
                    "interaction index out of range", "nothing was added to subset \"" + subset + "\"");
            return;
        }
        structuralDo(() -> {
            core.subsets.addLink("addLinkToSubset", core.dir.linkAt("addLinkToSubset", i), subset);
        });
    }

    public void removeMatFromSubset(String mass, String subset) {
        structuralDo(() -> {
            core.subsets.removeMat("removeMatFromSubset", core.dir.massId("removeMatFromSubset", mass), subset);
        });
    }

    public void removeLinkFromSubset(String link, String subset) {
        structuralDo(() -> {
            core.subsets.removeLink("removeLinkFromSubset", core.dir.linkId("removeLinkFromSubset", link), subset);
        });
    }

    public String[] getSubsetMembers(String subset) {
        enter();
        try {
            return core.subsets.memberNames("getSubsetMembers", subset);
        } finally {
            exit();
        }
    }

    public void changeMassParamOfSubset(double mass, String subset) {
        changeSubsetParam("changeMassParamOfSubset", mass, subset, "mass");
    }

    public void changeStiffnessParamOfSubset(double K, String subset) {
        changeSubsetParam("changeStiffnessParamOfSubset", K, subset, "stiffness");
    }

    public void changeDampingParamOfSubset(double Z, String subset) {
        changeSubsetParam("changeDampingParamOfSubset", Z, subset, "damping");
    }

    public void changeDistParamOfSubset(double d, String subset) {
        changeSubsetParam("changeDistParamOfSubset", d, subset, "dist");
    }

    public void changeParamOfSubset(double value, String subset, String param) {
        changeSubsetParam("changeParamOfSubset", value, subset, param);
    }

    private void changeSubsetParam(String op, double value, String subset, String param) {
        enterChange();
        try {
            core.subsets.changeParam(op, value, subset, param);
        } finally {
            exit();
        }
    }

    public double getParamValueOfSubset(String subset, String param) {
        enter();
        try {
            return core.subsets.paramValue("getParamValueOfSubset", subset, param);
        } finally {
            exit();
        }
    }

    public Vect3D getBarycenterOfSubset(String subset) {
        enter();
        try {
            return core.subsets.barycenter("getBarycenterOfSubset", subset, new double[3]);
        } finally {
            exit();
        }
    }

    public void addContactGroup(String subset, double threshold, double K, double Z) {
        checkGroupArgs("addContactGroup", subset, threshold, K, Z);
        structuralDo(() -> {
            core.subsets.addContactGroup("addContactGroup", subset, threshold, K, Z);
        });
    }

    public void setContactGroupParams(String subset, double threshold, double K, double Z) {
        checkGroupArgs("setContactGroupParams", subset, threshold, K, Z);
        structuralDo(() -> {
            core.subsets.setContactGroupParams("setContactGroupParams", subset, threshold, K, Z);
        });
    }

    public void removeContactGroup(String subset) {
        structuralDo(() -> {
            core.subsets.removeContactGroup("removeContactGroup", subset);
        });
    }

    public boolean hasContactGroup(String subset) {
        enter();
        try {
            return core.subsets.hasContactGroup(subset);
        } finally {
            exit();
        }
    }

    private static void checkGroupArgs(String op, String subset, double threshold, double K, double Z) {
        Check.positive(op, subset, "threshold", threshold);
        Check.finite(op, subset, "K", K);
        Check.finite(op, subset, "Z", Z);
    }

    public void changeDistXBetweenSubset(Vect3D center, double dist, String subset) {
        Check.vector("changeDistXBetweenSubset", subset, "center", center);
        Check.finite("changeDistXBetweenSubset", subset, "dist", dist);
        enterChange();
        try {
            core.paper.spaceAlongX("changeDistXBetweenSubset", center, dist, subset);
        } finally {
            exit();
        }
    }
}
