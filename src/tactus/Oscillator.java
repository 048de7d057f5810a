package tactus;

/**
 * A mass tied to its rest position by an internal spring and damper (Osc3D, Osc1D). Parameter
 * changes take effect at the next step.
 */
public abstract class Oscillator extends InertialMass {
    Oscillator(PhysicalModel model, int id) {
        super(model, id);
    }

    /** @return the internal stiffness (REAL_UNITS: N/m). */
    public double getStiffness() {
        model.enter(this);
        try {
            return model.core.params.oscStiffness("getStiffness", id);
        } finally {
            model.exit();
        }
    }

    /** Sets the internal stiffness (REAL_UNITS: N/m). */
    public void setStiffness(double K) {
        checkFinite("setStiffness", "K", K);
        model.enter(this);
        try {
            model.core.params.setOsc("setStiffness", id, K, Double.NaN);
        } finally {
            model.exit();
        }
    }

    /** @return the internal damping (REAL_UNITS: N·s/m). */
    public double getDamping() {
        model.enter(this);
        try {
            return model.core.params.oscDamping("getDamping", id);
        } finally {
            model.exit();
        }
    }

    /** Sets the internal damping (REAL_UNITS: N·s/m). */
    public void setDamping(double Z) {
        checkFinite("setDamping", "Z", Z);
        model.enter(this);
        try {
            model.core.params.setOsc("setDamping", id, Double.NaN, Z);
        } finally {
            model.exit();
        }
    }
}
