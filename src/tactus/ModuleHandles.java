package tactus;

import tactus.engine.LinkKind;
import tactus.engine.MassKind;
import tactus.internal.calls.ModuleCalls;
import tactus.internal.model.ModuleListener;

/**
 * The one place that makes the handles of a model's modules and keeps them by module id: the directory tells it, by
 * id, when a module joins or leaves the model ({@link ModuleListener}); the facade turns the ids its calls return
 * into handles here, and handles into the names its calls take.
 */
final class ModuleHandles implements ModuleListener {
    /** The calls every handle of this model makes (set once by the model, before its first module is added). */
    ModuleCalls calls;
    /**
     * The handles by id. Written only inside a structural change (under the model's lock, or on the stepping thread
     * while the caller holds the lock and waits), read after one or under the lock: no monitor, so the stepping
     * thread never waits here. Volatile so that a grown array is published whole.
     */
    private volatile Mass[] masses = new Mass[16];
    private volatile Interaction[] links = new Interaction[16];

    @Override
    public void massAdded(int id, MassKind kind, int stamp) {
        if (id >= masses.length) {
            masses = java.util.Arrays.copyOf(masses, Math.max(id + 1, masses.length * 2));
        }
        masses[id] = newMass(id, kind, stamp);
    }

    @Override
    public void linkAdded(int id, LinkKind kind) {
        if (id >= links.length) {
            links = java.util.Arrays.copyOf(links, Math.max(id + 1, links.length * 2));
        }
        links[id] = newLink(id, kind);
    }

    @Override
    public void massGone(int id) {
        if (id < masses.length && masses[id] != null) {
            masses[id].invalidate();
            masses[id] = null;
        }
    }

    @Override
    public void linkGone(int id) {
        if (id < links.length && links[id] != null) {
            links[id].invalidate();
            links[id] = null;
        }
    }

    /**
     * Returns the handle of a mass id that a call of the model just returned, typed as the caller declares it (the
     * id's kind decides the handle's class). Called inside the model (a read), the id and its handle agree.
     */
    @SuppressWarnings("unchecked")
    <T extends Mass> T mass(int id) {
        Mass[] all = masses;
        Mass m = id < all.length ? all[id] : null;
        if (m == null) {
            throw new IllegalStateException("the mass was removed by another thread meanwhile");
        }
        return (T) m;
    }

    /** Returns the handle of an interaction id a call just returned, or null for -1 (nothing was added). */
    @SuppressWarnings("unchecked")
    <T extends Interaction> T link(int id) {
        if (id < 0) {
            return null;
        }
        Interaction[] all = links;
        Interaction l = id < all.length ? all[id] : null;
        if (l == null) {
            throw new IllegalStateException("the interaction was removed by another thread meanwhile");
        }
        return (T) l;
    }

    /** Returns the name of a mass handle given to {@code op}, checking that it belongs to this model and is live. */
    String nameOf(Mass m) {
        if (m == null) {
            throw new IllegalArgumentException("a mass handle must not be null");
        }
        if (m.handles != this) {
            throw new IllegalArgumentException("mass handle " + m + " belongs to another model");
        }
        m.checkValid();
        return m.getName();
    }

    /** Returns the names of the two mass handles of a new interaction, refusing a mass linked to itself. */
    String[] distinct(String op, String name, Mass m1, Mass m2) {
        String a = nameOf(m1);
        String b = nameOf(m2);
        if (a.equals(b)) {
            throw tactus.internal.model.Check.fail(op, name, "cannot link mass \"" + a + "\" to itself");
        }
        return new String[] {a, b};
    }

    private Mass newMass(int id, MassKind kind, int stamp) {
        switch (kind) {
            case MASS3D:
                return new Mass3D(this, id, stamp);
            case MASS3D_SIMPLE:
                return new Mass3DSimple(this, id, stamp);
            case MASS2D_PLANE:
                return new Mass2DPlane(this, id, stamp);
            case MASS1D:
                return new Mass1D(this, id, stamp);
            case OSC3D:
                return new Osc3D(this, id, stamp);
            case OSC1D:
                return new Osc1D(this, id, stamp);
            case HAPTIC_INPUT3D:
                return new HapticInput3D(this, id, stamp);
            case POS_INPUT3D:
                return new PosInput3D(this, id, stamp);
            case GROUND3D:
                return new Ground3D(this, id, stamp);
            case GROUND1D:
                return new Ground1D(this, id, stamp);
            default:
                throw new IllegalStateException("no handle for " + kind);
        }
    }

    private Interaction newLink(int id, LinkKind kind) {
        switch (kind) {
            case SPRING3D:
                return new Spring3D(this, id);
            case DAMPER3D:
                return new Damper3D(this, id);
            case SPRING_DAMPER3D:
                return new SpringDamper3D(this, id);
            case SPRING_DAMPER1D:
                return new SpringDamper1D(this, id);
            case ROPE3D:
                return new Rope3D(this, id);
            case CONTACT3D:
                return new Contact3D(this, id);
            case BUBBLE3D:
                return new Bubble3D(this, id);
            case PLANE_CONTACT3D:
                return new PlaneContact3D(this, id);
            case ATTRACTOR3D:
                return new Attractor3D(this, id);
            case QUADRATIC_SPRING_DAMPER3D:
                return new QuadraticSpringDamper3D(this, id);
            case QUADRATIC_SPRING_DAMPER1D:
                return new QuadraticSpringDamper1D(this, id);
            case CUBIC_SPRING_DAMPER3D:
                return new CubicSpringDamper3D(this, id);
            case CUBIC_SPRING_DAMPER1D:
                return new CubicSpringDamper1D(this, id);
            case CLIPPED_SPRING_DAMPER3D:
                return new ClippedSpringDamper3D(this, id);
            case CLIPPED_SPRING_DAMPER1D:
                return new ClippedSpringDamper1D(this, id);
            case PLUCK3D:
                return new Pluck3D(this, id);
            case PLUCK1D:
                return new Pluck1D(this, id);
            case BOW3D:
                return new Bow3D(this, id);
            case BOW1D:
                return new Bow1D(this, id);
            case CLIPPED_CONTACT3D:
                return new ClippedContact3D(this, id);
            case CLIPPED_CONTACT1D:
                return new ClippedContact1D(this, id);
            default:
                throw new IllegalStateException("no handle for " + kind);
        }
    }
}
