package tactus.engine;

import java.util.Arrays;

/**
 * The mass-phase kernels. Each one advances a contiguous range of slots of one kind by one
 * step of the explicit central-difference scheme, using the forces accumulated during the
 * previous interaction phase, then clears those forces (except the haptic avatar, which
 * keeps accumulating until its force is taken).
 *
 * <p>With velocity retention {@code d}, the update is
 * {@code X(n+1) = X(n) + d (X(n) - X(n-1)) + F/M + g}, which is the scheme
 * {@code X(n+1) = (2 - f/M) X(n) - (1 - f/M) X(n-1) + F/M + g} written in incremental form.
 * Every slot is independent of the others, so each kernel can be split into chunks of slots and
 * run on several threads ({@link RangeKernel}).
 */
final class MassKernels {
    private MassKernels() {
    }

    static Kernel create(MassKind kind, StepPlan p, int s, int e, boolean plain) {
        switch (kind) {
            case MASS3D:
                return plain ? new Free3D(p, s, e) : new Medium3D(p, s, e);
            case MASS3D_SIMPLE:
                return new Free3D(p, s, e);
            case DRIVEN3D:
                return new Driven3D(p, s, e);
            case MASS2D_PLANE:
                return new Plane2D(p, s, e, plain);
            case MASS1D:
                return new Line1D(p, s, e, plain);
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

    /** A mass kernel over the slots [s, e): one stage, any chunk of slots can run on its own. */
    abstract static class SlotKernel implements RangeKernel {
        final StepPlan p;
        private final int s;
        private final int e;

        SlotKernel(StepPlan p, int s, int e) {
            this.p = p;
            this.s = s;
            this.e = e;
        }

        /** Advances the slots [from, to). */
        abstract void step(int from, int to);

        @Override
        public final void run() {
            step(s, e);
        }

        @Override
        public final int stages() {
            return 1;
        }

        @Override
        public final int start(int stage) {
            return s;
        }

        @Override
        public final int end(int stage) {
            return e;
        }

        @Override
        public final void run(int stage, int from, int to) {
            step(from, to);
        }

        /** Clears the force buffers of the slots [from, to). */
        final void clearForces(int from, int to) {
            // one loop, not three Arrays.fill calls: fixed points are few (a string's two ends), and each fill call
            // costs more than clearing a few slots
            final double[] fx = p.fx, fy = p.fy, fz = p.fz;
            for (int i = from; i < to; i++) {
                fx[i] = 0.0;
                fy[i] = 0.0;
                fz[i] = 0.0;
            }
        }
    }

    /**
     * Mass3D with neither friction nor gravity: X(n+1) = 2X(n) - X(n-1) + F/M. Each coordinate is a
     * separate loop whose arrays share one index, the form JDK 17's C2 vectorises.
     */
    static final class Free3D extends SlotKernel {
        Free3D(StepPlan p, int s, int e) {
            super(p, s, e);
        }

        @Override
        void step(int from, int to) {
            free(p.x, p.px, p.fx, p.invM, from, to);
            free(p.y, p.py, p.fy, p.invM, from, to);
            free(p.z, p.pz, p.fz, p.invM, from, to);
        }

    }

    /**
     * One coordinate of a mass with neither friction nor gravity: X(n+1) = X(n) + (X(n) - X(n-1)) + F/M, the
     * exact reduction of {@link #damped} with retention 1 and no gravity (up to the sign of a zero position).
     */
    static void free(double[] x, double[] px, double[] f, double[] im, int s, int e) {
        for (int i = s; i < e; i++) {
            double xi = x[i];
            x[i] = xi + (xi - px[i]) + f[i] * im[i];
            px[i] = xi;
            f[i] = 0;
        }
    }

    /** Mass3D with air friction and gravity, one loop per coordinate. */
    static final class Medium3D extends SlotKernel {
        Medium3D(StepPlan p, int s, int e) {
            super(p, s, e);
        }

        @Override
        void step(int from, int to) {
            Medium m = p.medium;
            damped(p.x, p.px, p.fx, p.invM, p.retention, m.gx, from, to);
            damped(p.y, p.py, p.fy, p.invM, p.retention, m.gy, from, to);
            damped(p.z, p.pz, p.fz, p.invM, p.retention, m.gz, from, to);
        }
    }

    /** One coordinate of a damped mass with gravity: X(n+1) = X(n) + d (X(n) - X(n-1)) + F/M + g. */
    static void damped(double[] x, double[] px, double[] f, double[] im, double[] d, double g, int s, int e) {
        for (int i = s; i < e; i++) {
            double xi = x[i];
            x[i] = xi + d[i] * (xi - px[i]) + f[i] * im[i] + g;
            px[i] = xi;
            f[i] = 0;
        }
    }

    /**
     * Mass2DPlane: x and y move as a Mass3D; z stays on its plane. With neither friction nor gravity
     * ({@code plain}) it uses the reduced update of {@link #free}.
     */
    static final class Plane2D extends SlotKernel {
        private final boolean plain;

        Plane2D(StepPlan p, int s, int e, boolean plain) {
            super(p, s, e);
            this.plain = plain;
        }

        @Override
        void step(int from, int to) {
            if (plain) {
                free(p.x, p.px, p.fx, p.invM, from, to);
                free(p.y, p.py, p.fy, p.invM, from, to);
            } else {
                Medium m = p.medium;
                damped(p.x, p.px, p.fx, p.invM, p.retention, m.gx, from, to);
                damped(p.y, p.py, p.fy, p.invM, p.retention, m.gy, from, to);
            }
            Arrays.fill(p.fz, from, to, 0.0);
        }
    }

    /**
     * Mass1D: only z moves; with neither friction nor gravity ({@code plain}), by the reduced update. Its x and y
     * forces, which never move it, are cleared here only when an interaction can write them
     * ({@link StepPlan#offAxisWriters}).
     */
    static final class Line1D extends SlotKernel {
        private final boolean plain;

        Line1D(StepPlan p, int s, int e, boolean plain) {
            super(p, s, e);
            this.plain = plain;
        }

        @Override
        void step(int from, int to) {
            if (!p.offAxisWriters) {
                if (plain) {
                    free(p.z, p.pz, p.fz, p.invM, from, to);
                } else {
                    damped(p.z, p.pz, p.fz, p.invM, p.retention, p.medium.gz, from, to);
                }
            } else if (plain) {
                free1D(p.z, p.pz, p.fz, p.fx, p.fy, p.invM, from, to);
            } else {
                damped1D(p.z, p.pz, p.fz, p.fx, p.fy, p.invM, p.retention, p.medium.gz, from, to);
            }
        }
    }

    /** {@link #free} on z, clearing the x and y forces in the same loop (a 1-D mass moves one coordinate). */
    static void free1D(double[] x, double[] px, double[] f, double[] f1, double[] f2, double[] im, int s, int e) {
        for (int i = s; i < e; i++) {
            double xi = x[i];
            x[i] = xi + (xi - px[i]) + f[i] * im[i];
            px[i] = xi;
            f[i] = 0;
            f1[i] = 0;
            f2[i] = 0;
        }
    }

    /** {@link #damped} on z, clearing the x and y forces in the same loop. */
    static void damped1D(double[] x, double[] px, double[] f, double[] f1, double[] f2, double[] im, double[] d, double g,
                         int s, int e) {
        for (int i = s; i < e; i++) {
            double xi = x[i];
            x[i] = xi + d[i] * (xi - px[i]) + f[i] * im[i] + g;
            px[i] = xi;
            f[i] = 0;
            f1[i] = 0;
            f2[i] = 0;
        }
    }

    /**
     * One coordinate of an oscillator, with Y = X - rest:
     * Y(n+1) = (2 - K/M - (Z+f)/M) Y(n) - (1 - (Z+f)/M) Y(n-1) + F/M + g, written incrementally.
     * The coefficients are read from the plan every step, so parameter changes apply at once.
     */
    static void oscillate(double[] x, double[] px, double[] r, double[] f, double[] im, double[] d, double[] k,
                          double g, int s, int e) {
        for (int i = s; i < e; i++) {
            double xi = x[i];
            x[i] = xi + d[i] * (xi - px[i]) - k[i] * (xi - r[i]) + f[i] * im[i] + g;
            px[i] = xi;
            f[i] = 0;
        }
    }

    /**
     * An oscillator kernel (Osc3D, Osc1D). When all its masses share one retention and one stiffness per mass (a
     * plate or a bank of identical resonators), it runs with them as constants: the same operations on the same
     * values, and a loop that JDK 17's C2 vectorises (with both as arrays the loop reads seven arrays, and C2 leaves
     * it scalar: about 3 times slower on 64 masses). {@link StepPlan#prepareStep()} looks again after every change of
     * the masses' coefficients. With stencil sweeps off ({@link Engine#setStencilSweeps(boolean)}), the reference
     * form, never.
     */
    abstract static class OscKernel extends SlotKernel {
        /** True when every mass of the kernel has retention {@link #sharedRetention} and {@link #sharedStiffness}. */
        boolean shared;
        double sharedRetention;
        double sharedStiffness;

        OscKernel(StepPlan p, int s, int e) {
            super(p, s, e);
        }

        /** Looks whether the kernel's masses share one retention and one stiffness per mass (compared as bits). */
        final void findSharedCoefficients() {
            int s = start(0), e = end(0);
            boolean same = s < e && p.sweepRuns;
            double d = same ? p.retention[s] : 0;
            double k = same ? p.oscStiffnessPerMass[s] : 0;
            for (int i = s + 1; i < e && same; i++) {
                same = Double.doubleToRawLongBits(p.retention[i]) == Double.doubleToRawLongBits(d)
                        && Double.doubleToRawLongBits(p.oscStiffnessPerMass[i]) == Double.doubleToRawLongBits(k);
            }
            shared = same;
            sharedRetention = d;
            sharedStiffness = k;
        }

        /** One coordinate of the oscillators [from, to): {@link #oscillate}, with the shared coefficients if any. */
        final void oscillateCoordinate(double[] x, double[] px, double[] r, double[] f, double g, int from, int to) {
            if (shared) {
                oscillateShared(x, px, r, f, p.invM, sharedRetention, sharedStiffness, g, from, to);
            } else {
                oscillate(x, px, r, f, p.invM, p.retention, p.oscStiffnessPerMass, g, from, to);
            }
        }
    }

    /** {@link #oscillate} for oscillators that all have retention d and stiffness per mass k. */
    static void oscillateShared(double[] x, double[] px, double[] r, double[] f, double[] im, double d, double k,
                                double g, int s, int e) {
        for (int i = s; i < e; i++) {
            double xi = x[i];
            x[i] = xi + d * (xi - px[i]) - k * (xi - r[i]) + f[i] * im[i] + g;
            px[i] = xi;
            f[i] = 0;
        }
    }

    /** Osc3D: a mass tied to its rest position by its own spring and damper. */
    static final class Osc3D extends OscKernel {
        Osc3D(StepPlan p, int s, int e) {
            super(p, s, e);
        }

        @Override
        void step(int from, int to) {
            Medium m = p.medium;
            oscillateCoordinate(p.x, p.px, p.restX, p.fx, m.gx, from, to);
            oscillateCoordinate(p.y, p.py, p.restY, p.fy, m.gy, from, to);
            oscillateCoordinate(p.z, p.pz, p.restZ, p.fz, m.gz, from, to);
        }
    }

    /** Osc1D: the oscillator along z only; its x and y forces as for {@link Line1D}. */
    static final class Osc1D extends OscKernel {
        Osc1D(StepPlan p, int s, int e) {
            super(p, s, e);
        }

        @Override
        void step(int from, int to) {
            if (p.offAxisWriters) {
                oscillate1D(p.z, p.pz, p.restZ, p.fz, p.fx, p.fy, p.invM, p.retention, p.oscStiffnessPerMass,
                        p.medium.gz, from, to);
            } else {
                oscillateCoordinate(p.z, p.pz, p.restZ, p.fz, p.medium.gz, from, to);
            }
        }
    }

    /** {@link #oscillate} on z, clearing the x and y forces in the same loop (an Osc1D moves one coordinate). */
    static void oscillate1D(double[] x, double[] px, double[] r, double[] f, double[] f1, double[] f2, double[] im,
                            double[] d, double[] k, double g, int s, int e) {
        for (int i = s; i < e; i++) {
            double xi = x[i];
            x[i] = xi + d[i] * (xi - px[i]) - k[i] * (xi - r[i]) + f[i] * im[i] + g;
            px[i] = xi;
            f[i] = 0;
            f1[i] = 0;
            f2[i] = 0;
        }
    }

    /**
     * HapticInput3D and PosInput3D: X(n+1) = X(n) + w (target - X(n)), an exponentially weighted
     * moving average toward the target. The previous position is kept so velocities are right.
     * The haptic avatar keeps its force buffer (an accumulator emptied by whoever reads it);
     * the position driver clears it every step.
     */
    static final class Input3D extends SlotKernel {
        private final boolean clearForce;

        Input3D(StepPlan p, int s, int e, boolean clearForce) {
            super(p, s, e);
            this.clearForce = clearForce;
        }

        @Override
        void step(int from, int to) {
            follow(p.x, p.px, p.tx, p.inputWeight, from, to);
            follow(p.y, p.py, p.ty, p.inputWeight, from, to);
            follow(p.z, p.pz, p.tz, p.inputWeight, from, to);
            if (clearForce) {
                clearForces(from, to);
            }
        }

        private static void follow(double[] x, double[] px, double[] t, double[] w, int s, int e) {
            for (int i = s; i < e; i++) {
                double xi = x[i];
                x[i] = xi + w[i] * (t[i] - xi);
                px[i] = xi;
            }
        }
    }

    /**
     * Masses under velocity control: X(n+1) = X(n) + v, with v the displacement per step kept in the target
     * arrays; forces are ignored and cleared. When the control stops, the mass keeps moving at v.
     */
    static final class Driven3D extends SlotKernel {
        Driven3D(StepPlan p, int s, int e) {
            super(p, s, e);
        }

        @Override
        void step(int from, int to) {
            drift(p.x, p.px, p.tx, from, to);
            drift(p.y, p.py, p.ty, from, to);
            drift(p.z, p.pz, p.tz, from, to);
            clearForces(from, to);
        }

        private static void drift(double[] x, double[] px, double[] v, int s, int e) {
            for (int i = s; i < e; i++) {
                double xi = x[i];
                x[i] = xi + v[i];
                px[i] = xi;
            }
        }
    }

    /** Ground3D and Ground1D: the position never changes; the force buffer is cleared. */
    static final class Fixed extends SlotKernel {
        Fixed(StepPlan p, int s, int e) {
            super(p, s, e);
        }

        @Override
        void step(int from, int to) {
            clearForces(from, to);
        }
    }
}
