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
            case MASS3D_SIMPLE:
                return new Mass3DSimple(model, id);
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
        model.enter(this);
        try {
            return model.core.dir.massName(id);
        } finally {
            model.exit();
        }
    }

    @Override
    public String getType() {
        model.enter(this);
        try {
            return model.core.dir.massKind(id).label();
        } finally {
            model.exit();
        }
    }

    /** @return a copy of the current position, in model units. */
    public Vect3D getPosition() {
        return getPosition(new Vect3D());
    }

    /** Writes the current position into {@code out} without allocating, and returns it. */
    public Vect3D getPosition(Vect3D out) {
        model.enter(this);
        try {
            return model.core.state.position(id, out);
        } finally {
            model.exit();
        }
    }

    /** @return the velocity over the last step, in units per second. */
    public Vect3D getVelocity() {
        model.enter(this);
        try {
            return model.core.state.velocity(id, new Vect3D());
        } finally {
            model.exit();
        }
    }

    /** @return the force accumulated on this mass by the last interaction phase (REAL_UNITS: N). */
    public Vect3D getForce() {
        model.enter(this);
        try {
            return model.core.state.force(id, new Vect3D());
        } finally {
            model.exit();
        }
    }

    /** Moves this mass to a position with zero velocity (see {@link PhysicalModel#setMatPosition}). */
    public void setPosition(Vect3D pos) {
        checkVector("setPosition", "pos", pos);
        model.enter(this);
        try {
            model.core.state.setPosition(id, pos);
        } finally {
            model.exit();
        }
    }

    /** Adds a force for the next step only (REAL_UNITS: N). */
    public void applyForce(double fx, double fy, double fz) {
        checkFinite("applyForce", "fx", fx);
        checkFinite("applyForce", "fy", fy);
        checkFinite("applyForce", "fz", fz);
        model.enter(this);
        try {
            model.core.state.addImpulse(id, fx, fy, fz);
        } finally {
            model.exit();
        }
    }
}
