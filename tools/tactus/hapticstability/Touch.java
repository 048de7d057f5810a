package tactus.hapticstability;

/**
 * What one run shows: for a two-sided spring (no hand), the growth of the oscillation about the equilibrium; for
 * a one-sided wall pressed by a hand, the peak and residual oscillation, the energy the device gave the hand over
 * the touch and the stiffness the hand felt. All from a {@link WallRig.Trace}.
 */
public final class Touch {
    /** True if the run counts as stable. */
    public final boolean stable;
    /** Peak oscillation about the local mean (20 ms moving average) after the touch, metres. */
    public final double peak;
    /** RMS oscillation over the last third of the run about its mean (SPRING), or about the 20 ms moving average during the hold (PLANE), metres. */
    public final double residual;
    /** Energy the device delivered to the hand over the touch, J (&lt;= 0: passive); NaN without a hand. */
    public final double energyToHand;
    /** Slope of the hand's force against penetration while pressing in, as a fraction of K; NaN without a hand. */
    public final double feltFraction;
    /** Oscillation RMS over the last third over the first third's (SPRING; 0 if the handle never moved); NaN for PLANE. */
    public final double growth;

    private Touch(boolean stable, double peak, double residual, double energyToHand, double feltFraction, double growth) {
        this.stable = stable;
        this.peak = peak;
        this.residual = residual;
        this.energyToHand = energyToHand;
        this.feltFraction = feltFraction;
        this.growth = growth;
    }

    /** Oscillation threshold for a pressed wall: residual RMS above this (metres) counts as unstable. */
    public static final double RESIDUAL_LIMIT = 5e-6;

    /**
     * Reads a two-sided spring run: e = y - y_eq, and its oscillation about each window's mean; unstable if the
     * oscillation's RMS over the last third exceeds the first third's, or if |e| ever exceeds 4 times the initial
     * step. A handle that friction holds (no oscillation at all) is stable.
     */
    public static Touch ofSpring(WallRig.Config c, WallRig.Trace t) {
        double eq = WallRig.wallY(c);
        int n = t.n;
        int third = n / 3;
        double peak = 0;
        for (int i = 0; i < n; i++) {
            peak = Math.max(peak, Math.abs(t.y[i] - eq));
        }
        double a1 = acRms(t.y, 0, third);
        double a3 = acRms(t.y, n - third, n);
        double growth = a1 < 1e-9 ? 0 : a3 / a1;
        boolean stable = t.failure == null && growth < 1 && peak < 4 * c.offset;
        return new Touch(stable, peak, a3, Double.NaN, Double.NaN, growth);
    }

    private static double acRms(double[] v, int from, int to) {
        double mean = 0;
        for (int i = from; i < to; i++) {
            mean += v[i];
        }
        mean /= to - from;
        double s = 0;
        for (int i = from; i < to; i++) {
            s += (v[i] - mean) * (v[i] - mean);
        }
        return Math.sqrt(s / (to - from));
    }

    /**
     * Reads a pressed one-sided wall: the hand presses in until pressEnd, holds from holdFrom to holdTo (seconds); the
     * touch is every sample from 50 ms before the first penetration to the end of the run.
     */
    public static Touch ofPress(WallRig.Config c, WallRig.Trace t, double pressEnd, double holdFrom, double holdTo) {
        double wall = WallRig.wallY(c);
        int n = t.n;
        int w = Math.max(1, (int) Math.round(0.02 / (t.t[1] - t.t[0])));
        // moving average over w samples (prefix sums)
        double[] pre = new double[n + 1];
        for (int i = 0; i < n; i++) {
            pre[i + 1] = pre[i] + t.y[i];
        }
        int firstIn = -1;
        for (int i = 0; i < n; i++) {
            if (t.y[i] < wall) {
                firstIn = i;
                break;
            }
        }
        double peak = 0;
        double sr = 0;
        int nr = 0;
        double energy = 0;
        int from = firstIn < 0 ? n : Math.max(1, firstIn - (int) Math.round(0.05 / (t.t[1] - t.t[0])));
        for (int i = from; i < n; i++) {
            energy += -(t.fx[i] * t.vx[i] + t.fy[i] * t.vy[i]) * (t.t[i] - t.t[i - 1]);
        }
        for (int i = Math.max(0, firstIn); firstIn >= 0 && i < n; i++) {
            int lo = Math.max(0, i - w / 2);
            int hi = Math.min(n, i + w / 2 + 1);
            double e = t.y[i] - (pre[hi] - pre[lo]) / (hi - lo);
            if (t.t[i] <= holdTo) {
                peak = Math.max(peak, Math.abs(e));
            }
            if (t.t[i] >= holdFrom && t.t[i] <= holdTo) {
                sr += e * e;
                nr++;
            }
        }
        double residual = nr > 0 ? Math.sqrt(sr / nr) : 0;
        // felt stiffness: the slope of the hand's push against the penetration while it presses in slowly (a
        // least-squares line, so that a constant sliding friction and the hand's damping at a steady speed drop out),
        // from the first contact to the end of the press
        double felt = pressSlope(t.t, t.y, t.fy, n, firstIn, wall, pressEnd) / c.stiffness;
        boolean stable = t.failure == null && residual < RESIDUAL_LIMIT;
        return new Touch(stable, peak, residual, energy, felt, Double.NaN);
    }

    /**
     * The least-squares slope (N/m) of the hand's push (-fy) against the penetration below the wall (wall - y, m), over
     * the samples from firstIn (-1: none) while the time is before pressEnd and the handle is inside; NaN with 10
     * samples or fewer.
     */
    static double pressSlope(double[] time, double[] y, double[] fy, int n, int firstIn, double wall, double pressEnd) {
        double sp = 0;
        double sf = 0;
        double spp = 0;
        double spf = 0;
        int np = 0;
        for (int i = Math.max(0, firstIn); firstIn >= 0 && i < n && time[i] < pressEnd; i++) {
            double pen = wall - y[i];
            if (pen > 0) {
                double f = -fy[i];
                sp += pen;
                sf += f;
                spp += pen * pen;
                spf += pen * f;
                np++;
            }
        }
        double den = np * spp - sp * sp;
        return np > 10 && den > 0 ? (np * spf - sp * sf) / den : Double.NaN;
    }
}
