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
 *
 * <p><b>One sweep.</b> Run on one thread ({@link #run()}), the kernel walks the run once, in cache-sized
 * blocks: each block's forces are computed and then added to every slot of the block at once,
 * {@code F(i) = (F(i) + f(i)) - f(i - o)} (near end first, then far end: the same two operations, in the same
 * order, as the two stages run one after the other). A kernel made {@linkplain #fused fused} also moves the
 * masses of its slots, block by block just ahead of the links that need them, so that a chain's positions
 * and forces are loaded into the L1 cache once per step instead of once by the mass kernel and again by
 * the links (the mass kernel of that kind then leaves those slots out). For several threads the same work
 * is cut into stages ({@link RangeKernel}); both ways compute every value with the same operations in the
 * same order, so they agree bit for bit.
 */
final class StencilKernel implements RangeKernel {
    private static final double TINY = 1e-300;
    /**
     * Indices per block of a sweep: the arrays one block touches (positions, forces, the run's parameters, the
     * scratch arrays and, when fused, the masses' coefficients: about 20 of this many doubles) stay within a
     * 48 KB L1 data cache. Measured on a 5,000-mass string: 256 is about 10% faster than 512 or 128.
     */
    private static final int SWEEP_BLOCK = 256;
    /** Indices per block of a stage (several threads, or the two-pass form). */
    private static final int STAGE_BLOCK = 512;
    private final StencilRun r;
    private final StepPlan p;
    /** The masses of slots [r.s, r.e + r.o), moved by this kernel; null when their own kernel moves them. */
    private final MassKernels.SlotKernel masses;
    /** true: {@link #run()} makes one sweep; false: it runs the stages one after the other (the two-pass form). */
    private final boolean sweep;

    private StencilKernel(StencilRun r, StepPlan p, MassKernels.SlotKernel masses, boolean sweep) {
        this.r = r;
        this.p = p;
        this.masses = masses;
        this.sweep = sweep;
    }

    /** A kernel for the links of a run only, stepped in one sweep. */
    static StencilKernel sweep(StencilRun r, StepPlan p) {
        return new StencilKernel(r, p, null, true);
    }

    /** A kernel for the links of a run only, stepped in two passes (near ends, then far ends), as before sweeps. */
    static StencilKernel twoPass(StencilRun r, StepPlan p) {
        return new StencilKernel(r, p, null, false);
    }

    /**
     * A kernel that also moves the masses of every slot its links touch, [r.s, r.e + r.o), with the given
     * mass kernel (which must handle those slots), stepped in one sweep. It must run after every other mass
     * kernel and before every other interaction kernel.
     */
    static StencilKernel fused(StencilRun r, StepPlan p, MassKernels.SlotKernel masses) {
        return new StencilKernel(r, p, masses, true);
    }

    /** @return the mass kernel this kernel runs for its slots, or null. */
    MassKernels.SlotKernel masses() {
        return masses;
    }

    @Override
    public void run() {
        if (!sweep) {
            for (int stage = 0; stage < stages(); stage++) {
                run(stage, start(stage), end(stage));
            }
            return;
        }
        final StepPlan q = p;
        final int s = r.s, e = r.e, o = r.o;
        int moved = s;
        for (int b = s; b < e; b += SWEEP_BLOCK) {
            int to = Math.min(e, b + SWEEP_BLOCK);
            if (masses != null) {
                masses.step(moved, to + o);
                moved = to + o;
            }
            near(b, to);
            int far = Math.max(b, s + o);
            add(q.fx, q.stencilVecX, b, Math.min(to, far));
            add(q.fy, q.stencilVecY, b, Math.min(to, far));
            add(q.fz, q.stencilVecZ, b, Math.min(to, far));
            if (far < to) {
                int n = to - far;
                System.arraycopy(q.stencilVecX, far - o, q.stencilFarX, far, n);
                System.arraycopy(q.stencilVecY, far - o, q.stencilFarY, far, n);
                System.arraycopy(q.stencilVecZ, far - o, q.stencilFarZ, far, n);
                addSubtract(q.fx, q.stencilVecX, q.stencilFarX, far, to);
                addSubtract(q.fy, q.stencilVecY, q.stencilFarY, far, to);
                addSubtract(q.fz, q.stencilVecZ, q.stencilFarZ, far, to);
            }
        }
        // slots past the near ends receive only the far-end force
        farEnds(Math.max(e, s + o), e + o);
    }

    @Override
    public int stages() {
        return masses != null ? 3 : 2;
    }

    @Override
    public int start(int stage) {
        int st = masses != null ? stage : stage + 1;
        return st == 0 ? r.s : st == 1 ? r.s : r.s + r.o;
    }

    @Override
    public int end(int stage) {
        int st = masses != null ? stage : stage + 1;
        return st == 0 ? r.e + r.o : st == 1 ? r.e : r.e + r.o;
    }

    /**
     * With masses: stage 0 moves the masses of slots [from, to). Then (stages 0 and 1 without masses): over
     * near ends i in [from, to), the forces of the links (i, i + o), added to the near ends; over far ends i
     * in [from, to), the same forces subtracted from the far ends.
     */
    @Override
    public void run(int stage, int from, int to) {
        int st = masses != null ? stage : stage + 1;
        if (st == 0) {
            masses.step(from, to);
            return;
        }
        for (int b = from; b < to; b += STAGE_BLOCK) {
            int bt = Math.min(to, b + STAGE_BLOCK);
            if (st == 1) {
                near(b, bt);
                add(p.fx, p.stencilVecX, b, bt);
                add(p.fy, p.stencilVecY, b, bt);
                add(p.fz, p.stencilVecZ, b, bt);
            } else {
                farEnds(b, bt);
            }
        }
    }

    /** The forces of the links whose near ends are [from, to), left in the stencilVec arrays. */
    private void near(int from, int to) {
        final StepPlan q = p;
        final int o = r.o, n = to - from;
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
    }

    /** Subtracts from the far ends [from, to) the forces of their links (computed before, by {@link #near}). */
    private void farEnds(int from, int to) {
        final StepPlan q = p;
        final int o = r.o;
        for (int b = from; b < to; b += STAGE_BLOCK) {
            int bt = Math.min(to, b + STAGE_BLOCK);
            int n = bt - b;
            System.arraycopy(q.stencilVecX, b - o, q.stencilFarX, b, n);
            System.arraycopy(q.stencilVecY, b - o, q.stencilFarY, b, n);
            System.arraycopy(q.stencilVecZ, b - o, q.stencilFarZ, b, n);
            subtract(q.fx, q.stencilFarX, b, bt);
            subtract(q.fy, q.stencilFarY, b, bt);
            subtract(q.fz, q.stencilFarZ, b, bt);
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

    /**
     * d[i] becomes the scalar force over distance; dp[i] takes the new distance. (A separate loop from the
     * square roots: on JDK 17 one loop with both the square root and the division runs about a third slower.)
     */
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

    /** f[i] = (f[i] + near[i]) - far[i]: a slot that is the near end of one link and the far end of another. */
    private static void addSubtract(double[] f, double[] near, double[] far, int s, int e) {
        for (int i = s; i < e; i++) {
            f[i] = (f[i] + near[i]) - far[i];
        }
    }
}
