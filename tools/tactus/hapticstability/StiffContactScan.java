package tactus.hapticstability;

import java.util.Locale;
import tactus.haptics.AvatarLink;
import tactus.haptics.emulator.PlantParameters;

/**
 * The energy bound ({@code HapticLoop.useStiffContacts}) on the sweep's pen-grip press through the real loop on the
 * emulated 2DIY: per wall (args: multiples of K0 = 40.7 N/m), stability, the stiffness felt while holding, the energy
 * the plant gave the hand (at the end and the most at any instant) and the largest force step. System properties:
 * kb (the bound's stiffness, N/m; default the wall's), seed (J), rise (N), scale (encoder counts multiplied),
 * period (s), uncontrolled (true: no bound), play (false: no contact play), hand (m,k,b of the grip), trace,
 * ticks/from/to (print per tick). docs/haptics-stability.md, "Stiff contacts".
 */
public final class StiffContactScan {
    private StiffContactScan() {
    }

    static WallRig.Variant bound(double kb, double seed, double rise) {
        return new WallRig.Variant() {
            @Override
            public String name() {
                return "bound";
            }

            @Override
            public AvatarLink wrap(AvatarLink model, double period) {
                PortLink p = new PortLink(model, period, 1, 1, false).delay(1).energyBound(kb).energyBoundSeed(seed)
                        .forceRiseLimit(rise);
                if (!"false".equals(System.getProperty("play"))) {   // the contact play, as useStiffContacts sets it
                    double[] q = PassivityVariants.twoDiyQuantum();   // finer encoders: a smaller count
                    double w = tactus.haptics.HapticLoop.CONTACT_PLAY_COUNTS
                            / Double.parseDouble(System.getProperty("scale", "1"));
                    p.contactPlay(w * q[0], w * q[1], 0);
                }
                if (!Boolean.getBoolean("ticks")) {
                    return p;
                }
                return new ForwardingAvatarLink(p) {
                    int n;
                    double y;
                    double fm;

                    @Override
                    public void setTarget(double x, double yy, double z) {
                        super.setTarget(x, yy, z);
                        y = yy;
                    }

                    @Override
                    public long takeForceCounted(double[] out) {
                        long r = super.takeForceCounted(out);
                        n++;
                        if (n >= Integer.getInteger("from", 200) && n < Integer.getInteger("to", 300)) {
                            System.out.printf("    n %d y %.1f um F %.3f budget %.4f mJ%n", n, y * 1e6, out[1],
                                    p.port().energyBudget() * 1e3);
                        }
                        return r;
                    }
                };
            }
        };
    }

    /** Felt stiffness while holding (N/m): mean hand force over mean penetration in the hold window. */
    public static double feltHolding(WallRig.Config c, WallRig.Trace t) {
        double wall = WallRig.wallY(c);
        double sf = 0, sp = 0;
        for (int i = 0; i < t.n; i++) {
            if (t.t[i] >= EmulatorBoundary.HOLD_FROM && t.t[i] <= EmulatorBoundary.HOLD_TO) {
                sf += -t.fy[i];
                sp += wall - t.y[i];
            }
        }
        return sf / sp;
    }

    /** The largest energy (J) the device had given the hand at any instant (running sum of -F_hand . v dt). */
    public static double peakEnergyToHand(WallRig.Trace t) {
        double e = 0, peak = 0;
        for (int i = 1; i < t.n; i++) {
            e += -(t.fx[i] * t.vx[i] + t.fy[i] * t.vy[i]) * (t.t[i] - t.t[i - 1]);
            peak = Math.max(peak, e);
        }
        return peak;
    }

    public static void main(String[] args) {
        Locale.setDefault(Locale.ROOT);
        double seed = Double.parseDouble(System.getProperty("seed", "1e-5"));
        double rise = Double.parseDouble(System.getProperty("rise", "0.5"));
        for (String a : args) {
            double k = Double.parseDouble(a) * 40.7;
            WallRig.Config c = StabilitySweep.pressConfig(PlantParameters.twoDiy(), bound(System.getProperty("kb") != null ? Double.parseDouble(System.getProperty("kb")) : k, seed, rise), k, 0);
            if (Boolean.getBoolean("uncontrolled")) {
                c.variant = WallRig.UNCONTROLLED;
            }
            String hand = System.getProperty("hand");   // m,k,b of the grip (kg, N/m, N s/m); default the pen grip
            if (hand != null) {
                String[] h = hand.split(",");
                c.hand = tactus.haptics.emulator.Hand.grasp(StabilitySweep.press(c.preset.d() / 2, WallRig.START_Y, c.gap,
                        0.003), Double.parseDouble(h[0]), Double.parseDouble(h[1]), Double.parseDouble(h[2]));
            }
            c.encoderScale = Float.parseFloat(System.getProperty("scale", "1"));
            c.period = Double.parseDouble(System.getProperty("period", "0.001"));
            c.ticks = (int) Math.round(1.8 / c.period);
            WallRig.Trace t = WallRig.run(c);
            Touch r = EmulatorBoundary.judge(c, t);
            System.out.printf("K %s K0 %.0f N/m: stable %b residual %.2f um, felt(hold) %.0f N/m, feltSlope %.2f, "
                    + "energy end %.4f mJ peak %.4f mJ, step %.3f N%n", a, k, r.stable, r.residual * 1e6,
                    feltHolding(c, t), r.feltFraction, r.energyToHand * 1e3, peakEnergyToHand(t) * 1e3, t.forceStep);
            if (Boolean.getBoolean("trace")) {
                double wall = WallRig.wallY(c);
                int every = Integer.getInteger("every", 400);
                for (int i = 0; i < t.n; i += every) {
                    System.out.printf("  t %.4f pen %.1f um  Fhand %.3f N%n", t.t[i], (wall - t.y[i]) * 1e6, -t.fy[i]);
                }
            }
        }
    }
}
