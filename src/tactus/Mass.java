package tactus;

import tactus.internal.realtime.ModelLock;
import tactus.internal.ModelCore;

/**
 * A handle on one mass-type module of a {@link PhysicalModel}: a thin view onto its slot in the
 * engine's arrays. Handles stay valid until the module is removed, the model is cleared, or the
 * mass is turned into a fixed point; after that every method throws {@link IllegalStateException}.
 */
public abstract class Mass extends Module {
    Mass(ModelCore core, ModelLock gate, int id) {
        super(core, gate, id);
    }


    @Override
    public String getName() {
        enter();
        try {
            return core.dir.massName(id);
        } finally {
            exit();
        }
    }

    @Override
    public String getType() {
        enter();
        try {
            return core.dir.massKind(id).label();
        } finally {
            exit();
        }
    }

    /** @return a copy of the current position, in model units. */
    public Vect3D getPosition() {
        return getPosition(new Vect3D());
    }

    /** Writes the current position into {@code out} without allocating, and returns it. */
    public Vect3D getPosition(Vect3D out) {
        enter();
        try {
            return core.state.position(id, out);
        } finally {
            exit();
        }
    }

    /** @return the velocity over the last step, in units per second. */
    public Vect3D getVelocity() {
        enter();
        try {
            return core.state.velocity(id, new Vect3D());
        } finally {
            exit();
        }
    }

    /** @return the force accumulated on this mass by the last interaction phase (REAL_UNITS: N). */
    public Vect3D getForce() {
        enter();
        try {
            return core.state.force(id, new Vect3D());
        } finally {
            exit();
        }
    }

    /** Moves this mass to a position with zero velocity (see {@link PhysicalModel#setMatPosition}). */
    public void setPosition(Vect3D pos) {
        checkVector("setPosition", "pos", pos);
        enter();
        try {
            core.state.setPosition(id, pos);
        } finally {
            exit();
        }
    }

    /** Adds a force for the next step only (REAL_UNITS: N). */
    public void applyForce(double fx, double fy, double fz) {
        checkFinite("applyForce", "fx", fx);
        checkFinite("applyForce", "fy", fy);
        checkFinite("applyForce", "fz", fz);
        enter();
        try {
            core.state.addImpulse(id, fx, fy, fz);
        } finally {
            exit();
        }
    }
}
