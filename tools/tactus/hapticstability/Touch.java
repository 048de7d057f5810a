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
    /** RMS oscillation about the local mean over the last 30 % of the run (SPRING) or of the hold (PLANE), metres. */
    public final double residual;
    /** Energy the device delivered to the hand over the touch, J (<= 0: passive); NaN without a hand. */
    public final double energyToHand;
    /** Force over penetration during the hold, as a fraction of K; NaN without a hand. */
    public final double feltFraction;
    /** RMS of the deviation over the last third over the first third (SPRING); NaN for PLANE. */
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
    public static final double RESIDUAL_LIMIT = 2e-5;

    /**
     * Reads a two-sided spring run: the deviation e = y - y_eq; unstable if its RMS over the last third exceeds the
     * first third's, or if |e| ever exceeds 4 times the initial step.
     */
    public static Touch ofSpring(WallRig.Config c, WallRig.Trace t) {
        double eq = WallRig.wallY(c);
        int n = t.n;
        int third = n / 3;
        double s1 = 0;
        double s3 = 0;
        double peak = 0;
        for (int i = 0; i < n; i++) {
            double e = t.y[i] - eq;
            peak = Math.max(peak, Math.abs(e));
            if (i < third) {
                s1 += e * e;
            } else if (i >= n - third) {
                s3 += e * e;
            }
        }
        double growth = Math.sqrt(s3 / s1);
        boolean stable = t.failure == null && growth < 1 && peak < 4 * c.offset;
        double residual = Math.sqrt(s3 / third);
        return new Touch(stable, peak, residual, Double.NaN, Double.NaN, growth);
    }

    /**
     * Reads a pressed one-sided wall: the hold window is given in seconds; the touch is every sample from 50 ms before
     * the first penetration to the end of the run.
     */
    public static Touch ofPress(WallRig.Config c, WallRig.Trace t, double holdFrom, double holdTo) {
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
        double fSum = 0;
        double penSum = 0;
        int nh = 0;
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
                fSum += -t.fy[i];
                penSum += wall - t.y[i];
                nh++;
            }
        }
        double residual = nr > 0 ? Math.sqrt(sr / nr) : 0;
        double felt = penSum > 0 ? (fSum / penSum) / c.stiffness : Double.NaN;
        boolean stable = t.failure == null && residual < RESIDUAL_LIMIT;
        return new Touch(stable, peak, residual, energy, felt, Double.NaN);
    }
}
