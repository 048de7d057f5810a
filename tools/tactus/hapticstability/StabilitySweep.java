package tactus.hapticstability;

import java.io.File;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import tactus.haptics.emulator.Hand;
import tactus.haptics.emulator.PlantParameters;
import tactus.report.LineChart;

/**
 * The full sweep behind docs/haptics-stability.md ({@code gradle stabilitySweep}): (1) the theory against the
 * emulator on a linear plant for several b, T and B; (2) walls from 0.1 to 400 times the uncontrolled bound on the
 * 2DIY plant as assumed (friction, the preset's encoders), without a hand (a step on a two-sided spring) and with a
 * pen grip pressing a one-sided wall, for every {@link #VARIANTS variant}; (3) the Z-width (largest stable K for
 * each B). Writes docs/haptics-stability-theory.csv, -sweep.csv, -zwidth.csv and -zwidth.png, and prints the
 * tables in Markdown. Every figure comes from the emulator in simulated time.
 */
public final class StabilitySweep {
    /**
     * What sits between device and avatar, one entry per method: add a controller here and every table and the
     * Z-width plot get its rows.
     */
    public static final List<WallRig.Variant> VARIANTS = new ArrayList<>(List.of(WallRig.UNCONTROLLED));

    static {
        // passivity control, virtual coupling, both (tactus.hapticstability.PassivityVariants): the coupling from the plant's
        // damping along the wall's axis, the observer told of the exchange's one tick of delay
        VARIANTS.addAll(tactus.hapticstability.PassivityVariants.all(
                EffectiveAxis.atEquilibrium(new WallRig.Config()).damping, 1));
    }

    /** Multiples of the uncontrolled bound swept. */
    static final double[] MULTIPLES = {0.1, 0.3, 0.5, 1, 2, 5, 10, 20, 40, 80, 200, 400};

    /**
     * Multiples of K0 scanned for the pen grip's Z-width: with a hand, friction and the encoders' steps make the
     * verdict not monotonic in K near the edge, so the edge is the last stable K of an increasing scan, not a
     * bisection.
     */
    static final double[] HAND_GRID = {5, 7, 10, 14, 20, 28, 40, 56, 80, 120, 200, 280, 400};

    /** Hand of the press: a light pen grip (kg, N/m, N s/m), assumed within the published ranges. */
    static final double HAND_MASS = 0.03;
    static final double HAND_STIFFNESS = 300;
    static final double HAND_DAMPING = 2;

    private StabilitySweep() {
    }

    /**
     * The intended motion of a press: still for 0.1 s, down at 20 mm/s to depth below the wall (gap below the
     * start), held until 1.35 s, back up at 20 mm/s, still (device metres; x stays at d/2).
     */
    static Hand.Script press(double x0, double y0, double gap, double depth) {
        double v = 0.02;
        double down = (gap + depth) / v;
        return (t, out) -> {
            double s;
            if (t < 0.1) {
                s = 0;
            } else if (t < 0.1 + down) {
                s = v * (t - 0.1);
            } else if (t < 1.35) {
                s = gap + depth;
            } else {
                s = Math.max(0, gap + depth - v * (t - 1.35));
            }
            out[0] = x0;
            out[1] = y0 - s;
        };
    }

    /** A press configuration on the given plant and variant: the pen grip presses a one-sided wall. */
    public static WallRig.Config pressConfig(PlantParameters plant, WallRig.Variant variant, double k, double b) {
        WallRig.Config c = config(plant, variant, WallRig.Wall.PLANE, k, b, 1800);
        c.hand = Hand.grasp(press(c.preset.d() / 2, WallRig.START_Y, c.gap, 0.003), HAND_MASS, HAND_STIFFNESS,
                HAND_DAMPING);
        return c;
    }

    /** A no-hand configuration: a 1 mm step on a two-sided spring. */
    static WallRig.Config springConfig(PlantParameters plant, WallRig.Variant variant, double k, double b) {
        return config(plant, variant, WallRig.Wall.SPRING, k, b, 2000);
    }

    private static WallRig.Config config(PlantParameters plant, WallRig.Variant variant, WallRig.Wall wall, double k,
                                         double b, int ticks) {
        WallRig.Config c = new WallRig.Config();
        c.plant = plant;
        c.variant = variant;
        c.wall = wall;
        c.stiffness = k;
        c.damping = b;
        c.ticks = ticks;
        return c;
    }

    /** Runs the sweep; args[0] is the docs folder. */
    public static void main(String[] args) throws IOException {
        File docs = new File(args.length > 0 ? args[0] : "docs");
        Locale.setDefault(Locale.ROOT);
        long t0 = System.nanoTime();
        theory(new File(docs, "haptics-stability-theory.csv"));
        PlantParameters plant = PlantParameters.twoDiy();
        EffectiveAxis ax = EffectiveAxis.atEquilibrium(springConfig(plant, WallRig.UNCONTROLLED, 0, 0));
        double k0 = SampledWallTheory.stiffnessLimit(ax.mass, ax.damping, 0.001, 1, 0);
        System.out.printf("%n2DIY plant as assumed, along y at the start pose: m = %.4f kg, b = %.4f N s/m; "
                + "uncontrolled bound K0 (theory, d = 1, B = 0) = %.1f N/m; passivity bound %.1f N/m%n%n",
                ax.mass, ax.damping, k0, SampledWallTheory.passivityLimit(ax.damping, 0.001, 1, 0));
        sweep(plant, k0, new File(docs, "haptics-stability-sweep.csv"));
        zwidth(plant, ax, new File(docs, "haptics-stability-zwidth.csv"), new File(docs, "haptics-stability-zwidth.png"));
        System.out.printf("%nsweep took %.0f s of wall-clock time%n", (System.nanoTime() - t0) * 1e-9);
    }

    private static void theory(File csv) throws IOException {
        double[][] points = {
            {2e-3, 0.0005, 0}, {2e-3, 0.001, 0}, {2e-3, 0.002, 0},
            {5e-3, 0.0005, 0}, {5e-3, 0.001, 0}, {5e-3, 0.002, 0},
            {1e-2, 0.0005, 0}, {1e-2, 0.001, 0}, {1e-2, 0.002, 0},
            {5e-3, 0.001, 0.2}, {5e-3, 0.001, 0.4}, {1e-2, 0.001, 0.5},
        };
        System.out.println("| joint b (N m s/rad) | m (kg) | b (N s/m) | T (ms) | B (N s/m) | 2b/T | exact, d = 0 | 2b/(3T) "
                + "| theory, d = 1 | emulator, d = 1 | emulator / theory | passivity, d = 1 |");
        System.out.println("|---|---|---|---|---|---|---|---|---|---|---|---|");
        try (PrintWriter w = new PrintWriter(csv, StandardCharsets.UTF_8)) {
            w.println("joint_damping_Nms_per_rad,mass_kg,damping_Ns_per_m,period_s,wall_damping_Ns_per_m,two_b_over_T,"
                    + "theory_d0,two_b_over_3T,theory_d1,emulator_d1,emulator_over_theory,passivity_d1");
            for (double[] pt : points) {
                WallRig.Config c = springConfig(PlantParameters.twoDiy().withoutFriction().withJointDamping(pt[0]),
                        WallRig.UNCONTROLLED, 0, pt[2]);
                c.period = pt[1];
                c.encoderScale = 64;
                c.ticks = (int) Math.round(2.0 / c.period);
                EffectiveAxis ax = EffectiveAxis.atEquilibrium(c);
                double m = ax.mass;
                double b = ax.damping;
                double T = c.period;
                double th0 = SampledWallTheory.stiffnessLimit(m, b, T, 0, c.damping);
                double th1 = SampledWallTheory.stiffnessLimit(m, b, T, 1, c.damping);
                double em = EmulatorBoundary.find(c, 0.85 * th1, 1.2 * th1, 0.005);
                double pass = SampledWallTheory.passivityLimit(b, T, 1, c.damping);
                w.printf("%g,%g,%g,%g,%g,%g,%g,%g,%g,%g,%g,%g%n", pt[0], m, b, T, c.damping, 2 * b / T, th0,
                        2 * b / (3 * T), th1, em, em / th1, pass);
                System.out.printf("| %.0e | %.4f | %.3f | %.1f | %.2f | %.0f | %.0f | %.0f | %.1f | %.1f | %.3f | %.1f |%n",
                        pt[0], m, b, T * 1e3, c.damping, 2 * b / T, th0, 2 * b / (3 * T), th1, em, em / th1, pass);
            }
        }
    }

    private static void sweep(PlantParameters plant, double k0, File csv) throws IOException {
        System.out.println("| variant | hand | K / K0 | K (N/m) | stable | peak (mm) | residual (mm) | growth "
                + "| energy to hand (mJ) | felt K / K | force step (N) |");
        System.out.println("|---|---|---|---|---|---|---|---|---|---|---|");
        try (PrintWriter w = new PrintWriter(csv, StandardCharsets.UTF_8)) {
            w.println("variant,hand,multiple,stiffness_N_per_m,stable,peak_m,residual_m,growth,energy_to_hand_J,felt_fraction,"
                    + "force_step_N");
            for (WallRig.Variant v : VARIANTS) {
                for (boolean withHand : new boolean[] {false, true}) {
                    for (double mult : MULTIPLES) {
                        double k = mult * k0;
                        WallRig.Config c = withHand ? pressConfig(plant, v, k, 0) : springConfig(plant, v, k, 0);
                        WallRig.Trace t = WallRig.run(c);
                        Touch r = EmulatorBoundary.judge(c, t);
                        String hand = withHand ? "pen grip" : "none";
                        w.printf("%s,%s,%g,%g,%b,%g,%g,%g,%g,%g,%g%n", v.name(), hand, mult, k, r.stable, r.peak,
                                r.residual, r.growth, r.energyToHand, r.feltFraction, t.forceStep);
                        System.out.printf("| %s | %s | %.1f | %.0f | %s | %.3f | %.4f | %s | %s | %s | %.2f |%n", v.name(),
                                hand, mult, k, r.stable ? "yes" : "**no**", r.peak * 1e3, r.residual * 1e3,
                                fmt(r.growth, "%.2f"), fmt(r.energyToHand * 1e3, "%.3f"), fmt(r.feltFraction, "%.2f"),
                                t.forceStep);
                    }
                }
            }
        }
    }

    private static String fmt(double v, String f) {
        return Double.isNaN(v) ? "n/a" : String.format(f, v);
    }

    private static void zwidth(PlantParameters plant, EffectiveAxis ax, File csv, File png) throws IOException {
        double[] fractions = {0, 0.25, 0.5, 0.75, 1.0, 1.5, 2.0};
        int nb = fractions.length;
        double[] bs = new double[nb];
        double[] theory = new double[nb];
        double[] pass = new double[nb];
        List<double[]> noHand = new ArrayList<>();
        List<double[]> hand = new ArrayList<>();
        for (int i = 0; i < nb; i++) {
            bs[i] = fractions[i] * ax.damping;
            theory[i] = SampledWallTheory.stiffnessLimit(ax.mass, ax.damping, 0.001, 1, bs[i]);
            pass[i] = SampledWallTheory.passivityLimit(ax.damping, 0.001, 1, bs[i]);
        }
        System.out.println();
        System.out.println("| variant | B (N s/m) | theory, linear plant (N/m) | passivity (N/m) | emulator, no hand (N/m) "
                + "| emulator, pen grip: last stable K of the scan (N/m) | pen grip: felt there (N/m) |");
        System.out.println("|---|---|---|---|---|---|---|");
        LineChart chart = new LineChart("Z-width of the emulated 2DIY with a pen grip (T = 1 ms, one tick of delay)",
                "wall damping B (N s/m)", "stiffness the hand feels at the stiffest stable wall (N/m)")
                .markers(true).logY(true);
        double scanTop = HAND_GRID[HAND_GRID.length - 1] * theory[0];
        try (PrintWriter w = new PrintWriter(csv, StandardCharsets.UTF_8)) {
            w.println("variant,wall_damping_Ns_per_m,theory_N_per_m,passivity_N_per_m,emulator_no_hand_N_per_m,"
                    + "emulator_pen_grip_N_per_m,pen_grip_felt_N_per_m,pen_grip_stable_to_scan_top");
            for (WallRig.Variant v : VARIANTS) {
                double[] kn = new double[nb];
                double[] kh = new double[nb];
                double[] felt = new double[nb];
                for (int i = 0; i < nb; i++) {
                    double guess = Double.isFinite(theory[i]) ? theory[i] : ax.damping / 0.001;
                    kn[i] = EmulatorBoundary.find(springConfig(plant, v, 0, bs[i]), 0.5 * guess, 2 * guess, 0.02);
                    kh[i] = EmulatorBoundary.lastStable(pressConfig(plant, v, 0, bs[i]), HAND_GRID, theory[0]);
                    felt[i] = Double.NaN;
                    if (kh[i] > 0) {
                        WallRig.Config c = pressConfig(plant, v, kh[i], bs[i]);
                        Touch r = EmulatorBoundary.judge(c, WallRig.run(c));
                        felt[i] = r.feltFraction * kh[i];
                    }
                    boolean top = kh[i] >= scanTop * (1 - 1e-9);
                    w.printf("%s,%g,%g,%g,%g,%g,%g,%b%n", v.name(), bs[i], theory[i], pass[i], kn[i], kh[i], felt[i], top);
                    System.out.printf("| %s | %.3f | %.1f | %.1f | %.1f | %.0f%s | %.0f |%n", v.name(), bs[i], theory[i],
                            pass[i], kn[i], kh[i], top ? " (scan's top)" : "", felt[i]);
                }
                ZWidthPoints z = ZWidthPoints.of(bs, kh, felt, scanTop);
                if (z.edgeB.length > 0) {
                    chart.series(v.name(), z.edgeB, z.edgeFelt);
                }
                chart.lowerBounds(v.name() + ", still stable at the scan's top (at least)", z.boundB, z.boundFelt);
            }
        }
        addSeries(chart, "theory: uncontrolled linear device alone (felt = K)", bs, theory);
        addSeries(chart, "passivity bound b > KT(d + 1/2) + |B| (none from B = b on)", bs, pass);
        chart.note(String.format(Locale.ROOT, "Emulator only, no real device measured. 2DIY plant as assumed: m = %.4f kg,"
                + " b = %.3f N s/m along y; Coulomb friction and a higher static threshold assumed (not measured);", ax.mass,
                ax.damping));
        chart.note("encoders 4880 counts/rev (about 148 um at the handle), 12-bit PWM, 0.123 N m clip; T = 1 ms, d = 1 tick."
                + " Pen grip assumed: 0.03 kg, 300 N/m, 2 N s/m, pressing at 20 mm/s.");
        chart.note(String.format(Locale.ROOT, "Felt = least-squares slope of the hand's push over the penetration while"
                + " pressing, at the stiffest wall of the scan 5..400 K0 (K0 = %.1f N/m) that stayed stable.", theory[0]));
        chart.save(png, 900, 640);
    }

    /** Adds the finite, positive points of a series (a log axis cannot show the others). */
    private static void addSeries(LineChart chart, String name, double[] xs, double[] ys) {
        int n = 0;
        double[] x = new double[xs.length];
        double[] y = new double[ys.length];
        for (int i = 0; i < xs.length; i++) {
            if (Double.isFinite(ys[i]) && ys[i] > 0) {
                x[n] = xs[i];
                y[n] = ys[i];
                n++;
            }
        }
        chart.series(name, Arrays.copyOf(x, n), Arrays.copyOf(y, n));
    }
}
