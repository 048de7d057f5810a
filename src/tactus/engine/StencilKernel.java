package tactus.engine;

/**
 * Steps one {@link StencilRun}: the spring-damper force {@code f = -K (d - l0) - Z (d(n) - d(n-1))} of the
 * link between slots i and i + o, for every i of the run, as a sequence of simple loops that index every
 * array with the same loop variable (so that JDK 17's C2 vectorises them, square roots and divisions
 * included):
 * <ol>
 *   <li>copy the positions of the far ends (slots i + o) next to slot i;</li>
 *   <li>differences, distance, scalar force over distance, force components;</li>
 *   <li>add the force to the near ends; copy it next to the far ends and subtract it there.</li>
 * </ol>
 * The distance is {@code sqrt(d^2 + 1e-300)}, so that no division by zero can occur: for coincident masses
 * it is 1e-150 and the force (a finite scalar times a zero difference) is zero. The added 1e-300 vanishes
 * in the rounding of {@code d^2} only when {@code d} exceeds about 1e-142; closer masses see a distance up to
 * 1e-150 too large. Above that the distance is exactly {@code sqrt(d^2)}, as in the index-array kernels
 * (which skip d = 0 instead).
 */
final class StencilKernel implements RangeKernel {
    private static final double TINY = 1e-300;
    /** Indices per block: about 14 arrays of this many doubles stay within a 64 KB L1 data cache. */
    private static final int BLOCK = 512;
    private final StencilRun r;
    private final StepPlan p;

    StencilKernel(StencilRun r, StepPlan p) {
        this.r = r;
        this.p = p;
    }

    @Override
    public void run() {
        run(0, r.s, r.e);
        run(1, r.s + r.o, r.e + r.o);
    }

    @Override
    public int stages() {
        return 2;
    }

    @Override
    public int start(int stage) {
        return stage == 0 ? r.s : r.s + r.o;
    }

    @Override
    public int end(int stage) {
        return stage == 0 ? r.e : r.e + r.o;
    }

    /**
     * Stage 0, over near ends i in [from, to): forces of the links (i, i + o), added to the near ends.
     * Stage 1, over far ends i in [from, to): the same forces subtracted from the far ends.
     */
    @Override
    public void run(int stage, int from, int to) {
        for (int b = from; b < to; b += BLOCK) {
            block(stage, b, Math.min(to, b + BLOCK));
        }
    }

    /** One cache-sized block of a stage: every loop over [from, to) before moving on, so the data stays in L1. */
    private void block(int stage, int from, int to) {
        final StepPlan q = p;
        final int o = r.o, n = to - from;
        if (stage == 0) {
            System.arraycopy(q.x, from + o, q.stencilVecX, from, n);
            System.arraycopy(q.y, from + o, q.stencilVecY, from, n);
            System.arraycopy(q.z, from + o, q.stencilVecZ, from, n);
            difference(q.x, q.stencilVecX, from, to);
            difference(q.y, q.stencilVecY, from, to);
            difference(q.z, q.stencilVecZ, from, to);
            distance(q.stencilVecX, q.stencilVecY, q.stencilVecZ, q.stencilDist, from, to);
            coefficient(q.stencilDist, r.k, r.z, r.l0, r.dp, from, to);
            scale(q.stencilVecX, q.stencilDist, from, to);
            scale(q.stencilVecY, q.stencilDist, from, to);
            scale(q.stencilVecZ, q.stencilDist, from, to);
            add(q.fx, q.stencilVecX, from, to);
            add(q.fy, q.stencilVecY, from, to);
            add(q.fz, q.stencilVecZ, from, to);
        } else {
            System.arraycopy(q.stencilVecX, from - o, q.stencilFarX, from, n);
            System.arraycopy(q.stencilVecY, from - o, q.stencilFarY, from, n);
            System.arraycopy(q.stencilVecZ, from - o, q.stencilFarZ, from, n);
            subtract(q.fx, q.stencilFarX, from, to);
            subtract(q.fy, q.stencilFarY, from, to);
            subtract(q.fz, q.stencilFarZ, from, to);
        }
    }

    /** far[i] = near[i] - far[i]: the coordinate difference X1 - X2. */
    private static void difference(double[] near, double[] far, int s, int e) {
        for (int i = s; i < e; i++) {
            far[i] = near[i] - far[i];
        }
    }

    private static void distance(double[] dx, double[] dy, double[] dz, double[] d, int s, int e) {
        for (int i = s; i < e; i++) {
            d[i] = Math.sqrt(dx[i] * dx[i] + dy[i] * dy[i] + dz[i] * dz[i] + TINY);
        }
    }

    /** d[i] becomes the scalar force over distance; dp[i] takes the new distance. */
    private static void coefficient(double[] d, double[] k, double[] z, double[] l0, double[] dp, int s, int e) {
        for (int i = s; i < e; i++) {
            double di = d[i];
            double f = -k[i] * (di - l0[i]) - z[i] * (di - dp[i]);
            dp[i] = di;
            d[i] = f / di;
        }
    }

    private static void scale(double[] v, double[] c, int s, int e) {
        for (int i = s; i < e; i++) {
            v[i] *= c[i];
        }
    }

    private static void add(double[] f, double[] v, int s, int e) {
        for (int i = s; i < e; i++) {
            f[i] += v[i];
        }
    }

    private static void subtract(double[] f, double[] v, int s, int e) {
        for (int i = s; i < e; i++) {
            f[i] -= v[i];
        }
    }
}
