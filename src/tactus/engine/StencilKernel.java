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
 * The distance is {@code sqrt(d^2 + 1e-300)}: for coincident masses this gives a tiny positive distance and
 * a zero force instead of a division by zero, and for any other distance it is exactly {@code sqrt(d^2)}.
 */
final class StencilKernel implements Kernel {
    private static final double TINY = 1e-300;
    private final StencilRun r;
    private final StepPlan p;

    StencilKernel(StencilRun r, StepPlan p) {
        this.r = r;
        this.p = p;
    }

    @Override
    public void run() {
        final int s = r.s, e = r.e, o = r.o, n = e - s;
        final StepPlan q = p;
        System.arraycopy(q.x, s + o, q.sbx, s, n);
        System.arraycopy(q.y, s + o, q.sby, s, n);
        System.arraycopy(q.z, s + o, q.sbz, s, n);
        difference(q.x, q.sbx, s, e);
        difference(q.y, q.sby, s, e);
        difference(q.z, q.sbz, s, e);
        distance(q.sbx, q.sby, q.sbz, q.sdd, s, e);
        coefficient(q.sdd, r.k, r.z, r.l0, r.dp, s, e);
        scale(q.sbx, q.sdd, s, e);
        scale(q.sby, q.sdd, s, e);
        scale(q.sbz, q.sdd, s, e);
        add(q.fx, q.sbx, s, e);
        add(q.fy, q.sby, s, e);
        add(q.fz, q.sbz, s, e);
        System.arraycopy(q.sbx, s, q.stx, s + o, n);
        System.arraycopy(q.sby, s, q.sty, s + o, n);
        System.arraycopy(q.sbz, s, q.stz, s + o, n);
        subtract(q.fx, q.stx, s + o, e + o);
        subtract(q.fy, q.sty, s + o, e + o);
        subtract(q.fz, q.stz, s + o, e + o);
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
