package tactus.internal.edit;

import tactus.engine.Engine;
import tactus.engine.LinkKind;
import tactus.engine.MassKind;
import tactus.Vect3D;
import tactus.internal.model.Check;
import tactus.internal.model.UnitScale;
import tactus.internal.model.ModelBase;
import tactus.internal.stability.StabilityGuard;

/**
 * Adds masses and interactions: validates every argument (naming the element and the value), creates the
 * module in the engine in per-step units, registers its name and handle, and lets the stability guard check
 * the result (a rejected module is removed again). Mass names are unique; interaction names may repeat. The
 * caller holds the model's lock.
 */
public final class ModuleBuilder {
    private final ModelBase c;
    private final StabilityGuard guard;
    private final TopologyEditor topology;
    private final Engine engine;

    public ModuleBuilder(ModelBase core, StabilityGuard guard, TopologyEditor topology) {
        this.guard = guard;
        this.topology = topology;
        this.c = core;
        this.engine = core.engine;
    }

    /** Validates the arguments that do not depend on the model's state (no lock needed). */
    public static void checkMassArgs(String op, MassKind kind, String name, double m, Vect3D pos, Vect3D vel,
                              double K, double Z, int smoothing) {
        Check.name(op, name);
        Check.vector(op, name, "initPos", pos);
        Check.vector(op, name, "initVel", vel);
        if (kind.isInertial()) {
            Check.positive(op, name, "mass", m);
        }
        if (kind.isOscillator()) {
            Check.finite(op, name, "K", K);
            Check.finite(op, name, "Z", Z);
        }
        if (kind.isInput() && smoothing < 1) {
            throw Check.fail(op, name, "smoothing must be >= 1 step, got " + smoothing);
        }
    }

    public int addMass(String op, MassKind kind, String name, double m, Vect3D pos, Vect3D vel,
                 double K, double Z, int smoothing) {
        if (c.dir.mats.id(name) >= 0) {
            throw Check.fail(op, name, "a mass with this name already exists");
        }
        UnitScale u = c.units();
        int id = engine.addMass(kind, m, pos.x, pos.y, pos.z,
                u.velocityIn(vel.x), u.velocityIn(vel.y), u.velocityIn(vel.z));
        if (kind.isOscillator()) {
            engine.setOscillator(id, u.stiffnessIn(K), u.dampingIn(Z));
        }
        if (kind.isInput()) {
            engine.setInputWeight(id, 1.0 / smoothing);
        }
        c.dir.registerMass(name, id, kind);
        guard.afterChange(() -> topology.removeMass(id));
        topology.compileIfRunning();
        return id;
    }

    /** Validates the arguments of an interaction that do not depend on the model's state. */
    public static void checkLinkArgs(String op, LinkKind kind, String name, double K, double Z, double len,
                              double aux, int axis) {
        Check.name(op, name);
        Check.finite(op, name, "K", K);
        Check.finite(op, name, "Z", Z);
        ParamEditor.checkLength(op, name, kind, len);
        if (kind == LinkKind.PLANE_CONTACT3D) {
            Check.finite(op, name, "pos", aux);
            if (axis < 0 || axis > 2) {
                throw Check.fail(op, name, "orientation must be 0 (x), 1 (y) or 2 (z), got " + axis);
            }
        }
        if (kind == LinkKind.ATTRACTOR3D) {
            Check.finite(op, name, "attr", aux);
        }
    }

    public int addLink(String op, LinkKind kind, String name, int a, int b, double K, double Z, double len,
                        double aux, int axis) {
        if (!kind.isSingleMass() && a == b) {
            throw Check.fail(op, name, "cannot link mass \"" + c.dir.massName(a) + "\" to itself");
        }
        UnitScale u = c.units();
        int id;
        if (kind == LinkKind.PLANE_CONTACT3D) {
            id = engine.addPlaneContact(a, axis, aux, len, u.stiffnessIn(K), u.dampingIn(Z));
        } else if (kind == LinkKind.ATTRACTOR3D) {
            id = engine.addAttractor(a, b, len, u.forceIn(aux));
        } else {
            id = engine.addLink(kind, a, b, u.stiffnessIn(K), u.dampingIn(Z), len);
        }
        c.dir.registerLink(name, id, kind);
        guard.afterChange(() -> topology.removeLink(id));
        topology.compileIfRunning();
        if (kind == LinkKind.CONTACT3D && engine.linkDistance(id) == 0) {
            System.err.println(coincidentContactWarning(name, c.dir.massName(a), c.dir.massName(b)));
        }
        return id;
    }

    /**
     * Adds an interaction whose kind has parameters beyond K, Z and the length (mi.lib's nonlinear interactions):
     * {@code aux} holds them in the order of {@link LinkKind#auxNames()}, in the model's units. Validates them all
     * first, then adds as {@link #addLink}.
     */
    public int addLinkWithAux(String op, LinkKind kind, String name, int a, int b, double K, double Z, double len,
                              double... aux) {
        if (aux.length != kind.auxCount()) {
            throw new IllegalArgumentException(op + ": a " + kind.label() + " takes " + kind.auxCount()
                    + " parameters beyond K, Z and the length, got " + aux.length);
        }
        for (int i = 0; i < aux.length; i++) {
            ParamEditor.checkAux(op, name, kind, i, aux[i]);
        }
        if (a == b) {
            throw Check.fail(op, name, "cannot link mass \"" + c.dir.massName(a) + "\" to itself");
        }
        UnitScale u = c.units();
        int id = engine.addLink(kind, a, b, u.stiffnessIn(K), u.dampingIn(Z), len);
        for (int i = 0; i < aux.length; i++) {
            engine.setLinkAux(id, i, u.paramIn(kind.auxUnit(i), aux[i]));
        }
        c.dir.registerLink(name, id, kind);
        guard.afterChange(() -> topology.removeLink(id));
        topology.compileIfRunning();
        return id;
    }

    /** The warning printed once, when a Contact3D is added between two masses at exactly the same position. */
    public static String coincidentContactWarning(String link, String m1, String m2) {
        return "Tactus: Contact3D \"" + link + "\" joins \"" + m1 + "\" and \"" + m2 + "\" at exactly the same"
                + " position: at distance 0 a contact has no direction to push along, so it exerts no force until"
                + " the masses separate";
    }
}
