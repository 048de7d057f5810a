package tactus;


/**
 * An interaction with a stiffness K, a damping Z and a length parameter: the spring-damper family
 * (springs, ropes, contacts, bubbles, 1D spring-dampers). The length is a rest length, a contact
 * threshold or a bubble radius depending on the type.
 */
public abstract class ElasticInteraction extends Interaction {
    ElasticInteraction(ModuleHandles handles, int id) {
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

    /** {@return the damping (REAL_UNITS: N·s/m)} */
    public double getDamping() {
        return damping();
    }

    /** Sets the damping (REAL_UNITS: N·s/m). */
    public void setDamping(double Z) {
        damping(Z);
    }

    /** {@return the length parameter: rest length, threshold or radius (model length units)} */
    public double getLength() {
        return length();
    }

    /** Sets the length parameter: rest length, threshold or radius, &ge; 0. */
    public void setLength(double d) {
        length("setLength", d);
    }
}
