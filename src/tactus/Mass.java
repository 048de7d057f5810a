package tactus;

import tactus.internal.calls.ModuleCalls;

/**
 * A handle on one mass-type module of a {@link PhysicalModel}: a thin view onto its slot in the
 * engine's arrays. Handles stay valid until the module is removed, the model is cleared, or the
 * mass is turned into a fixed point; after that every method throws {@link IllegalStateException}.
 */
public abstract class Mass extends Module {
    /** The stamp of the module this handle was made for (a mass made fixed keeps its id under a new stamp). */
    final int stamp;

    Mass(ModuleHandles handles, int id, int stamp) {
        super(handles, id);
        this.stamp = stamp;
    }

    @Override
    public String getName() {
        checkValid();
        return calls.massName(id, stamp);
    }

    @Override
    public String getType() {
        checkValid();
        return calls.massType(id, stamp);
    }

    /** {@return a copy of the current position, in model units} */
    public Vect3D getPosition() {
        return getPosition(new Vect3D());
    }

    /** Writes the current position into {@code out} without allocating, and returns it. */
    public Vect3D getPosition(Vect3D out) {
        checkValid();
        return calls.motion(id, stamp, ModuleCalls.Motion.POSITION, out);
    }

    /** {@return the velocity over the last step, in units per second} */
    public Vect3D getVelocity() {
        checkValid();
        return calls.motion(id, stamp, ModuleCalls.Motion.VELOCITY, new Vect3D());
    }

    /** {@return the force accumulated on this mass by the last interaction phase (REAL_UNITS: N)} */
    public Vect3D getForce() {
        checkValid();
        return calls.motion(id, stamp, ModuleCalls.Motion.FORCE, new Vect3D());
    }

    /** Moves this mass to a position with zero velocity (see {@link PhysicalModel#setMatPosition}). */
    public void setPosition(Vect3D pos) {
        checkVector("setPosition", "pos", pos);
        calls.setPosition(id, stamp, pos);
    }

    /** Adds a force for the next step only (REAL_UNITS: N). */
    public void applyForce(double fx, double fy, double fz) {
        checkFinite("applyForce", "fx", fx);
        checkFinite("applyForce", "fy", fy);
        checkFinite("applyForce", "fz", fz);
        calls.applyForce(id, stamp, fx, fy, fz);
    }
}
