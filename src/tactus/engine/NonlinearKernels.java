package tactus.engine;

import static tactus.engine.LinkKernels.previousDistance;
import static tactus.engine.LinkKernels.push;

/**
 * The kernels of mi.lib's nonlinear interactions. A kernel shared by several kinds picks the law with a switch on
 * the batch's kind, a loop invariant held in a final local; each law is a static method of {@link NonlinearLaws},
 * called directly (no virtual call in the loop). The 1-D kernels act
 * along z on the signed difference {@code e = z1 - z2}, as mi.lib does; the 3-D kernels apply the same law along
 * the direction between the two masses, as {@code SpringDamper3D} does for the linear spring, except the bow,
 * whose friction acts along the relative velocity.
 */
final class NonlinearKernels {
    private NonlinearKernels() {
    }

    /** The 1-D springs and the pluck: {@code F = law(e - l0, e - e(n-1))}; mass 1 receives -F, mass 2 +F, on z. */
    static final class Elastic1D extends LinkKernels.BatchKernel {
        Elastic1D(LinkBatch b, StepPlan p) {
            super(b, p);
        }

        @Override
        public void run() {
            final double[] z = p.z, fz = p.fz;
            final int[] ia = b.a, ib = b.b;
            final double[] k = b.k, zz = b.z, l0 = b.len, dp = b.dp, q = b.aux0, r = b.aux1;
            final LinkKind kind = b.kind;
            for (int j = 0, n = b.n; j < n; j++) {
                int a = ia[j], c = ib[j];
                double e = z[a] - z[c];
                double x = e - l0[j];
                double v = e - dp[j];
                dp[j] = e;
                double f;
                switch (kind) {
                    case QUADRATIC_SPRING_DAMPER1D:
                        f = NonlinearLaws.quadratic(k[j], q[j], zz[j], x, v);
                        break;
                    case CUBIC_SPRING_DAMPER1D:
                        f = NonlinearLaws.cubic(k[j], q[j], zz[j], x, v);
                        break;
                    case CLIPPED_SPRING_DAMPER1D:
                        f = NonlinearLaws.clipped(k[j], q[j], r[j], zz[j], x, v);
                        break;
                    default:
                        f = NonlinearLaws.pluck(k[j], q[j], zz[j], x, v);
                }
                fz[a] -= f;
                fz[c] += f;
            }
        }
    }

    /** The 3-D springs and the pluck: {@code F = law(d - l0, d - d(n-1))} along the unit vector from mass 2 to 1. */
    static final class Elastic3D extends LinkKernels.BatchKernel {
        Elastic3D(LinkBatch b, StepPlan p) {
            super(b, p);
        }

        @Override
        public void run() {
            final double[] x = p.x, y = p.y, z = p.z, fx = p.fx, fy = p.fy, fz = p.fz;
            final int[] ia = b.a, ib = b.b;
            final double[] k = b.k, zz = b.z, l0 = b.len, dp = b.dp, q = b.aux0, r = b.aux1;
            final LinkKind kind = b.kind;
            for (int j = 0, n = b.n; j < n; j++) {
                int a = ia[j], c = ib[j];
                double dx = x[a] - x[c], dy = y[a] - y[c], dz = z[a] - z[c];
                double d = Math.sqrt(dx * dx + dy * dy + dz * dz);
                double e = d - l0[j];
                double v = d - dp[j];
                dp[j] = d;
                double f;
                switch (kind) {
                    case QUADRATIC_SPRING_DAMPER3D:
                        f = NonlinearLaws.quadratic(k[j], q[j], zz[j], e, v);
                        break;
                    case CUBIC_SPRING_DAMPER3D:
                        f = NonlinearLaws.cubic(k[j], q[j], zz[j], e, v);
                        break;
                    case CLIPPED_SPRING_DAMPER3D:
                        f = NonlinearLaws.clipped(k[j], q[j], r[j], zz[j], e, v);
                        break;
                    default:
                        f = NonlinearLaws.pluck(k[j], q[j], zz[j], e, v);
                }
                double s = d > 0 ? -f / d : 0.0;
                push(fx, fy, fz, a, c, s, dx, dy, dz);
            }
        }
    }

    /**
     * Bow1D: {@code F = bow((z1 - z1') - (z2 - z2'))}, the velocities taken from the masses' previous positions as
     * mi.lib takes them; mass 1 receives -F, mass 2 +F, on z.
     */
    static final class Bow1D extends LinkKernels.BatchKernel {
        Bow1D(LinkBatch b, StepPlan p) {
            super(b, p);
        }

        @Override
        public void run() {
            final double[] z = p.z, pz = p.pz, fz = p.fz;
            final int[] ia = b.a, ib = b.b;
            final double[] zz = b.z, scale = b.aux0, type = b.aux1;
            for (int j = 0, n = b.n; j < n; j++) {
                int a = ia[j], c = ib[j];
                double v = (z[a] - pz[a]) - (z[c] - pz[c]);
                double f = NonlinearLaws.bow(zz[j], scale[j], type[j], v);
                fz[a] -= f;
                fz[c] += f;
            }
        }
    }

    /**
     * Bow3D: with the relative velocity {@code w = (X1 - X1') - (X2 - X2')}, the friction {@code F = bow(|w|)}
     * acts against w: mass 1 receives {@code -F w/|w|}, mass 2 the opposite. A bow slides, so its friction acts
     * along the sliding velocity and not along the line between the masses.
     */
    static final class Bow3D extends LinkKernels.BatchKernel {
        Bow3D(LinkBatch b, StepPlan p) {
            super(b, p);
        }

        @Override
        public void run() {
            final double[] x = p.x, y = p.y, z = p.z, px = p.px, py = p.py, pz = p.pz;
            final int[] ia = b.a, ib = b.b;
            final double[] zz = b.z, scale = b.aux0, type = b.aux1;
            for (int j = 0, n = b.n; j < n; j++) {
                int a = ia[j], c = ib[j];
                double wx = (x[a] - px[a]) - (x[c] - px[c]);
                double wy = (y[a] - py[a]) - (y[c] - py[c]);
                double wz = (z[a] - pz[a]) - (z[c] - pz[c]);
                double w = Math.sqrt(wx * wx + wy * wy + wz * wz);
                if (w > 0) {
                    double s = -NonlinearLaws.bow(zz[j], scale[j], type[j], w) / w;
                    push(p.fx, p.fy, p.fz, a, c, s, wx, wy, wz);
                }
            }
        }
    }

    /**
     * ClippedContact1D, mi.lib's nlCollisionClipped: while {@code z2 - z1 < threshold}, {@code F = clipped(e + t,
     * e - e(n-1))} with {@code e = z1 - z2}; mass 1 receives -F, mass 2 +F. The previous difference is kept on
     * every step, engaged or not, as mi.lib's delayed positions are.
     */
    static final class Contact1D extends LinkKernels.BatchKernel {
        Contact1D(LinkBatch b, StepPlan p) {
            super(b, p);
        }

        @Override
        public void run() {
            final double[] z = p.z, fz = p.fz;
            final int[] ia = b.a, ib = b.b;
            final double[] k = b.k, zz = b.z, t = b.len, dp = b.dp, c3 = b.aux0, kMax = b.aux1;
            for (int j = 0, n = b.n; j < n; j++) {
                int a = ia[j], c = ib[j];
                double e = z[a] - z[c];
                double v = e - dp[j];
                dp[j] = e;
                if (z[c] - z[a] < t[j]) {
                    double f = NonlinearLaws.clipped(k[j], c3[j], kMax[j], zz[j], e + t[j], v);
                    fz[a] -= f;
                    fz[c] += f;
                }
            }
        }
    }

    /**
     * ClippedContact3D: while {@code d < threshold}, the clipped law of the penetration {@code t - d} and of its
     * rate {@code -(d - d(n-1))} pushes the masses apart. As for Rope3D, the previous distance of a contact that
     * starts to act is taken from the masses' previous positions.
     */
    static final class Contact3D extends LinkKernels.BatchKernel {
        Contact3D(LinkBatch b, StepPlan p) {
            super(b, p);
        }

        @Override
        public void run() {
            final double[] x = p.x, y = p.y, z = p.z, fx = p.fx, fy = p.fy, fz = p.fz;
            final int[] ia = b.a, ib = b.b;
            final double[] k = b.k, zz = b.z, t = b.len, dp = b.dp, c3 = b.aux0, kMax = b.aux1;
            for (int j = 0, n = b.n; j < n; j++) {
                int a = ia[j], c = ib[j];
                double dx = x[a] - x[c], dy = y[a] - y[c], dz = z[a] - z[c];
                double d2 = dx * dx + dy * dy + dz * dz;
                double l = t[j];
                if (d2 >= l * l) {
                    dp[j] = -1.0;
                    continue;
                }
                double d = Math.sqrt(d2);
                double prev = dp[j] < 0 ? previousDistance(p, a, c) : dp[j];
                dp[j] = d;
                if (d > 0) {
                    double f = NonlinearLaws.clipped(k[j], c3[j], kMax[j], zz[j], l - d, prev - d);
                    push(fx, fy, fz, a, c, f / d, dx, dy, dz);
                }
            }
        }
    }
}
