package tactus;

/**
 * A spring-damper with a quadratic term, Faust mi.lib's {@code nlSpringDamper2}: with e the elongation and v its
 * rate, {@code F = K e + Q sgn(e) e^2 + Z v}. Its slope grows with |e|: past a displacement the explicit scheme
 * becomes unstable, and the stability check can bound only its linear part K.
 */
public abstract class QuadraticSpringDamper extends ElasticInteraction {
    QuadraticSpringDamper(ModuleHandles handles, int id) {
        super(handles, id);
    }

    /** {@return the quadratic stiffness Q (REAL_UNITS: N/m^2; mi.lib's q)} */
    public double getQuadraticStiffness() {
        return aux("getQuadraticStiffness", 0);
    }

    /** Sets the quadratic stiffness Q (REAL_UNITS: N/m^2; mi.lib's q). */
    public void setQuadraticStiffness(double q) {
        aux("setQuadraticStiffness", 0, q);
    }
}
