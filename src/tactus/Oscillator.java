package tactus;

import tactus.internal.realtime.ModelLock;
import tactus.internal.ModelCore;

/**
 * A mass tied to its rest position by an internal spring and damper (Osc3D, Osc1D). Parameter
 * changes take effect at the next step.
 */
public abstract class Oscillator extends InertialMass {
    Oscillator(ModelCore core, ModelLock gate, int id) {
        super(core, gate, id);
    }

    /** @return the internal stiffness (REAL_UNITS: N/m). */
    public double getStiffness() {
        enter();
        try {
            return core.params.oscStiffness("getStiffness", id);
        } finally {
            exit();
        }
    }

    /** Sets the internal stiffness (REAL_UNITS: N/m). */
    public void setStiffness(double K) {
        checkFinite("setStiffness", "K", K);
        enter();
        try {
            core.params.setOsc("setStiffness", id, K, Double.NaN);
        } finally {
            exit();
        }
    }

    /** @return the internal damping (REAL_UNITS: N·s/m). */
    public double getDamping() {
        enter();
        try {
            return core.params.oscDamping("getDamping", id);
        } finally {
            exit();
        }
    }

    /** Sets the internal damping (REAL_UNITS: N·s/m). */
    public void setDamping(double Z) {
        checkFinite("setDamping", "Z", Z);
        enter();
        try {
            core.params.setOsc("setDamping", id, Double.NaN, Z);
        } finally {
            exit();
        }
    }
}
