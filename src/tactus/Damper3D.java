package tactus;

import tactus.internal.realtime.ModelLock;
import tactus.internal.ModelCore;

/** A radial damper: f = -Z (d(n) - d(n-1)) along the line between the masses. */
public final class Damper3D extends Interaction {
    Damper3D(ModelCore core, ModelLock gate, int id) {
        super(core, gate, id);
    }

    /** @return the damping (REAL_UNITS: N·s/m). */
    public double getDamping() {
        return damping();
    }

    /** Sets the damping (REAL_UNITS: N·s/m). */
    public void setDamping(double Z) {
        damping(Z);
    }
}
