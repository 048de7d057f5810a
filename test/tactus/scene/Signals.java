package tactus.scene;

import tactus.PhysicalModel;
import tactus.Vect3D;

/**
 * Small estimators for the scene tests. All of them rest on one fact about the explicit scheme: a
 * linear mode obeys the two-term recurrence y(n+1) = a y(n) - b y(n-1), whose solutions are
 * y(n) = C rho^n cos(theta n + phi) with rho^2 = b and 2 rho cos(theta) = a.
 */
final class Signals {
    private Signals() {
    }

    /** The discrete period, in steps, of an undamped mass-spring with ratio K/M: 2 pi / acos(1 - K/(2M)). */
    static double discretePeriod(double kOverM) {
        return 2 * Math.PI / Math.acos(1 - kOverM / 2);
    }

    /**
     * Least-squares estimate of cos(omega) for an undamped sinusoid: since y(n+1) + y(n-1) = 2 cos(omega) y(n)
     * holds exactly for y(n) = A cos(omega n + phi), c = sum y(n) (y(n+1) + y(n-1)) / (2 sum y(n)^2) over
     * n in [from, to).
     */
    static double cosOmega(double[] y, int from, int to) {
        double num = 0;
        double den = 0;
        for (int n = Math.max(from, 1); n < to && n + 1 < y.length; n++) {
            num += y[n] * (y[n + 1] + y[n - 1]);
            den += 2 * y[n] * y[n];
        }
        return num / den;
    }

    /** The period in steps estimated by {@link #cosOmega}. */
    static double fittedPeriod(double[] y, int from, int to) {
        return 2 * Math.PI / Math.acos(cosOmega(y, from, to));
    }

    /** Least-squares fit of y(n+1) = a y(n) - b y(n-1) over n in [from, to); returns {a, b}. */
    static double[] fitAr2(double[] y, int from, int to) {
        double s11 = 0, s12 = 0, s22 = 0, r1 = 0, r2 = 0;
        for (int n = Math.max(from, 1); n < to && n + 1 < y.length; n++) {
            double u = y[n];
            double v = -y[n - 1];
            s11 += u * u;
            s12 += u * v;
            s22 += v * v;
            r1 += u * y[n + 1];
            r2 += v * y[n + 1];
        }
        double det = s11 * s22 - s12 * s12;
        return new double[] {(r1 * s22 - r2 * s12) / det, (s11 * r2 - s12 * r1) / det};
    }

    /**
     * Period from upward zero crossings located by linear interpolation: (t_last - t_first) / (count - 1).
     * An estimator independent of the recurrence; its interpolation error is O(omega^2) steps per crossing,
     * spread over the whole record.
     */
    static double crossingPeriod(double[] y) {
        double first = Double.NaN;
        double last = Double.NaN;
        int count = 0;
        for (int n = 1; n < y.length; n++) {
            if (y[n - 1] < 0 && y[n] >= 0) {
                double t = (n - 1) + (-y[n - 1]) / (y[n] - y[n - 1]);
                if (count == 0) {
                    first = t;
                }
                last = t;
                count++;
            }
        }
        return (last - first) / (count - 1);
    }

    static double maxAbs(double[] y) {
        double m = 0;
        for (double v : y) {
            m = Math.max(m, Math.abs(v));
        }
        return m;
    }

    /**
     * Runs {@code n} single steps and records one coordinate of a mass minus {@code offset}; element 0 is the
     * state before the first step.
     */
    static double[] record(PhysicalModel pm, String mass, int axis, double offset, int n) {
        double[] y = new double[n + 1];
        Vect3D p = new Vect3D();
        for (int i = 0; i <= n; i++) {
            if (i > 0) {
                pm.computeStep();
            }
            pm.getMatPosition(mass, p);
            y[i] = (axis == 0 ? p.x : axis == 1 ? p.y : p.z) - offset;
        }
        return y;
    }

    static double relErr(double actual, double expected) {
        return Math.abs(actual - expected) / Math.abs(expected);
    }
}
