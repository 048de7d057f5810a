package tactus;

import tactus.engine.MassKind;

/**
 * A handle on one mass-type module of a {@link PhysicalModel}: a thin view onto its slot in the
 * engine's arrays. Handles stay valid until the module is removed, the model is cleared, or the
 * mass is turned into a fixed point; after that every method throws {@link IllegalStateException}.
 */
public abstract class Mass extends Module {
    Mass(PhysicalModel model, int id) {
        super(model, id);
    }

    static Mass create(PhysicalModel model, int id, MassKind kind) {
        switch (kind) {
            case MASS3D:
                return new Mass3D(model, id);
            case MASS2D_PLANE:
                return new Mass2DPlane(model, id);
            case MASS1D:
                return new Mass1D(model, id);
            case OSC3D:
                return new Osc3D(model, id);
            case OSC1D:
                return new Osc1D(model, id);
            case HAPTIC_INPUT3D:
                return new HapticInput3D(model, id);
            case POS_INPUT3D:
                return new PosInput3D(model, id);
            case GROUND3D:
                return new Ground3D(model, id);
            case GROUND1D:
                return new Ground1D(model, id);
            default:
                throw new IllegalStateException("no handle for " + kind);
        }
    }

    @Override
    public String getName() {
        checkValid();
        return model.massName(id);
    }

    @Override
    public String getType() {
        checkValid();
        return model.massKindOf(id).label();
    }

    /** @return a copy of the current position, in model units. */
    public Vect3D getPosition() {
        checkValid();
        return model.position(id, new Vect3D());
    }

    /** Writes the current position into {@code out} without allocating, and returns it. */
    public Vect3D getPosition(Vect3D out) {
        checkValid();
        return model.position(id, out);
    }

    /** @return the velocity over the last step, in units per second. */
    public Vect3D getVelocity() {
        checkValid();
        return model.velocity(id, new Vect3D());
    }

    /** @return the force accumulated on this mass by the last interaction phase (REAL_UNITS: N). */
    public Vect3D getForce() {
        checkValid();
        return model.force(id, new Vect3D());
    }

    /** Moves this mass to a position with zero velocity. */
    public void setPosition(Vect3D pos) {
        checkValid();
        model.setMatPosition(model.massName(id), pos);
    }

    /** Adds a force for the next step only (REAL_UNITS: N). */
    public void applyForce(double fx, double fy, double fz) {
        checkValid();
        model.triggerForceImpulse(model.massName(id), fx, fy, fz);
    }
}
