package tactus;


/** A linear spring: f = -K (d - l0) along the line between the masses, with no damping. */
public final class Spring3D extends Interaction {
    Spring3D(ModuleHandles handles, int id) {
        super(handles, id);
    }

    /** {@return the stiffness (REAL_UNITS: N/m)} */
    public double getStiffness() {
        return stiffness();
    }

    /** Sets the stiffness (REAL_UNITS: N/m). */
    public void setStiffness(double K) {
        stiffness(K);
    }

    /** {@return the rest length} */
    public double getLength() {
        return length();
    }

    /** Sets the rest length, &ge; 0. */
    public void setLength(double d) {
        length("setLength", d);
    }
}
