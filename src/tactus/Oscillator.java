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
        checkValid();
        return model.getMatStiffness(model.massName(id));
    }

    /** Sets the internal stiffness (REAL_UNITS: N/m). */
    public void setStiffness(double K) {
        checkValid();
        model.setMatStiffness(model.massName(id), K);
    }

    /** @return the internal damping (REAL_UNITS: N·s/m). */
    public double getDamping() {
        checkValid();
        return model.getMatDamping(model.massName(id));
    }

    /** Sets the internal damping (REAL_UNITS: N·s/m). */
    public void setDamping(double Z) {
        checkValid();
        model.setMatDamping(model.massName(id), Z);
    }
}
