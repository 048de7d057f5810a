package tactus;

/**
 * A spring-damper with a cubic term, Faust mi.lib's {@code nlSpringDamper3}: with e the elongation and v its rate,
 * {@code F = K e + Q e^3 + Z v}. Its slope grows with e^2: past a displacement the explicit scheme becomes
 * unstable, and the stability check can bound only its linear part K.
 */
public abstract class CubicSpringDamper extends ElasticInteraction {
    CubicSpringDamper(ModuleHandles handles, int id) {
        super(handles, id);
    }

    /** {@return the cubic stiffness Q (REAL_UNITS: N/m^3; mi.lib's q)} */
    public double getCubicStiffness() {
        return aux("getCubicStiffness", 0);
    }

    /** Sets the cubic stiffness Q (REAL_UNITS: N/m^3; mi.lib's q). */
    public void setCubicStiffness(double q) {
        aux("setCubicStiffness", 0, q);
    }
}
