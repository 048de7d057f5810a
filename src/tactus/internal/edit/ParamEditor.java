package tactus.internal.edit;

import tactus.engine.Engine;
import tactus.engine.LinkKind;
import tactus.engine.MassKind;
import tactus.internal.model.Check;
import tactus.internal.model.PaperLeniency;
import tactus.internal.model.ModelBase;
import tactus.internal.stability.StabilityGuard;

/**
 * Reads and changes module parameters in the model's units: inertia, oscillator stiffness and damping, link
 * stiffness, damping and length, plane positions and attraction factors. Every change is validated before
 * anything is written, then checked by the stability guard with an undo. The caller holds the model's lock.
 */
public final class ParamEditor {
    private final ModelBase c;
    private final StabilityGuard guard;
    private final Engine engine;

    public ParamEditor(ModelBase core, StabilityGuard guard) {
        this.guard = guard;
        this.c = core;
        this.engine = core.engine;
    }

    // ---------------------------------------------------------------- masses

    public void requireInertial(String op, int id) {
        MassKind k = engine.massKind(id);
        if (!k.isInertial()) {
            throw Check.fail(op, c.dir.massName(id), "a " + k.label() + " has no mass parameter");
        }
    }

    public void requireOsc(String op, int id) {
        MassKind k = engine.massKind(id);
        if (!k.isOscillator()) {
            throw Check.fail(op, c.dir.massName(id), "only Osc3D and Osc1D have stiffness and damping, this is a "
                    + k.label());
        }
    }

    public double mass(String op, int id) {
        requireInertial(op, id);
        return engine.mass(id);
    }

    public void setMass(String op, int id, double mass) {
        requireInertial(op, id);
        Check.positive(op, c.dir.massName(id), "mass", mass);
        double old = engine.mass(id);
        c.writes().setMass(id, mass);
        guard.afterChange(() -> engine.setMass(id, old));
    }

    /**
     * The paper's {@code getMatMassAt}: a module without inertia (a ground, an input) answers its nominal mass 1, as
     * the paper's engine did (one warning; strict mode throws).
     */
    public double paperMass(String op, int id) {
        MassKind k = engine.massKind(id);
        if (!k.isInertial()) {
            c.lenient.forgive(PaperLeniency.Kind.NO_SUCH_PARAMETER, op, c.dir.massName(id),
                    "a " + k.label() + " has no mass parameter", "1 was returned");
            return 1;
        }
        return engine.mass(id);
    }

    /** The paper's {@code setMatMass(At)}: a module without inertia is left alone (one warning; strict mode throws). */
    public void paperSetMass(String op, int id, double mass) {
        MassKind k = engine.massKind(id);
        if (!k.isInertial()) {
            c.lenient.forgive(PaperLeniency.Kind.NO_SUCH_PARAMETER, op, c.dir.massName(id),
                    "a " + k.label() + " has no mass parameter", "it was left alone");
            return;
        }
        setMass(op, id, mass);
    }

    /**
     * @return true when the mass is an oscillator; otherwise, for the paper's index calls, false after one warning
     *     (the paper's engine answered 0 or did nothing), or the exception in strict mode
     */
    public boolean paperIsOsc(String op, int id, String skipped) {
        return c.paperMassIs(MassKind::isOscillator, PaperLeniency.Kind.NO_SUCH_PARAMETER, op, id,
                "only Osc3D and Osc1D have stiffness and damping", skipped);
    }

    /** @return true when the link is a plane contact; otherwise as {@link #paperIsOsc}. */
    public boolean paperIsPlane(String op, int id) {
        LinkKind k = engine.linkKind(id);
        if (k == LinkKind.PLANE_CONTACT3D) {
            return true;
        }
        c.lenient.forgive(PaperLeniency.Kind.NO_SUCH_PARAMETER, op, c.dir.linkName(id), "only a "
                + LinkKind.PLANE_CONTACT3D.label() + " has this parameter, this is a " + k.label(), "0 was returned");
        return false;
    }

    public double oscStiffness(String op, int id) {
        requireOsc(op, id);
        return c.units().stiffnessOut(engine.oscStiffness(id));
    }

    public double oscDamping(String op, int id) {
        requireOsc(op, id);
        return c.units().dampingOut(engine.oscDamping(id));
    }

    /** Sets an oscillator's stiffness and/or damping in model units; NaN keeps the current value. */
    public void setOsc(String op, int id, double K, double Z) {
        requireOsc(op, id);
        String n = c.dir.massName(id);
        if (!Double.isNaN(K)) {
            Check.finite(op, n, "K", K);
        }
        if (!Double.isNaN(Z)) {
            Check.finite(op, n, "Z", Z);
        }
        double oldK = engine.oscStiffness(id), oldZ = engine.oscDamping(id);
        c.writes().setOscillator(id, Double.isNaN(K) ? Double.NaN : c.units().stiffnessIn(K),
                Double.isNaN(Z) ? Double.NaN : c.units().dampingIn(Z));
        guard.afterChange(() -> engine.setOscillator(id, oldK, oldZ));
    }

    // ---------------------------------------------------------------- interactions

    public double linkStiffness(int id) {
        return c.units().stiffnessOut(engine.linkStiffness(id));
    }

    public double linkDamping(int id) {
        return c.units().dampingOut(engine.linkDamping(id));
    }

    public double linkLength(int id) {
        return engine.linkLength(id);
    }

    /** @return the current distance between the link's masses (the gap to the plane for a plane contact). */
    public double linkDistance(int id) {
        return engine.linkDistance(id);
    }

    /** @return the distance minus the length parameter. */
    public double linkElongation(int id) {
        return engine.linkDistance(id) - engine.linkLength(id);
    }

    /**
     * Sets any of stiffness, damping, length of one link in model units; NaN means "leave unchanged" (public
     * callers reject NaN first). Validates everything before changing anything.
     */
    public void setLink(String op, int id, double K, double Z, double len) {
        LinkKind kind = engine.linkKind(id);
        String n = c.dir.linkName(id);
        if (!Double.isNaN(K) && !kind.hasStiffness()) {
            throw Check.fail(op, n, "a " + kind.label() + " has no stiffness");
        }
        if (!Double.isNaN(Z) && !kind.hasDamping()) {
            throw Check.fail(op, n, "a " + kind.label() + " has no damping");
        }
        if (!Double.isNaN(len)) {
            if (!kind.hasLength()) {
                throw Check.fail(op, n, "a " + kind.label() + " has no length parameter");
            }
            checkLength(op, n, kind, len);
        }
        double oldK = engine.linkStiffness(id), oldZ = engine.linkDamping(id), oldL = engine.linkLength(id);
        c.writes().setLinkParams(id, Double.isNaN(K) ? Double.NaN : c.units().stiffnessIn(K),
                Double.isNaN(Z) ? Double.NaN : c.units().dampingIn(Z), len);
        guard.afterChange(() -> engine.setLinkParams(id, oldK, oldZ, oldL));
    }

    /** Validates a length parameter for a link kind: any finite offset for planes, &gt; 0 for attractors, else &ge; 0. */
    public static void checkLength(String op, String element, LinkKind kind, double len) {
        if (kind == LinkKind.PLANE_CONTACT3D) {
            Check.finite(op, element, "l0", len);
        } else if (kind == LinkKind.ATTRACTOR3D) {
            Check.attractorLimit(op, element, len);
        } else {
            Check.nonNegative(op, element, "dist", len);
        }
    }

    /** @return the plane position of a plane contact, in length units. */
    public double planePosition(String op, int id) {
        requireKind(op, id, LinkKind.PLANE_CONTACT3D);
        return engine.planePosition(id);
    }

    public void setPlanePosition(String op, int id, double pos) {
        requireKind(op, id, LinkKind.PLANE_CONTACT3D);
        Check.finite(op, c.dir.linkName(id), "pos", pos);
        double old = engine.planePosition(id);
        c.writes().setPlanePosition(id, pos);
        guard.afterChange(() -> engine.setPlanePosition(id, old));
    }

    /** @return the attraction factor of an attractor (REAL_UNITS: N·m²). */
    public double attraction(String op, int id) {
        requireKind(op, id, LinkKind.ATTRACTOR3D);
        return c.units().forceOut(engine.attraction(id));
    }

    public void setAttraction(String op, int id, double attr) {
        requireKind(op, id, LinkKind.ATTRACTOR3D);
        Check.finite(op, c.dir.linkName(id), "attr", attr);
        double old = engine.attraction(id);
        c.writes().setAttraction(id, c.units().forceIn(attr));
        guard.afterChange(() -> engine.setAttraction(id, old));
    }

    /** @return the axis (0 = x, 1 = y, 2 = z) of a plane contact. */
    public int planeAxis(String op, int id) {
        requireKind(op, id, LinkKind.PLANE_CONTACT3D);
        return engine.linkAxis(id);
    }

    /**
     * @return parameter {@code index} beyond K, Z and the length of a link whose kind has it (its name is
     *     {@code kind.auxNames()[index]}), in the model's units
     */
    public double aux(String op, int id, int index) {
        LinkKind kind = requireAux(op, id, index);
        return c.units().paramOut(kind.auxUnit(index), engine.linkAux(id, index));
    }

    /** Sets parameter {@code index} beyond K, Z and the length of a link, in the model's units, validated first. */
    public void setAux(String op, int id, int index, double value) {
        LinkKind kind = requireAux(op, id, index);
        checkAux(op, c.dir.linkName(id), kind, index, value);
        double old = engine.linkAux(id, index);
        c.writes().setLinkAux(id, index, c.units().paramIn(kind.auxUnit(index), value));
        guard.afterChange(() -> engine.setLinkAux(id, index, old));
    }

    /**
     * Validates a parameter beyond K, Z and the length: finite; a pluck's or a bow's scale &gt; 0; a bow's profile 0
     * (piecewise linear) or 1 (smooth); a clipped law's cubic stiffness C and bound Kmax &ge; 0.
     */
    public static void checkAux(String op, String element, LinkKind kind, int index, double value) {
        String name = kind.auxNames()[index];
        Check.finite(op, element, name, value);
        if (name.equals("scale")) {
            Check.positive(op, element, name, value);
        } else if (name.equals("profile") && value != 0 && value != 1) {
            throw Check.fail(op, element, "profile must be 0 (piecewise linear) or 1 (smooth), got " + value);
        } else if (name.equals("C") || name.equals("Kmax")) {
            Check.nonNegative(op, element, name, value);
        }
    }

    private LinkKind requireAux(String op, int id, int index) {
        LinkKind k = engine.linkKind(id);
        if (index < 0 || index >= k.auxCount()) {
            throw Check.fail(op, c.dir.linkName(id), "a " + k.label() + " has no such parameter");
        }
        return k;
    }

    private void requireKind(String op, int id, LinkKind kind) {
        LinkKind k = engine.linkKind(id);
        if (k != kind) {
            throw Check.fail(op, c.dir.linkName(id), "only a " + kind.label() + " has this parameter, this is a "
                    + k.label());
        }
    }
}
