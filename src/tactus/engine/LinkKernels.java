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

    static Kernel create(LinkBatch b, StepPlan p) {
        switch (b.kind) {
            case SPRING3D:
                return new Spring(b, p);
            case DAMPER3D:
                return new Damper(b, p);
            case SPRING_DAMPER3D:
                return new SpringDamper(b, p);
            case SPRING_DAMPER1D:
                return new SpringDamper1D(b, p);
            case ROPE3D:
            case BUBBLE3D:
                return new Stretched(b, p);
            case CONTACT3D:
                return new Proximity(b, p);
            case PLANE_CONTACT3D:
                return new Plane(b, p);
            case ATTRACTOR3D:
                return new Attractor(b, p);
            default:
                throw new IllegalStateException("no kernel for " + b.kind);
        }
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
     */
    static final class SpringDamper1D extends BatchKernel {
        SpringDamper1D(LinkBatch b, StepPlan p) {
            super(b, p);
        }

        @Override
        public void run() {
            final double[] z = p.z, fz = p.fz;
            final int[] ia = b.a, ib = b.b;
            final double[] k = b.k, zz = b.z, l0 = b.len, dp = b.dp;
            for (int j = 0, n = b.n; j < n; j++) {
                int a = ia[j], c = ib[j];
                double e = z[a] - z[c];
                double f = k[j] * (e - l0[j]) + zz[j] * (e - dp[j]);
                dp[j] = e;
                fz[a] -= f;
                fz[c] += f;
            }
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
