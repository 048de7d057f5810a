package tactus.engine;

/**
 * The interaction-phase kernels. Each one reads the positions just computed by the mass phase
 * and adds equal and opposite forces into the two masses' force buffers. With
 * {@code d = |X1 - X2|} and {@code u = (X1 - X2)/d}, a link with scalar force {@code f}
 * adds {@code f u} to mass 1 and {@code -f u} to mass 2, so a negative {@code f} attracts.
 * Damping uses the link's own previous distance: {@code v = d(n) - d(n-1)}.
 * Coincident masses ({@code d = 0}) exchange no force, so no NaN can appear: a contact between them stays
 * inert until they separate, and a pair crossing exactly d = 0 passes through (the facade warns when a
 * Contact3D is added between coincident masses).
 */
final class LinkKernels {
    private LinkKernels() {
    }

    /** @return the kernel that steps one batch: the one its kind's descriptor names. */
    static Kernel create(LinkBatch b, StepPlan p) {
        return b.kind.kernel(b, p);
    }

    /** A kernel over the links of one batch. */
    abstract static class BatchKernel implements Kernel {
        final LinkBatch b;
        final StepPlan p;

        BatchKernel(LinkBatch b, StepPlan p) {
            this.b = b;
            this.p = p;
        }
    }

    /** Spring3D: f = -K (d - l0). */
    static final class Spring extends BatchKernel {
        Spring(LinkBatch b, StepPlan p) {
            super(b, p);
        }

        @Override
        public void run() {
            final double[] x = p.x, y = p.y, z = p.z, fx = p.fx, fy = p.fy, fz = p.fz;
            final int[] ia = b.a, ib = b.b;
            final double[] k = b.k, l0 = b.len;
            for (int j = 0, n = b.nIrregular; j < n; j++) {
                int a = ia[j], c = ib[j];
                double dx = x[a] - x[c], dy = y[a] - y[c], dz = z[a] - z[c];
                double d = Math.sqrt(dx * dx + dy * dy + dz * dz);
                double s = d > 0 ? -k[j] * (d - l0[j]) / d : 0.0;
                push(fx, fy, fz, a, c, s, dx, dy, dz);
            }
        }
    }

    /** Damper3D: f = -Z (d(n) - d(n-1)). */
    static final class Damper extends BatchKernel {
        Damper(LinkBatch b, StepPlan p) {
            super(b, p);
        }

        @Override
        public void run() {
            final double[] x = p.x, y = p.y, z = p.z, fx = p.fx, fy = p.fy, fz = p.fz;
            final int[] ia = b.a, ib = b.b;
            final double[] zz = b.z, dp = b.dp;
            for (int j = 0, n = b.nIrregular; j < n; j++) {
                int a = ia[j], c = ib[j];
                double dx = x[a] - x[c], dy = y[a] - y[c], dz = z[a] - z[c];
                double d = Math.sqrt(dx * dx + dy * dy + dz * dz);
                double s = d > 0 ? -zz[j] * (d - dp[j]) / d : 0.0;
                dp[j] = d;
                push(fx, fy, fz, a, c, s, dx, dy, dz);
            }
        }
    }

    /** SpringDamper3D: f = -K (d - l0) - Z (d(n) - d(n-1)). */
    static final class SpringDamper extends BatchKernel {
        SpringDamper(LinkBatch b, StepPlan p) {
            super(b, p);
        }

        @Override
        public void run() {
            final double[] x = p.x, y = p.y, z = p.z, fx = p.fx, fy = p.fy, fz = p.fz;
            final int[] ia = b.a, ib = b.b;
            final double[] k = b.k, zz = b.z, l0 = b.len, dp = b.dp;
            for (int j = 0, n = b.nIrregular; j < n; j++) {
                int a = ia[j], c = ib[j];
                double dx = x[a] - x[c], dy = y[a] - y[c], dz = z[a] - z[c];
                double d = Math.sqrt(dx * dx + dy * dy + dz * dz);
                double f = -k[j] * (d - l0[j]) - zz[j] * (d - dp[j]);
                dp[j] = d;
                double s = d > 0 ? f / d : 0.0;
                push(fx, fy, fz, a, c, s, dx, dy, dz);
            }
        }
    }

    /**
     * SpringDamper1D: on the signed difference {@code e = z1 - z2},
     * {@code F = K (e - l0) + Z (e(n) - e(n-1))}; mass 1 receives -F and mass 2 receives +F along z.
     *
     * <p>The links are taken in batch order. A stretch of at least {@link #MIN_SEGMENT} consecutive links that
     * join slots {@code s + i} and {@code s + i + 1} (a 1-D string built in order, the rows of a plate) runs as
     * a <em>segment</em>: one loop that carries the previous link's force and the far end's position in
     * registers and writes each mass's force once, {@code F(t) = (F(t) + f(t - 1)) - f(t)}, where the
     * link-by-link loop stores a force and loads it back at the next link. These are the same operations in the
     * same order for each mass (a mass of a segment receives +f from the link before it, then -f from its own),
     * so the results are bit for bit those of the link-by-link loop ({@code SpringDamper1DSegmentTest}), which
     * {@link Engine#setStencilSweeps(boolean) setStencilSweeps(false)} selects for every link. A segment whose links
     * all have the same parameters (a uniform string) holds them in registers too; which segments are uniform is
     * looked at again after every parameter change.
     */
    static final class SpringDamper1D extends BatchKernel {
        /** Fewest links for a segment: below this the link-by-link loop is as fast. */
        static final int MIN_SEGMENT = 8;
        /** Batch index ranges [segStart[q], segEnd[q]) run as segments; everything between them link by link. */
        private final int[] segStart;
        private final int[] segEnd;

        SpringDamper1D(LinkBatch b, StepPlan p) {
            super(b, p);
            int[] starts = new int[4];
            int[] ends = new int[4];
            int count = 0;
            int n = b.nIrregular;   // the links of stencil runs are stepped by their own kernels
            int j = p.sweepRuns ? 0 : n; // stencil sweeps off (Engine.setStencilSweeps): every link one by one
            while (j < n) {
                int e = j;
                while (e < n && b.b[e] == b.a[e] + 1 && (e == j || b.a[e] == b.a[e - 1] + 1)) {
                    e++;
                }
                if (e - j >= MIN_SEGMENT) {
                    if (count == starts.length) {
                        starts = java.util.Arrays.copyOf(starts, 2 * count);
                        ends = java.util.Arrays.copyOf(ends, 2 * count);
                    }
                    starts[count] = j;
                    ends[count] = e;
                    count++;
                    j = e;
                } else {
                    j = Math.max(j + 1, e);
                }
            }
            segStart = java.util.Arrays.copyOf(starts, count);
            segEnd = java.util.Arrays.copyOf(ends, count);
            uniform = new boolean[count];
            segK = new double[count];
            segZ = new double[count];
            segL = new double[count];
        }

        /** @return the number of segments (diagnostics and tests). */
        int segments() {
            return segStart.length;
        }

        /** The batch's parameter version that {@link #uniform} describes. */
        private int seenParams = -1;
        /** Per segment: true when its links share one stiffness, damping and length, held in segK, segZ, segL. */
        private final boolean[] uniform;
        private final double[] segK;
        private final double[] segZ;
        private final double[] segL;

        /**
         * True when every link outside the segments has the same stiffness, damping and length (uK, uZ, uL), held in
         * registers then (a plate's links, the ends of a string); with stencil sweeps off, never (the reference).
         */
        private boolean uniformLinks;
        private double uK;
        private double uZ;
        private double uL;

        @Override
        public void run() {
            if (b.paramsVersion != seenParams) {
                findUniformSegments();
            }
            int from = 0;
            for (int q = 0; q < segStart.length; q++) {
                between(from, segStart[q]);
                if (uniform[q]) {
                    uniformSegment(segStart[q], segEnd[q], segK[q], segZ[q], segL[q]);
                } else {
                    segment(segStart[q], segEnd[q]);
                }
                from = segEnd[q];
            }
            between(from, b.nIrregular);
        }

        /** The links [from, to) outside the segments, one by one. */
        private void between(int from, int to) {
            if (uniformLinks) {
                uniformLinks(from, to, uK, uZ, uL);
            } else {
                links(from, to);
            }
        }

        /** Looks again (after a parameter change) which segments have one set of parameters for all their links. */
        private void findUniformSegments() {
            seenParams = b.paramsVersion;
            findUniformLinks();
            for (int q = 0; q < segStart.length; q++) {
                int js = segStart[q];
                double kk = b.k[js], zz = b.z[js], l = b.len[js];
                boolean same = true;
                for (int j = js + 1; j < segEnd[q] && same; j++) {
                    same = hasParams(j, kk, zz, l);
                }
                uniform[q] = same;
                segK[q] = kk;
                segZ[q] = zz;
                segL[q] = l;
            }
        }

        /** Looks again whether the links outside the segments all share one stiffness, damping and length. */
        private void findUniformLinks() {
            int q = 0;
            boolean same = true;
            boolean first = true;
            for (int j = 0; j < b.nIrregular && same; j++) {
                if (q < segStart.length && j == segStart[q]) {
                    j = segEnd[q++] - 1;   // a segment's links are looked at by findUniformSegments
                    continue;
                }
                if (first) {
                    uK = b.k[j];
                    uZ = b.z[j];
                    uL = b.len[j];
                    first = false;
                } else {
                    same = hasParams(j, uK, uZ, uL);
                }
            }
            uniformLinks = same && !first && p.sweepRuns;
        }

        /**
         * @return true if link j has exactly this stiffness, damping and length, compared as bits: the constants must
         *     give exactly the values the links hold (-0.0, NaN)
         */
        private boolean hasParams(int j, double kk, double zz, double l) {
            return Double.doubleToRawLongBits(b.k[j]) == Double.doubleToRawLongBits(kk)
                    && Double.doubleToRawLongBits(b.z[j]) == Double.doubleToRawLongBits(zz)
                    && Double.doubleToRawLongBits(b.len[j]) == Double.doubleToRawLongBits(l);
        }

        /** @return true when the links outside the segments run with their shared parameters as constants (tests). */
        boolean uniformLinks() {
            return uniformLinks;
        }

        /** As {@link #links}, for links that all have stiffness kk, damping zz and length l: fewer loads per link. */
        private void uniformLinks(int from, int to, double kk, double zz, double l) {
            final double[] z = p.z, fz = p.fz, dp = b.dp;
            final int[] ia = b.a, ib = b.b;
            for (int j = from; j < to; j++) {
                int a = ia[j], c = ib[j];
                double e = z[a] - z[c];
                double f = kk * (e - l) + zz * (e - dp[j]);
                dp[j] = e;
                fz[a] -= f;
                fz[c] += f;
            }
        }

        /** As {@link #segment}, for links that all have stiffness kk, damping zz and length l: fewer loads per link. */
        private void uniformSegment(int js, int je, double kk, double zz, double l) {
            final double[] z = p.z, fz = p.fz, dp = b.dp;
            final int shift = b.a[js] - js;
            double near = z[js + shift];
            double far = z[js + shift + 1];
            double e = near - far;
            double f = kk * (e - l) + zz * (e - dp[js]);
            dp[js] = e;
            fz[js + shift] -= f;
            for (int j = js + 1; j < je; j++) {
                int t = j + shift;
                near = far;
                far = z[t + 1];
                e = near - far;
                double g = kk * (e - l) + zz * (e - dp[j]);
                dp[j] = e;
                fz[t] = (fz[t] + f) - g;
                f = g;
            }
            fz[je + shift] += f;
        }

        /** The links [from, to) one by one. */
        private void links(int from, int to) {
            final double[] z = p.z, fz = p.fz;
            final int[] ia = b.a, ib = b.b;
            final double[] k = b.k, zz = b.z, l0 = b.len, dp = b.dp;
            for (int j = from; j < to; j++) {
                int a = ia[j], c = ib[j];
                double e = z[a] - z[c];
                double f = k[j] * (e - l0[j]) + zz[j] * (e - dp[j]);
                dp[j] = e;
                fz[a] -= f;
                fz[c] += f;
            }
        }

        /** The links [js, je) (at least two), link js + i joining slots s + i and s + i + 1 (s = a[js]). */
        private void segment(int js, int je) {
            final double[] z = p.z, fz = p.fz;
            final double[] k = b.k, zz = b.z, l0 = b.len, dp = b.dp;
            final int shift = b.a[js] - js; // slot of mass 1 of link j
            double near = z[js + shift];
            double far = z[js + shift + 1];
            double e = near - far;
            double f = k[js] * (e - l0[js]) + zz[js] * (e - dp[js]);
            dp[js] = e;
            fz[js + shift] -= f;
            for (int j = js + 1; j < je; j++) {
                int t = j + shift;
                near = far;
                far = z[t + 1];
                e = near - far;
                double g = k[j] * (e - l0[j]) + zz[j] * (e - dp[j]);
                dp[j] = e;
                fz[t] = (fz[t] + f) - g;
                f = g;
            }
            fz[je + shift] += f;
        }
    }

    /**
     * Rope3D and Bubble3D: the spring-damper force, only while {@code d > l0} (rope length or
     * bubble radius). On the first active step the previous distance is re-derived from the
     * masses' previous positions, so the damper sees the true approach speed.
     */
    static final class Stretched extends BatchKernel {
        Stretched(LinkBatch b, StepPlan p) {
            super(b, p);
        }

        @Override
        public void run() {
            final double[] x = p.x, y = p.y, z = p.z, fx = p.fx, fy = p.fy, fz = p.fz;
            final int[] ia = b.a, ib = b.b;
            final double[] k = b.k, zz = b.z, l0 = b.len, dp = b.dp;
            for (int j = 0, n = b.n; j < n; j++) {
                int a = ia[j], c = ib[j];
                double dx = x[a] - x[c], dy = y[a] - y[c], dz = z[a] - z[c];
                double d2 = dx * dx + dy * dy + dz * dz;
                double l = l0[j];
                if (d2 <= l * l) {
                    dp[j] = -1.0;
                    continue;
                }
                double d = Math.sqrt(d2);
                double prev = dp[j] < 0 ? previousDistance(p, a, c) : dp[j];
                dp[j] = d;
                push(fx, fy, fz, a, c, springDamperOverDistance(k[j], zz[j], l, d, prev), dx, dy, dz);
            }
        }
    }

    /**
     * Contact3D: the spring-damper force with the threshold as rest length, only while
     * {@code d < threshold}. The force is not clamped, as in the reference scheme. A contact that acts stamps
     * the step in {@link LinkBatch#engagedAt}; one that does not is left untouched, so a step writes nothing for
     * the contacts that are apart. When the batch has a {@link ContactIndex}, only its candidates are tested;
     * they are every contact that can act, in batch order, so the sums are those of a test of every contact.
     */
    static final class Proximity extends BatchKernel {
        Proximity(LinkBatch b, StepPlan p) {
            super(b, p);
            if (b.contactIndex == null || b.contactIndex.plan() != p) {
                b.contactIndex = ContactIndex.forBatch(b, p);
            }
        }

        @Override
        public void run() {
            long step = ++b.contactSteps;
            ContactIndex index = b.contactIndex;
            if (index != null && index.refresh()) {
                final int[] cand = index.candidate;
                for (int q = 0, m = index.candidates; q < m; q++) {
                    contact(cand[q], step);
                }
            } else {
                for (int j = 0, n = b.n; j < n; j++) {
                    contact(j, step);
                }
            }
        }

        /** Tests contact j and, while it is engaged, applies its force and stamps the step. */
        private void contact(int j, long step) {
            final double[] x = p.x, y = p.y, z = p.z;
            int a = b.a[j], c = b.b[j];
            double dx = x[a] - x[c], dy = y[a] - y[c], dz = z[a] - z[c];
            double d2 = dx * dx + dy * dy + dz * dz;
            double t = b.len[j];
            if (d2 >= t * t) {
                return;
            }
            double d = Math.sqrt(d2);
            double prev = b.engagedAt[j] == step - 1 ? b.dp[j] : previousDistance(p, a, c);
            b.dp[j] = d;
            b.engagedAt[j] = step;
            if (d > 0) {
                push(p.fx, p.fy, p.fz, a, c, springDamperOverDistance(b.k[j], b.z[j], t, d, prev), dx, dy, dz);
            }
        }
    }

    /**
     * PlaneContact3D: with q the mass coordinate on the plane's axis and {@code t = q - pos - l0},
     * while {@code t < 0} the axis force {@code -K t - Z (q(n) - q(n-1))} pushes the mass back to
     * the positive side. Links are grouped by axis, so the loop has no branch on the axis.
     */
    static final class Plane extends BatchKernel {
        Plane(LinkBatch b, StepPlan p) {
            super(b, p);
        }

        @Override
        public void run() {
            int[] as = b.axisStart;
            axis(as[0], as[1], p.x, p.px, p.fx);
            axis(as[1], as[2], p.y, p.py, p.fy);
            axis(as[2], as[3], p.z, p.pz, p.fz);
        }

        private void axis(int s, int e, double[] q, double[] pq, double[] fq) {
            final int[] ia = b.a;
            final double[] k = b.k, zz = b.z, l0 = b.len, pos = b.planePosition;
            for (int j = s; j < e; j++) {
                int a = ia[j];
                double qa = q[a];
                double t = qa - pos[j] - l0[j];
                if (t < 0) {
                    fq[a] += -k[j] * t - zz[j] * (qa - pq[a]);
                }
            }
        }
    }

    /** Attractor3D: f = -A / d^2 while d > the limit distance; no damping. */
    static final class Attractor extends BatchKernel {
        Attractor(LinkBatch b, StepPlan p) {
            super(b, p);
        }

        @Override
        public void run() {
            final double[] x = p.x, y = p.y, z = p.z, fx = p.fx, fy = p.fy, fz = p.fz;
            final int[] ia = b.a, ib = b.b;
            final double[] lim = b.len, att = b.attraction;
            for (int j = 0, n = b.n; j < n; j++) {
                int a = ia[j], c = ib[j];
                double dx = x[a] - x[c], dy = y[a] - y[c], dz = z[a] - z[c];
                double d2 = dx * dx + dy * dy + dz * dz;
                double l = lim[j];
                if (d2 <= l * l || d2 == 0) {
                    continue;
                }
                double d = Math.sqrt(d2);
                double s = -att[j] / (d2 * d);
                push(fx, fy, fz, a, c, s, dx, dy, dz);
            }
        }
    }

    /**
     * The force law of every conditional spring-damper (Rope3D, Bubble3D, Contact3D and contact groups): the
     * scalar force {@code -K (d - l0) - Z (d - dPrev)} divided by the distance d (&gt; 0), ready to scale the
     * difference vector. One definition, so explicit contacts and contact groups agree bit for bit; small
     * enough for C2 to inline into every loop.
     */
    static double springDamperOverDistance(double k, double z, double l0, double d, double dPrev) {
        return (-k * (d - l0) - z * (d - dPrev)) / d;
    }

    /** Adds {@code s (dx, dy, dz)} to mass a's force and subtracts it from mass c's: one link's action and reaction. */
    static void push(double[] fx, double[] fy, double[] fz, int a, int c, double s, double dx, double dy, double dz) {
        fx[a] += s * dx;
        fy[a] += s * dy;
        fz[a] += s * dz;
        fx[c] -= s * dx;
        fy[c] -= s * dy;
        fz[c] -= s * dz;
    }

    /** Distance between two masses at the previous step, from their previous positions. */
    static double previousDistance(StepPlan p, int a, int c) {
        double dx = p.px[a] - p.px[c], dy = p.py[a] - p.py[c], dz = p.pz[a] - p.pz[c];
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }
}
