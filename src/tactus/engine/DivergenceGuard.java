package tactus.engine;

/**
 * Watches a running plan for divergence and keeps it free of subnormal numbers.
 *
 * <p>Every {@link #interval()} steps it scans all positions once: a non-finite coordinate, or one whose
 * magnitude exceeds {@link #limit()}, is a divergence, detected at most {@code interval} steps after it
 * appears. The same scan flushes to zero every coordinate closer to zero than {@link #FLUSH} (1e-150):
 * a decaying model then never reaches the subnormal range, where arithmetic is tens of times slower
 * (differences and squares of such small normal numbers stay normal). The scan costs one pass over the
 * positions per interval, so about {@code 1/interval} of a mass update per step.
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
     * Scans a plan: flushes tiny coordinates, and finds a diverged mass.
     *
     * @return the slot of the diverged mass with the lowest id (non-finite first, else the largest
     *     magnitude beyond the limit), or -1 when the state is sane
     */
    int scan(StepPlan p) {
        double worst = 0;
        worst = Math.max(worst, flush(p.x, p.nMass));
        worst = Math.max(worst, flush(p.y, p.nMass));
        worst = Math.max(worst, flush(p.z, p.nMass));
        worst = Math.max(worst, flush(p.px, p.nMass));
        worst = Math.max(worst, flush(p.py, p.nMass));
        worst = Math.max(worst, flush(p.pz, p.nMass));
        LinkBatch oneD = p.batch(LinkKind.SPRING_DAMPER1D);
        if (oneD != null) {
            flush(oneD.dp, oneD.n);
        }
        if (worst <= limit) {
            return -1;
        }
        return culprit(p);
    }

    /** @return the largest magnitude in the first n values (NaN if any is NaN), after flushing tiny ones. */
    private static double flush(double[] v, int n) {
        double m = 0;
        for (int i = 0; i < n; i++) {
            double a = Math.abs(v[i]);
            if (a < FLUSH) {
                v[i] = 0;
            }
            m = Math.max(m, a);
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
