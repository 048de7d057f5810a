package tactus.hapticstability;

import java.util.Locale;
import tactus.haptics.emulator.PlantParameters;

/**
 * The stiff-wall measurements on the emulated Inverse3 (docs/haptics-stability.md, "In 3-D and at audio rate"): the
 * generic 3-DoF plant ({@link PlantParameters#cartesian3Dof()}) through the real haptic loop in lockstep
 * ({@link Inverse3WallRig}); the largest stable stiffness of a two-sided wall along the y axis and along the
 * diagonal (1, 1, 1), without and with Coulomb friction, without and with the passivity controller, the model
 * stepped by the haptic loop or at 44.1 kHz in a PhyUGen; and, at audio rate, the energy a stiff wall gives the
 * handle (observer against the plant's own record). Prints Markdown tables. About 8 minutes (each run takes its
 * simulated time of wall clock: the loop runs at its real rate).
 */
public final class Inverse3WallSweep {
    /** The diagonal direction of the off-axis wall. */
    static final double[] DIAGONAL = {1, 1, 1};
    /** The on-axis direction. */
    static final double[] AXIS_Y = {0, 1, 0};

    private Inverse3WallSweep() {
    }

    /** The plant's mass along an axis (kg): joint inertia plus handle mass, for the Cartesian kinematics. */
    static double mass(PlantParameters p) {
        return p.jointInertia() + p.handleMass();
    }

    /** The plant's viscous damping along an axis (N s/m). */
    static double damping(PlantParameters p) {
        return p.jointDamping() + p.taskDamping();
    }

    /**
     * The largest stable stiffness (N/m) for this configuration, by geometric bisection to about 0.5 %, starting
     * around {@code guess}; +infinity if a wall of {@code top} is still stable.
     */
    static double edge(Inverse3WallRig.Config base, double guess, double top) {
        double lo = guess;
        double hi = guess;
        if (unstable(base, guess)) {
            do {
                hi = lo;
                lo /= 2;
            } while (unstable(base, lo) && lo > 1e-3 * guess);
        } else {
            do {
                lo = hi;
                hi *= 2;
                if (hi > top) {
                    return Double.POSITIVE_INFINITY;
                }
            } while (!unstable(base, hi));
        }
        while (hi / lo > 1.01) {
            double mid = Math.sqrt(lo * hi);
            if (unstable(base, mid)) {
                hi = mid;
            } else {
                lo = mid;
            }
        }
        return Math.sqrt(lo * hi);
    }

    static boolean unstable(Inverse3WallRig.Config base, double k) {
        Inverse3WallRig.Config c = base.copy();
        c.stiffness = k;
        return Inverse3WallRig.run(c).unstable();
    }

    private static String fmt(double k) {
        return Double.isInfinite(k) ? "stable to the top" : String.format(Locale.ROOT, "%.0f", k);
    }

    /** Prints the tables: both, or only {@code edges} or {@code energy} if that is the first argument. */
    public static void main(String[] args) {
        String only = args.length > 0 ? args[0] : "";
        PlantParameters full = PlantParameters.cartesian3Dof();
        PlantParameters linear = full.withoutFriction();
        double m = mass(full);
        double b = damping(full);
        double T = 0.001;
        double th0 = SampledWallTheory.stiffnessLimit(m, b, T, 0, 0);
        double th1 = SampledWallTheory.stiffnessLimit(m, b, T, 1, 0);
        System.out.printf(Locale.ROOT, "plant %s: m = %.3f kg, b = %.3f N s/m per axis; T = %.1f ms%n", full, m, b, T * 1e3);
        System.out.printf(Locale.ROOT, "theory: d = 0 %.1f N/m (exact closed form %.1f, 2b/T %.0f), d = 1 %.1f N/m; "
                + "passivity d = 0 %.0f, d = 1 %.0f%n", th0, SampledWallTheory.exactLimitNoDelay(m, b, T), 2 * b / T, th1,
                SampledWallTheory.passivityLimit(b, T, 0, 0), SampledWallTheory.passivityLimit(b, T, 1, 0));

        if (!only.equals("energy")) {
            edges(full, linear, th0, th1);
        }
        if (!only.equals("edges")) {
            energy(full, th1);
        }
    }

    private static void edges(PlantParameters full, PlantParameters linear, double th0, double th1) {
        System.out.println();
        System.out.println("| model stepped | wall | plant | controller | largest stable K (N/m) | / theory d = 0 | / theory d = 1 |");
        System.out.println("|---|---|---|---|---|---|---|");
        double top = 64 * th0;
        String[] names = {"haptic loop, 1 kHz", "PhyUGen, 44.1 kHz, per tick", "PhyUGen, 44.1 kHz, 256-sample buffers",
            "PhyUGen, 44.1 kHz, 1024-sample buffers"};
        int[] bursts = {0, 0, 256, 1024};
        for (int mode = 0; mode < names.length; mode++) {
            for (PlantParameters p : new PlantParameters[] {linear, full}) {
                for (double[] dir : new double[][] {AXIS_Y, DIAGONAL}) {
                    if ((mode > 0 && dir == DIAGONAL) || (mode == 2 && p == full)) {
                        continue;
                    }
                    for (boolean pc : new boolean[] {false, true}) {
                        Inverse3WallRig.Config c = new Inverse3WallRig.Config();
                        c.plant = p;
                        c.direction = dir;
                        c.control = pc;
                        c.dampingLimit = 100;
                        c.mode = mode == 0 ? Inverse3WallRig.Mode.HAPTICS_ONLY : Inverse3WallRig.Mode.AUDIO;
                        c.burst = bursts[mode];
                        double guess = mode == 0 ? th0 : mode == 1 ? th1 : th1 * 20 / bursts[mode];
                        double k = edge(c, guess, top);
                        System.out.printf(Locale.ROOT, "| %s | %s | %s | %s | %s | %.3f | %.3f |%n", names[mode],
                                dir == AXIS_Y ? "along y" : "diagonal (1,1,1)", p == linear ? "no friction" : "Coulomb 0.05 N",
                                pc ? "PC, limit 100 N s/m" : "off", fmt(k), k / th0, k / th1);
                        System.out.flush();
                    }
                }
            }
        }

    }

    private static void energy(PlantParameters full, double th1) {
        System.out.println();
        System.out.println("Energy at audio rate: the plant with friction, a wall of K along y (1 mm step, 2 s); observer "
                + "net energy (in - out) against minus the work the plant recorded.");
        System.out.println();
        System.out.println("| model stepped | K (N/m) | controller | stable | work on the handle (mJ) | observer net (mJ) "
                + "| net + work (J) | dissipated (mJ) | active ticks |");
        System.out.println("|---|---|---|---|---|---|---|---|---|");
        for (int burst : new int[] {0, 1024}) {
            for (double k : new double[] {0.5 * th1, 3 * th1, 10 * th1}) {
                for (boolean pc : new boolean[] {false, true}) {
                    Inverse3WallRig.Config c = new Inverse3WallRig.Config();
                    c.plant = full;
                    c.control = pc;
                    c.dampingLimit = 100;
                    c.mode = Inverse3WallRig.Mode.AUDIO;
                    c.burst = burst;
                    c.stiffness = k;
                    Inverse3WallRig.Trace t = Inverse3WallRig.run(c);
                    System.out.printf(Locale.ROOT, "| PhyUGen, %s | %.0f | %s | %s | %.3f | %.3f | %.1e | %.3f | %.1f %% |%n",
                            burst == 0 ? "per tick" : "1024-sample buffers", k, pc ? "PC" : "off", t.unstable() ? "no" : "yes",
                            1e3 * t.work, 1e3 * t.net, t.net + t.work, 1e3 * t.dissipated, 100 * t.activeShare);
                    System.out.flush();
                }
            }
        }
    }
}
