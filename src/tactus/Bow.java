package tactus;

/**
 * A bowing friction, Faust mi.lib's {@code nlBow}: a force on the relative velocity v of the two masses that
 * grows with |v| (sticking) up to a peak and then falls (slipping), the stick-slip that makes a bowed string
 * sound. Profile 0 is mi.lib's piecewise-linear curve, peaking at a third of the velocity scale and zero beyond
 * the scale; profile 1 its smooth curve {@code 0.63 Z v exp(-4 (v/scale)^2 + 1/2)}.
 */
public abstract class Bow extends Interaction {
    Bow(ModuleHandles handles, int id) {
        super(handles, id);
    }

    /** {@return the friction coefficient Z (REAL_UNITS: N·s/m; mi.lib's z)} */
    public double getDamping() {
        return damping();
    }

    /** Sets the friction coefficient Z (REAL_UNITS: N·s/m; mi.lib's z). */
    public void setDamping(double Z) {
        damping(Z);
    }

    /** {@return the velocity scale (REAL_UNITS: m/s, ALGO_UNITS: length per step; mi.lib's scale)} */
    public double getScale() {
        return aux("getScale", 0);
    }

    /** Sets the velocity scale, &gt; 0 (REAL_UNITS: m/s, ALGO_UNITS: length per step; mi.lib's scale). */
    public void setScale(double scale) {
        aux("setScale", 0, scale);
    }

    /** {@return the friction profile: 0 piecewise linear, 1 smooth (mi.lib's type)} */
    public int getProfile() {
        return (int) aux("getProfile", 1);
    }

    /** Sets the friction profile: 0 piecewise linear, 1 smooth (mi.lib's type). */
    public void setProfile(int profile) {
        aux("setProfile", 1, profile);
    }
}
