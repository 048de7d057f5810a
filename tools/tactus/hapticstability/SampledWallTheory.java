package tactus.hapticstability;

/**
 * The stability boundary of a virtual wall rendered by a sampled-data haptic loop, from the z-domain model: a
 * device of mass m (kg) and viscous damping b (N s/m), a zero-order hold of period T (s), d ticks of delay between
 * the position sample and the force it produces, and a wall of stiffness K (N/m) and damping B (N s/m, velocity by
 * backward difference over one tick). Device alone (no hand).
 *
 * <p>The hold-equivalent of 1 / (m s^2 + b s) is g (c1 z + c0) / ((z - 1)(z - p)) with delta = b T / m,
 * p = e^-delta, g = m / b^2, c1 = delta + p - 1, c0 = 1 - p - delta p; the wall is
 * C(z) = ((K + B/T) z - B/T) / z; the closed loop's characteristic polynomial is
 * z^(d+1) (z - 1)(z - p) + g (c1 z + c0) ((K + B/T) z - B/T). It is tested with the Schur-Cohn (Jury) recursion,
 * and the largest stable K found by bisection.
 */
public final class SampledWallTheory {
    private SampledWallTheory() {
    }

    /** The characteristic polynomial's coefficients, lowest power first. */
    public static double[] characteristic(double m, double b, double T, int d, double K, double B) {
        double delta = b * T / m;
        double p = Math.exp(-delta);
        double g = m / (b * b);
        double c1 = delta + p - 1;
        double c0 = (1 - p) - delta * p;
        // (z - 1)(z - p) = z^2 - (1 + p) z + p, times z^(d+1)
        double[] poly = new double[d + 4];
        poly[d + 1] = p;
        poly[d + 2] = -(1 + p);
        poly[d + 3] = 1;
        // + g (c1 z + c0)(k1 z - k0)
        double k1 = K + B / T;
        double k0 = B / T;
        poly[2] += g * c1 * k1;
        poly[1] += g * (c0 * k1 - c1 * k0);
        poly[0] += -g * c0 * k0;
        return poly;
    }

    /** True if every root of the polynomial (coefficients lowest power first) lies strictly inside the unit circle. */
    public static boolean isSchurStable(double[] coefficients) {
        int n = coefficients.length - 1;
        double[] a = coefficients.clone();
        while (n > 0) {
            double an = a[n];
            double a0 = a[0];
            if (!(Math.abs(a0) < Math.abs(an))) {
                return false;
            }
            double[] next = new double[n];
            for (int i = 1; i <= n; i++) {
                next[i - 1] = an * a[i] - a0 * a[n - i];
            }
            // rescale to keep the numbers in range
            double s = 0;
            for (double v : next) {
                s = Math.max(s, Math.abs(v));
            }
            for (int i = 0; i < n; i++) {
                next[i] /= s;
            }
            a = next;
            n--;
        }
        return true;
    }

    /** True if the loop with these parameters is asymptotically stable. */
    public static boolean isStable(double m, double b, double T, int d, double K, double B) {
        return isSchurStable(characteristic(m, b, T, d, K, B));
    }

    /**
     * The largest wall stiffness (N/m) for which the loop is stable, by bisection to a relative 1e-9; NaN if even
     * a vanishing stiffness is unstable (B too large for the delay).
     */
    public static double stiffnessLimit(double m, double b, double T, int d, double B) {
        double lo = 1e-9 * b / T;
        if (!isStable(m, b, T, d, lo, B)) {
            return Double.NaN;
        }
        double hi = b / T;
        while (isStable(m, b, T, d, hi, B)) {
            lo = hi;
            hi *= 2;
            if (hi > 1e12) {
                return Double.POSITIVE_INFINITY;
            }
        }
        while (hi - lo > 1e-9 * hi) {
            double mid = 0.5 * (lo + hi);
            if (isStable(m, b, T, d, mid, B)) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        return lo;
    }

    /**
     * The exact limit with no delay and B = 0: K = (b / T) delta (1 - e^-delta) / (1 - e^-delta - delta e^-delta),
     * delta = b T / m, which tends to 2 b / T as delta goes to 0 (it is 2 b / T (1 + delta / 6 + O(delta^2))).
     */
    public static double exactLimitNoDelay(double m, double b, double T) {
        double delta = b * T / m;
        double p = Math.exp(-delta);
        return b / T * delta * (1 - p) / (1 - p - delta * p);
    }

    /** The passivity bound b > K T (d + 1/2) + |B| solved for K (N/m); negative when |B| >= b. */
    public static double passivityLimit(double b, double T, int d, double B) {
        return (b - Math.abs(B)) / (T * (d + 0.5));
    }
}
