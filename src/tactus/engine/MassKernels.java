package tactus.engine;

/**
 * The mass-phase kernels. Each one advances a contiguous range of slots of one kind by one
 * step of the explicit central-difference scheme, using the forces accumulated during the
 * previous interaction phase, then clears those forces (except the haptic avatar, which
 * keeps accumulating until its force is taken).
 *
 * <p>With velocity retention {@code d}, the update is
 * {@code X(n+1) = X(n) + d (X(n) - X(n-1)) + F/M + g}, which is the scheme
 * {@code X(n+1) = (2 - f/M) X(n) - (1 - f/M) X(n-1) + F/M + g} written in incremental form.
 */
final class MassKernels {
    private MassKernels() {
    }

    static Kernel create(MassKind kind, StepPlan p, int s, int e, boolean plain) {
        switch (kind) {
            case MASS3D:
                return plain ? new Free3D(p, s, e) : new Medium3D(p, s, e);
            case MASS2D_PLANE:
                return new Plane2D(p, s, e);
            case MASS1D:
                return new Line1D(p, s, e);
            case OSC3D:
                return new Osc3D(p, s, e);
            case OSC1D:
                return new Osc1D(p, s, e);
            case HAPTIC_INPUT3D:
                return new Input3D(p, s, e, false);
            case POS_INPUT3D:
                return new Input3D(p, s, e, true);
            case GROUND3D:
            case GROUND1D:
                return new Fixed(p, s, e);
            default:
                throw new IllegalStateException("no kernel for " + kind);
        }
    }

    /**
     * Mass3D with neither friction nor gravity: X(n+1) = 2X(n) - X(n-1) + F/M. Each coordinate is a
     * separate loop whose arrays share one index, the form JDK 17's C2 vectorises.
     */
    static final class Free3D implements RangeKernel {
        private final StepPlan p;
        private final int s;
        private final int e;

        Free3D(StepPlan p, int s, int e) {
            this.p = p;
            this.s = s;
            this.e = e;
        }

        @Override
        public void run() {
            run(0, s, e);
        }

        @Override
        public int stages() {
            return 1;
        }

        @Override
        public int start(int stage) {
            return s;
        }

        @Override
        public int end(int stage) {
            return e;
        }

        @Override
        public void run(int stage, int from, int to) {
            free(p.x, p.px, p.fx, p.invM, from, to);
            free(p.y, p.py, p.fy, p.invM, from, to);
            free(p.z, p.pz, p.fz, p.invM, from, to);
        }

        private static void free(double[] x, double[] px, double[] f, double[] im, int s, int e) {
            for (int i = s; i < e; i++) {
                double xi = x[i];
                x[i] = xi + (xi - px[i]) + f[i] * im[i];
                px[i] = xi;
                f[i] = 0;
            }
        }
    }

    /** Mass3D with air friction and gravity, one loop per coordinate. */
    static final class Medium3D implements RangeKernel {
        private final StepPlan p;
        private final int s;
        private final int e;

        Medium3D(StepPlan p, int s, int e) {
            this.p = p;
            this.s = s;
            this.e = e;
        }

        @Override
        public void run() {
            run(0, s, e);
        }

        @Override
        public int stages() {
            return 1;
        }

        @Override
        public int start(int stage) {
            return s;
        }

        @Override
        public int end(int stage) {
            return e;
        }

        @Override
        public void run(int stage, int from, int to) {
            Medium m = p.medium;
            damped(p.x, p.px, p.fx, p.invM, p.dmp, m.gx, from, to);
            damped(p.y, p.py, p.fy, p.invM, p.dmp, m.gy, from, to);
            damped(p.z, p.pz, p.fz, p.invM, p.dmp, m.gz, from, to);
        }

        private static void damped(double[] x, double[] px, double[] f, double[] im, double[] d, double g,
                                   int s, int e) {
            for (int i = s; i < e; i++) {
                double xi = x[i];
                x[i] = xi + d[i] * (xi - px[i]) + f[i] * im[i] + g;
                px[i] = xi;
                f[i] = 0;
            }
        }
    }

    /** Mass2DPlane: x and y move as a Mass3D; z stays on its plane. */
    static final class Plane2D implements Kernel {
        private final StepPlan p;
        private final int s;
        private final int e;

        Plane2D(StepPlan p, int s, int e) {
            this.p = p;
            this.s = s;
            this.e = e;
        }

        @Override
        public void run() {
            final double[] x = p.x, y = p.y, px = p.px, py = p.py;
            final double[] fx = p.fx, fy = p.fy, fz = p.fz, im = p.invM, d = p.dmp;
            final double gx = p.medium.gx, gy = p.medium.gy;
            for (int i = s; i < e; i++) {
                double m = im[i], r = d[i];
                double xi = x[i], yi = y[i];
                x[i] = xi + r * (xi - px[i]) + fx[i] * m + gx;
                y[i] = yi + r * (yi - py[i]) + fy[i] * m + gy;
                px[i] = xi;
                py[i] = yi;
                fx[i] = 0;
                fy[i] = 0;
                fz[i] = 0;
            }
        }
    }

    /** Mass1D: only z moves. */
    static final class Line1D implements Kernel {
        private final StepPlan p;
        private final int s;
        private final int e;

        Line1D(StepPlan p, int s, int e) {
            this.p = p;
            this.s = s;
            this.e = e;
        }

        @Override
        public void run() {
            final double[] z = p.z, pz = p.pz, fx = p.fx, fy = p.fy, fz = p.fz, im = p.invM, d = p.dmp;
            final double gz = p.medium.gz;
            for (int i = s; i < e; i++) {
                double zi = z[i];
                z[i] = zi + d[i] * (zi - pz[i]) + fz[i] * im[i] + gz;
                pz[i] = zi;
                fx[i] = 0;
                fy[i] = 0;
                fz[i] = 0;
            }
        }
    }

    /**
     * Osc3D: with Y = X - rest, Y(n+1) = (2 - K/M - (Z+f)/M) Y(n) - (1 - (Z+f)/M) Y(n-1) + F/M + g.
     * The coefficients are read from the plan every step, so parameter changes apply at once.
     */
    static final class Osc3D implements Kernel {
        private final StepPlan p;
        private final int s;
        private final int e;

        Osc3D(StepPlan p, int s, int e) {
            this.p = p;
            this.s = s;
            this.e = e;
        }

        @Override
        public void run() {
            final double[] x = p.x, y = p.y, z = p.z, px = p.px, py = p.py, pz = p.pz;
            final double[] fx = p.fx, fy = p.fy, fz = p.fz, im = p.invM, d = p.dmp, k = p.stf;
            final double[] rx = p.rx, ry = p.ry, rz = p.rz;
            final double gx = p.medium.gx, gy = p.medium.gy, gz = p.medium.gz;
            for (int i = s; i < e; i++) {
                double m = im[i], r = d[i], c = k[i];
                double xi = x[i], yi = y[i], zi = z[i];
                x[i] = xi + r * (xi - px[i]) - c * (xi - rx[i]) + fx[i] * m + gx;
                y[i] = yi + r * (yi - py[i]) - c * (yi - ry[i]) + fy[i] * m + gy;
                z[i] = zi + r * (zi - pz[i]) - c * (zi - rz[i]) + fz[i] * m + gz;
                px[i] = xi;
                py[i] = yi;
                pz[i] = zi;
                fx[i] = 0;
                fy[i] = 0;
                fz[i] = 0;
            }
        }
    }

    /** Osc1D: the oscillator along z only. */
    static final class Osc1D implements Kernel {
        private final StepPlan p;
        private final int s;
        private final int e;

        Osc1D(StepPlan p, int s, int e) {
            this.p = p;
            this.s = s;
            this.e = e;
        }

        @Override
        public void run() {
            final double[] z = p.z, pz = p.pz, fx = p.fx, fy = p.fy, fz = p.fz;
            final double[] im = p.invM, d = p.dmp, k = p.stf, rz = p.rz;
            final double gz = p.medium.gz;
            for (int i = s; i < e; i++) {
                double zi = z[i];
                z[i] = zi + d[i] * (zi - pz[i]) - k[i] * (zi - rz[i]) + fz[i] * im[i] + gz;
                pz[i] = zi;
                fx[i] = 0;
                fy[i] = 0;
                fz[i] = 0;
            }
        }
    }

    /**
     * HapticInput3D and PosInput3D: X(n+1) = X(n) + w (target - X(n)), an exponentially weighted
     * moving average toward the target. The previous position is kept so velocities are right.
     * The haptic avatar keeps its force buffer (an accumulator emptied by whoever reads it);
     * the position driver clears it every step.
     */
    static final class Input3D implements Kernel {
        private final StepPlan p;
        private final int s;
        private final int e;
        private final boolean clearForce;

        Input3D(StepPlan p, int s, int e, boolean clearForce) {
            this.p = p;
            this.s = s;
            this.e = e;
            this.clearForce = clearForce;
        }

        @Override
        public void run() {
            final double[] x = p.x, y = p.y, z = p.z, px = p.px, py = p.py, pz = p.pz;
            final double[] tx = p.tx, ty = p.ty, tz = p.tz, w = p.w;
            for (int i = s; i < e; i++) {
                double a = w[i];
                double xi = x[i], yi = y[i], zi = z[i];
                x[i] = xi + a * (tx[i] - xi);
                y[i] = yi + a * (ty[i] - yi);
                z[i] = zi + a * (tz[i] - zi);
                px[i] = xi;
                py[i] = yi;
                pz[i] = zi;
            }
            if (clearForce) {
                java.util.Arrays.fill(p.fx, s, e, 0.0);
                java.util.Arrays.fill(p.fy, s, e, 0.0);
                java.util.Arrays.fill(p.fz, s, e, 0.0);
            }
        }
    }

    /** Ground3D and Ground1D: the position never changes; the force buffer is cleared. */
    static final class Fixed implements Kernel {
        private final StepPlan p;
        private final int s;
        private final int e;

        Fixed(StepPlan p, int s, int e) {
            this.p = p;
            this.s = s;
            this.e = e;
        }

        @Override
        public void run() {
            java.util.Arrays.fill(p.fx, s, e, 0.0);
            java.util.Arrays.fill(p.fy, s, e, 0.0);
            java.util.Arrays.fill(p.fz, s, e, 0.0);
        }
    }
}
