package tactus.hapticstability;

import java.util.Locale;
import tactus.haptics.emulator.PlantParameters;
import tactus.haptics.passivity.VirtualCoupling;
import tactus.haptics.AvatarLink;

/**
 * Why the passivity controller alone loses the pen-grip wall (docs/haptics-stability.md, "Passivity control"): runs
 * the sweep's press on the 2DIY plant with the controller at several damping limits, and the coupling sized for the
 * grip with the controller, over walls of 0.1 to 400 K0, and prints per run the verdict, the energy to the hand, the
 * felt stiffness, the share of ticks at which the controller acted and the share at which it acted at its limit
 * (saturated), and the largest change of the force sent from one tick to the next (a buzz the position hardly shows). Simulated time, deterministic. Run: the class's main with the tools classpath.
 */
public final class PenGripDiagnosis {
    /** The uncontrolled bound of the 2DIY plant as assumed (theory, d = 1), N/m. */
    private static final double K0 = 40.7;

    private PenGripDiagnosis() {
    }

    /** A variant that counts, on the loop's thread, the ticks with damping and those with damping at the limit. */
    private static WallRig.Variant counting(String name, double limit, double tolerance, VirtualCoupling coupling,
                                            long[] counts, double[] step) {
        return new WallRig.Variant() {
            @Override
            public String name() {
                return name;
            }

            @Override
            public AvatarLink wrap(AvatarLink model, double period) {
                PortLink p = new PortLink(model, period, 1, 1, false).delay(1).control(true).dampingLimit(limit)
                        .tolerance(tolerance);
                if (coupling != null) {
                    p.coupling(coupling);
                }
                return new ForwardingAvatarLink(p) {
                    @Override
                    public long takeForceCounted(double[] out) {
                        long n = inner.takeForceCounted(out);
                        double alpha = p.observer().damping();
                        counts[0]++;
                        counts[1] += alpha > 0 ? 1 : 0;
                        counts[2] += alpha >= 0.999 * limit ? 1 : 0;
                        step[0] = Math.max(step[0], Math.hypot(out[0] - step[1], out[1] - step[2]));
                        step[1] = out[0];
                        step[2] = out[1];
                        return n;
                    }
                };
            }
        };
    }

    private static void scan(String name, double limit, double tolerance, VirtualCoupling coupling) {
        for (double m : new double[] {0.1, 1, 5, 14, 20, 28, 40, 56, 80, 120, 200, 280, 400}) {
            long[] counts = new long[3];
            double[] step = new double[3];
            WallRig.Config c = StabilitySweep.pressConfig(PlantParameters.twoDiy(),
                    counting(name, limit, tolerance, coupling, counts, step), m * K0, 0);
            WallRig.Trace t = WallRig.run(c);
            Touch r = EmulatorBoundary.judge(c, t);
            System.out.printf("| %s | %.0f | %.1f | %.1f | %.0f | %s | %.4f | %.3f | %.3f | %.1f %% | %.1f %% | %.2f |%n", name,
                    limit, tolerance * 1e3, m, c.stiffness, r.stable ? "yes" : "**no**", r.residual * 1e3,
                    r.energyToHand * 1e3, r.feltFraction, 100.0 * counts[1] / counts[0], 100.0 * counts[2] / counts[0],
                    step[0]);
        }
    }

    /**
     * Prints the Markdown table; with arguments "k c" (N/m, N s/m) scans only a grip coupling of that stiffness and
     * damping (with the controller).
     */
    public static void main(String[] args) {
        Locale.setDefault(Locale.ROOT);
        if (args.length == 3) {
            double k = Double.parseDouble(args[0]);
            double c = Double.parseDouble(args[1]);
            scan("coupling " + k + " N/m, " + c + " N s/m + PC", 10, Double.parseDouble(args[2]),
                    VirtualCoupling.forContacts(k, c, PassivityVariants.GRIP_LARGEST_CONTACT, 1e-3));
            return;
        }
        System.out.println("| variant | damping limit (N s/m) | tolerance (mJ) | K / K0 | K (N/m) | stable | residual (mm) "
                + "| energy to hand (mJ) | felt K / K | controller active | at its limit | largest force step (N) |");
        System.out.println("|---|---|---|---|---|---|---|---|---|---|---|---|");
        for (double limit : new double[] {10, 20, 50}) {
            scan("passivity control", limit, 0, null);
        }
        scan("passivity control", 10, 1e-3, null);
        scan("grip coupling + PC", 10, 0, VirtualCoupling.forContacts(PassivityVariants.GRIP_COUPLING_STIFFNESS,
                PassivityVariants.GRIP_COUPLING_DAMPING,
                PassivityVariants.GRIP_LARGEST_CONTACT, 1e-3));
        scan("grip coupling + PC", 10, 1e-3, VirtualCoupling.forContacts(PassivityVariants.GRIP_COUPLING_STIFFNESS,
                PassivityVariants.GRIP_COUPLING_DAMPING, PassivityVariants.GRIP_LARGEST_CONTACT, 1e-3));
    }
}
