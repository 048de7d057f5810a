package tactus;

/**
 * An interaction with Faust mi.lib's clipped cubic law ({@code nlSpringDamperClipped}, and
 * {@code nlCollisionClipped} for contacts): {@code K e + C e^3 + Z v} up to mi.lib's clipping displacement
 * {@code b = sqrt(Kmax - K) / C} (per-step units), then {@code Kmax e + (Z + 0.3 Kmax) v}; with C = 0 the linear
 * {@code K e + Z v}, with K &ge; Kmax the linear {@code Kmax e + Z v}. The stiffness K is mi.lib's s.
 */
public abstract class ClippedInteraction extends ElasticInteraction {
    ClippedInteraction(ModuleHandles handles, int id) {
        super(handles, id);
    }

    /** {@return the cubic stiffness C (REAL_UNITS: N/m^3; mi.lib's c)} */
    public double getCubicStiffness() {
        return aux("getCubicStiffness", 0);
    }

    /** Sets the cubic stiffness C, &ge; 0 (REAL_UNITS: N/m^3; mi.lib's c). */
    public void setCubicStiffness(double c) {
        aux("setCubicStiffness", 0, c);
    }

    /** {@return the bounding stiffness Kmax (REAL_UNITS: N/m; mi.lib's k)} */
    public double getMaxStiffness() {
        return aux("getMaxStiffness", 1);
    }

    /** Sets the bounding stiffness Kmax, &ge; 0 (REAL_UNITS: N/m; mi.lib's k). */
    public void setMaxStiffness(double k) {
        aux("setMaxStiffness", 1, k);
    }
}
