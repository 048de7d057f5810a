package tactus;


/** A radial damper: f = -Z (d(n) - d(n-1)) along the line between the masses. */
public final class Damper3D extends Interaction {
    Damper3D(ModuleHandles handles, int id) {
        super(handles, id);
    }

    /** {@return the damping (REAL_UNITS: N·s/m)} */
    public double getDamping() {
        return damping();
    }

    /** Sets the damping (REAL_UNITS: N·s/m). */
    public void setDamping(double Z) {
        damping(Z);
    }
}
