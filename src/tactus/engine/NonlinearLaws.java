package tactus.engine;

/**
 * The force laws of the nonlinear interactions, as Faust's {@code mi.lib} defines them, in per-step units. Each
 * law returns the force {@code F} that mi.lib computes before it routes {@code -F} to mass 1 and {@code +F} to
 * mass 2, from the displacement {@code e} (mi.lib's {@code deltapos = x1 - x2}, less the rest length) and the
 * velocity {@code v} (mi.lib's {@code deltavel}, a displacement per step). The kernels of both the 1-D and the
 * 3-D kinds call these functions, which are small enough to be inlined into their loops; the energy meter and
 * the stability check use the potentials and slopes below.
 */
public final class NonlinearLaws {
    /** mi.lib's {@code nlPluck} sharpness: the tipping point lies at a tenth of the scale. */
    public static final double PLUCK_SHARPNESS = 10;
    /** mi.lib's {@code nlBow} sharpness: the friction peaks at a third of the velocity scale. */
    public static final double BOW_SHARPNESS = 3;
    /** mi.lib's over-damping of the clipped part of {@code nlSpringDamperClipped}, as a fraction of its bound. */
    public static final double CLIP_OVERDAMPING = 0.3;

    private NonlinearLaws() {
    }

    /** mi.lib's {@code nlSpringDamper2}: {@code k e + q sgn(e) e^2 + z v}. */
    public static double quadratic(double k, double q, double z, double e, double v) {
        return k * e + q * Math.signum(e) * (e * e) + z * v;
    }

    /** mi.lib's {@code nlSpringDamper3}: {@code k e + q e^3 + z v}. */
    public static double cubic(double k, double q, double z, double e, double v) {
        return k * e + q * (e * e * e) + z * v;
    }

    /**
     * mi.lib's {@code nlSpringDamperClipped} with linear stiffness s, cubic stiffness c and bound k: {@code s e + z v}
     * when c = 0; {@code k e + z v} when s &ge; k; otherwise {@code s e + c e^3 + z v} while {@code |e| <= b} with
     * mi.lib's {@code b = sqrt(k - s) / c}, and beyond it {@code k e + (z + 0.3 k) v}.
     */
    public static double clipped(double s, double c, double k, double z, double e, double v) {
        if (c == 0) {
            return s * e + z * v;
        }
        if (s >= k) {
            return k * e + z * v;
        }
        if (Math.abs(e) <= clipPoint(s, c, k)) {
            return s * e + c * (e * e * e) + z * v;
        }
        return k * e + (z + CLIP_OVERDAMPING * k) * v;
    }

    /** {@return mi.lib's clipping displacement {@code b = sqrt(k - s) / c} of {@link #clipped} (per-step units)} */
    public static double clipPoint(double s, double c, double k) {
        return Math.sqrt(k - s) / c;
    }

    /**
     * mi.lib's {@code nlPluck} with stiffness k and distance scale: with {@code tip = scale / 10} and
     * {@code kEnd = k / 10}, {@code -(k - kEnd) e + z v} while {@code |e| < tip}, then
     * {@code -sgn(e) tip k + kEnd e + z v} while {@code |e| < scale}, and 0 beyond (the pluck has let go).
     */
    public static double pluck(double k, double scale, double z, double e, double v) {
        double a = Math.abs(e);
        double tip = scale / PLUCK_SHARPNESS;
        double kEnd = k / PLUCK_SHARPNESS;
        if (a < tip) {
            return (k - kEnd) * -e + z * v;
        }
        if (a < scale) {
            return Math.signum(e) * -tip * k + kEnd * e + z * v;
        }
        return 0;
    }

    /**
     * mi.lib's {@code nlBow} with friction z and velocity scale: the smooth profile (type &gt; 0)
     * {@code 0.63 z v exp(-4 (v / scale)^2 + 1/2)}; the piecewise-linear one, with {@code tip = scale / 3} and
     * {@code zEnd = z / 3}, {@code (z - zEnd) v} while {@code |v| < tip}, {@code sgn(v) tip z - zEnd v} while
     * {@code |v| < scale}, and 0 beyond.
     */
    public static double bow(double z, double scale, double type, double v) {
        if (type > 0) {
            double r = v / scale;
            return 0.63 * z * v * Math.exp(-4 * (r * r) + 0.5);
        }
        double a = Math.abs(v);
        double tip = scale / BOW_SHARPNESS;
        double zEnd = z / BOW_SHARPNESS;
        if (a < tip) {
            return (z - zEnd) * v;
        }
        if (a < scale) {
            return Math.signum(v) * tip * z - zEnd * v;
        }
        return 0;
    }

    /** The potential of {@link #quadratic} at displacement e: {@code k e^2 / 2 + q |e|^3 / 3}. */
    public static double quadraticPotential(double k, double q, double e) {
        double a = Math.abs(e);
        return 0.5 * k * e * e + q * a * a * a / 3;
    }

    /** The potential of {@link #cubic} at displacement e: {@code k e^2 / 2 + q e^4 / 4}. */
    public static double cubicPotential(double k, double q, double e) {
        double e2 = e * e;
        return 0.5 * k * e2 + 0.25 * q * e2 * e2;
    }

    /** The potential of {@link #clipped} at displacement e: the integral of its elastic force from 0 to e. */
    public static double clippedPotential(double s, double c, double k, double e) {
        if (c == 0) {
            return 0.5 * s * e * e;
        }
        if (s >= k) {
            return 0.5 * k * e * e;
        }
        double b = clipPoint(s, c, k);
        double a = Math.abs(e);
        if (a <= b) {
            return 0.5 * s * a * a + 0.25 * c * a * a * a * a;
        }
        return 0.5 * s * b * b + 0.25 * c * b * b * b * b + 0.5 * k * (a * a - b * b);
    }

    /** The potential of {@link #pluck} at displacement e: the integral of its elastic force from 0 to e. */
    public static double pluckPotential(double k, double scale, double e) {
        double tip = scale / PLUCK_SHARPNESS;
        double kEnd = k / PLUCK_SHARPNESS;
        double a = Math.min(Math.abs(e), Math.max(scale, 0));
        if (a < tip) {
            return -0.5 * (k - kEnd) * a * a;
        }
        return -0.5 * (k - kEnd) * tip * tip - tip * k * (a - tip) + 0.5 * kEnd * (a * a - tip * tip);
    }

    /**
     * {@return the largest elastic slope {@code |dF/de|} that {@link #clipped} reaches: its bound k, or the cubic's
     * slope {@code s + 3 c b^2} at mi.lib's clipping point b when that is larger}
     */
    public static double clippedStiffnessBound(double s, double c, double k) {
        if (c == 0) {
            return Math.abs(s);
        }
        if (s >= k) {
            return Math.abs(k);
        }
        double b = clipPoint(s, c, k);
        return Math.max(Math.abs(k), Math.abs(s + 3 * c * b * b));
    }

    /** {@return the largest slope {@code |dF/dv|} of {@link #bow}: 2z/3 piecewise, 0.63 e^0.5 z smooth} */
    public static double bowDampingBound(double z, double type) {
        return type > 0 ? 0.63 * Math.exp(0.5) * Math.abs(z) : Math.abs(z - z / BOW_SHARPNESS);
    }
}
