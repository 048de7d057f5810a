package tactus.engine;

/**
 * Watches a running plan for divergence and keeps it free of subnormal numbers.
 *
 * <p>Every {@link #interval()} steps it scans all positions once: a non-finite coordinate, or one whose
 * magnitude exceeds {@link #limit()}, is a divergence, detected at most {@code interval} steps after it
 * appears. The same scan protects decaying models from subnormal numbers, where arithmetic is tens of
 * times slower: when every current and previous coordinate of an axis is closer to zero than
 * {@link #FLUSH} (1e-150), that whole axis is set to exactly zero (a string vibrating around y = 0 comes to
 * rest exactly instead of creeping through the subnormal range; squares and products of numbers above
 * 1e-150 stay normal). On an axis that other parts of the model keep busy, each mass that has decayed
 * below the threshold is set to rest at zero instead. The scan costs one pass over the positions per
 * interval, so about {@code 1/interval} of a mass update per step.
 */
public final class DivergenceGuard {
    /** Coordinates with a magnitude below this are set to exactly zero. */
    public static final double FLUSH = 1e-150;

    private int interval = 64;
    private double limit = 1e12;

    /** @return the number of steps between two scans. */
    public int interval() {
        return interval;
    }

    /** Sets the number of steps between two scans (&ge; 1). */
    public void setInterval(int steps) {
        if (steps < 1) {
            throw new IllegalArgumentException("divergence check interval must be >= 1 step, got " + steps);
        }
        interval = steps;
    }

    /** @return the largest coordinate magnitude accepted as sane. */
    public double limit() {
        return limit;
    }

    /** Sets the largest coordinate magnitude accepted as sane (finite, &gt; 0). */
    public void setLimit(double limit) {
        if (!(limit > 0) || !Double.isFinite(limit)) {
            throw new IllegalArgumentException("divergence limit must be a finite number > 0, got " + limit);
        }
        this.limit = limit;
    }

    /**
     * Scans a plan: flushes axes that have decayed to nothing, and finds a diverged mass.
     *
     * @return the slot of the diverged mass with the lowest id (non-finite first, else the largest
     *     magnitude beyond the limit), or -1 when the state is sane
     */
    int scan(StepPlan p) {
        double wx = axis(p.x, p.px, p.fx, p, false);
        double wy = axis(p.y, p.py, p.fy, p, false);
        double wz = axis(p.z, p.pz, p.fz, p, true);
        double worst = Math.max(wx, Math.max(wy, wz));
        if (worst <= limit) {
            return -1;
        }
        return culprit(p);
    }

    /**
     * @return the largest magnitude of an axis's coordinates (NaN if any is NaN; a non-finite previous position
     *     shows up in the current one a step later). Tiny coordinates are flushed: when every current and
     *     previous coordinate of the axis is below {@link #FLUSH}, the whole axis (positions, previous
     *     positions, forces) is set to exactly zero, which removes the residual motion without adding energy;
     *     when other masses keep the axis busy, each mass whose current and previous coordinates are both below
     *     {@link #FLUSH} is set to rest at zero on that axis (a change of at most 1e-150, far below the
     *     round-off of the busy part's energy).
     */
    private static double axis(double[] x, double[] px, double[] f, StepPlan p, boolean isZ) {
        int n = p.nMass;
        double m = 0;
        boolean tiny = false;
        for (int i = 0; i < n; i++) {
            double a = Math.abs(x[i]);
            m = Math.max(m, a);
            tiny |= a < FLUSH & a > 0;
        }
        if (!tiny) {
            return m;
        }
        if (m < FLUSH && largest(px, n) < FLUSH) {
            java.util.Arrays.fill(x, 0, n, 0.0);
            java.util.Arrays.fill(px, 0, n, 0.0);
            java.util.Arrays.fill(f, 0, n, 0.0);
            LinkBatch oneD = p.batch(LinkKind.SPRING_DAMPER1D);
            if (isZ && oneD != null) {
                java.util.Arrays.fill(oneD.dp, 0, oneD.n, 0.0);
            }
        } else {
            for (int i = 0; i < n; i++) {
                if (Math.abs(x[i]) < FLUSH && Math.abs(px[i]) < FLUSH) {
                    x[i] = 0;
                    px[i] = 0;
                    f[i] = 0;
                }
            }
            LinkBatch oneD = p.batch(LinkKind.SPRING_DAMPER1D);
            if (isZ && oneD != null) {
                // a 1D link whose two ends now rest at zero must not remember a tiny previous length
                for (int j = 0; j < oneD.n; j++) {
                    int a = oneD.a[j], b = oneD.b[j];
                    if (x[a] == 0 && x[b] == 0 && px[a] == 0 && px[b] == 0) {
                        oneD.dp[j] = 0;
                    }
                }
            }
        }
        return m;
    }

    /** @return the largest magnitude among the first n values, or NaN if one of them is NaN. */
    private static double largest(double[] v, int n) {
        double m = 0;
        for (int i = 0; i < n; i++) {
            m = Math.max(m, Math.abs(v[i]));
        }
        return m;
    }

    private int culprit(StepPlan p) {
        int nonFinite = -1;
        int beyond = -1;
        double beyondMag = 0;
        for (int s = 0; s < p.nMass; s++) {
            double m = Math.max(Math.abs(p.x[s]), Math.max(Math.abs(p.y[s]), Math.abs(p.z[s])));
            double q = Math.max(Math.abs(p.px[s]), Math.max(Math.abs(p.py[s]), Math.abs(p.pz[s])));
            m = Math.max(m, q);
            if (Double.isNaN(m) || Double.isInfinite(m)) {
                if (nonFinite < 0 || p.massId[s] < p.massId[nonFinite]) {
                    nonFinite = s;
                }
            } else if (m > limit && m > beyondMag) {
                beyondMag = m;
                beyond = s;
            }
        }
        return nonFinite >= 0 ? nonFinite : beyond;
    }
}
