package tactus.engine;

/**
 * Watches a running plan for divergence and keeps it free of subnormal numbers.
 *
 * <p>Every {@link #interval()} steps it scans all positions once: a non-finite coordinate, or one whose
 * magnitude exceeds {@link #limit()}, is a divergence, detected at most {@code interval} steps after it
 * appears. The same scan protects decaying models from subnormal numbers, where arithmetic is tens of
 * times slower: on an axis where some coordinate has decayed below {@link #FLUSH} (1e-150), every mass
 * whose current and previous coordinates are that tiny is set to rest at exactly zero, with the negligible
 * force it carries (a string vibrating around y = 0 comes to rest exactly instead of creeping through the
 * subnormal range; squares and products of numbers above 1e-150 stay normal). Masses that are zero or larger are left alone, and no real
 * force is lost. {@link #flushedValues()} counts the values flushed, so that a model placed below the
 * engine's resolution can be diagnosed. The scan costs one pass over the positions per interval, so about
 * {@code 1/interval} of a mass update per step.
 */
public final class DivergenceGuard {
    /** Coordinates with a magnitude below this are set to exactly zero. */
    public static final double FLUSH = 1e-150;
    /**
     * The force on a mass that the scan sets to rest at zero, and every force on an axis whose every current
     * and previous coordinate is below {@link #FLUSH}, is set to zero when its magnitude is below this
     * (per-step units): such forces were computed from the flushed positions (a stiffness times a tiny
     * distance), and keeping them would re-excite the axis at about 1e-149 for ever. Larger forces are real
     * (a haptic push, a plane contact) and are kept. A force of this size moves nothing measurable.
     */
    public static final double FORCE_FLUSH = 1e-100;

    private int interval = 64;
    private double limit = 1e12;
    private long flushed;

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
     *     shows up in the current one a step later). When some current coordinate of the axis is tiny (non-zero
     *     and below {@link #FLUSH}), every mass whose current and previous coordinates are both below
     *     {@link #FLUSH}, one of them non-zero, is set to rest at zero on that axis (both together, so that the
     *     flush creates no velocity), and its force is set to zero if it is below {@link #FORCE_FLUSH}; when
     *     the whole axis is below {@link #FLUSH}, every force below {@link #FORCE_FLUSH} is set to zero; and a
     *     SpringDamper1D link on z whose two ends now rest at zero forgets its previous length. A mass that
     *     is not tiny (in particular one at exactly zero, such as a haptic avatar at the origin) keeps its
     *     state and forces on a busy axis, and a real force is never removed, whatever the other masses on the
     *     axis do. (Forces on masses that are not flushed are left alone even when small: removing them would
     *     feed round-off noise of about 1e-149 into the decaying motion faster than damping removes it.)
     */
    private double axis(double[] x, double[] px, double[] f, StepPlan p, boolean isZ) {
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
        boolean wholeAxis = m < FLUSH && largest(px, n) < FLUSH;
        for (int i = 0; i < n; i++) {
            double a = Math.abs(x[i]), b = Math.abs(px[i]);
            boolean rest = a < FLUSH && b < FLUSH && (a > 0 || b > 0);
            if (rest) {
                x[i] = 0;
                px[i] = 0;
                flushed++;
            }
            double c = Math.abs(f[i]);
            if ((rest || wholeAxis) && c < FORCE_FLUSH && c > 0) {
                f[i] = 0;
                flushed++;
            }
        }
        if (isZ) {
            // a 1D link whose two ends now rest at zero must not remember a previous length (a phantom velocity)
            for (LinkBatch oneD : p.batches) {
                if (oneD == null || !oneD.kind.isOneDimensional() || !oneD.kind.keepsHistory()) {
                    continue;
                }
                for (int j = 0; j < oneD.n; j++) {
                    int a = oneD.a[j], b = oneD.b[j];
                    if (oneD.dp[j] != 0 && x[a] == 0 && x[b] == 0 && px[a] == 0 && px[b] == 0) {
                        oneD.dp[j] = 0;
                        flushed++;
                    }
                }
            }
        }
        return m;
    }

    /**
     * @return how many non-zero values (coordinates, forces, previous lengths) the scans have set to zero
     *     because they were below {@link #FLUSH}: a diagnostic for a model that lives below the engine's
     *     resolution of 1e-150 instead of decaying into it
     */
    public long flushedValues() {
        return flushed;
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
