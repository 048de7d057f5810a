package tactus.hapticstability;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.function.Consumer;
import tactus.haptics.HapticLoop;
import tactus.haptics.passivity.VirtualCoupling;

/**
 * The adversarial suite of hands and walls (docs/haptics-stability.md, "The adversarial suite"): the cases that try
 * to break a configuration of the haptic loop, the configurations that existed before the recommended one, and a
 * main that runs every case on each and prints the Markdown table (simulated time; each run takes its simulated
 * length, about 1 s). Run: {@code gradle adversarialSuite}.
 */
public final class AdversarialSuite {
    /**
     * The largest energy the hand may receive (J): the numerical floor of the energy count on passive runs (the
     * energy integral over the plant's 50 microsecond substeps, the encoders' steps through a wall the loop renders
     * well inside its bound) is below 2 microjoules; 10 microjoules is five times that and a fifth of 0.05 mJ.
     */
    public static final double ENERGY_TOLERANCE = 1e-5;
    /**
     * The largest force step between ticks (N) that is not a buzz; a step is checked against it with a rounding margin
     * of 1 nN ({@link #withinStepLimit}), as the loop's own limit of 0.5 N comes out at 0.5 N plus rounding.
     */
    public static final double FORCE_STEP_LIMIT = 0.5;

    /** True if the force step (N) is within {@link #FORCE_STEP_LIMIT}, up to 1 nN of rounding. */
    public static boolean withinStepLimit(double step) {
        return step <= FORCE_STEP_LIMIT + 1e-9;
    }

    private AdversarialSuite() {
    }

    /** No control: the model's force goes to the device as it is. */
    public static final Consumer<HapticLoop> UNCONTROLLED = loop -> {
    };

    /** The passivity controller alone, told of the exchange's one tick of delay. */
    public static final Consumer<HapticLoop> PASSIVITY_CONTROL = loop -> {
        loop.setExchangeDelay(1);
        loop.setPassivityControl(true);
    };

    /** The coupling sized for the pen grip (800 N/m, 1 N s/m) with the controller and its 1 mJ tolerance. */
    public static final Consumer<HapticLoop> GRIP_COUPLING_PC = loop -> {
        loop.setExchangeDelay(1);
        loop.setVirtualCoupling(VirtualCoupling.forContacts(PassivityVariants.GRIP_COUPLING_STIFFNESS,
                PassivityVariants.GRIP_COUPLING_DAMPING, PassivityVariants.GRIP_LARGEST_CONTACT, 1.0 / loop.rate()));
        loop.setPassivityTolerance(PassivityVariants.GRIP_TOLERANCE);
        loop.setPassivityControl(true);
    };

    /** The energy bound at the 2DIY's stiff contact without its count reserve: {@code useStiffContacts(1600)}. */
    public static final Consumer<HapticLoop> STIFF_CONTACTS = loop -> {
        loop.setExchangeDelay(1);
        loop.useStiffContacts(HapticLoop.TWO_DIY_STIFF_CONTACT);
    };

    /**
     * The recommended call on the 2DIY, {@code useStiffContacts()} with one tick of exchange delay: the bound at
     * {@link HapticLoop#TWO_DIY_STIFF_CONTACT} with its count reserve at {@link HapticLoop#ROBUST_COUNT_RESERVE} (no wall
     * lost to encoder flicker, at the price of a softer onset).
     */
    public static final Consumer<HapticLoop> STIFF_CONTACTS_COUNT_RESERVE = loop -> {
        loop.setExchangeDelay(1);
        loop.useStiffContacts();
    };

    /**
     * The recommended configuration on the emulated 3-DoF device in lockstep ({@link AdversarialRig3D}: no tick of
     * delay, positions not quantised): {@code useStiffContacts()}, which picks
     * {@link HapticLoop#INVERSE3_STIFF_CONTACT} on a 3-DoF device.
     */
    public static final Consumer<HapticLoop> STIFF_CONTACTS_3DOF = loop -> {
        loop.setExchangeDelay(0);
        loop.useStiffContacts();
    };

    /**
     * The energy bound as it was before the hold compensation and the trim of 2: {@link #STIFF_CONTACTS_3DOF} with the
     * compensation off and the trim at 8, with half the plant's damping declared
     * ({@link HapticLoop#setDeviceDissipation}: 0.25 of its 0.5 N s/m).
     */
    public static final Consumer<HapticLoop> STIFF_CONTACTS_3DOF_DECLARED = loop -> {
        STIFF_CONTACTS_3DOF.accept(loop);
        loop.setHoldCompensation(false);
        loop.setEnergyBoundTrim(8);
        loop.setDeviceDissipation(0.25, 0);
    };

    /** The configurations of the 3-DoF table ({@code --3dof}), by name. */
    public static Map<String, Consumer<HapticLoop>> configurations3D() {
        Map<String, Consumer<HapticLoop>> m = new LinkedHashMap<>();
        m.put("uncontrolled", UNCONTROLLED);
        m.put("bound, trim 8, 0.25 N s/m declared", STIFF_CONTACTS_3DOF_DECLARED);
        m.put("stiff contacts 3-DoF", STIFF_CONTACTS_3DOF);
        return m;
    }

    /** The configurations of the table, by name. */
    public static Map<String, Consumer<HapticLoop>> configurations() {
        Map<String, Consumer<HapticLoop>> m = new LinkedHashMap<>();
        m.put("uncontrolled", UNCONTROLLED);
        m.put("passivity control", PASSIVITY_CONTROL);
        m.put("grip coupling + PC", GRIP_COUPLING_PC);
        m.put("stiff contacts", STIFF_CONTACTS);
        m.put("stiff contacts + count reserve", STIFF_CONTACTS_COUNT_RESERVE);
        return m;
    }

    /** A case with friction and no shift. */
    private static AdversarialCase of(AdversarialCase.Kind kind, AdversarialCase.Grip grip, double multiple,
                                      double speed) {
        return new AdversarialCase(kind, grip, multiple * AdversarialCase.K0, speed, true, 0);
    }

    /**
     * The suite's cases: every scene with the pen grip at 200 K0, and with friction or without; the grips from a
     * stiff pinch to a loose hold on presses and wall changes; taps from 50 to 200 mm/s; slow presses at 5 and 20 mm/s;
     * walls of 20, 80, 200 and 400 K0; a wall change at another phase of the tick.
     */
    public static List<AdversarialCase> cases() {
        List<AdversarialCase> l = new ArrayList<>();
        AdversarialCase.Grip pen = AdversarialCase.Grip.PEN;
        for (AdversarialCase.Kind k : new AdversarialCase.Kind[] {AdversarialCase.Kind.SWITCH_ON,
                AdversarialCase.Kind.MOVE_IN, AdversarialCase.Kind.RELEASE}) {
            l.add(of(k, pen, 200, 0.02));
        }
        l.add(of(AdversarialCase.Kind.STIFFEN, pen, 200, 0.02));
        l.add(of(AdversarialCase.Kind.STIFFEN, pen, 400, 0.02));
        for (double m : new double[] {20, 80, 200, 400}) {
            l.add(of(AdversarialCase.Kind.PRESS, pen, m, 0.02));
        }
        l.add(of(AdversarialCase.Kind.PRESS, pen, 200, 0.005));
        for (double v : new double[] {0.05, 0.2}) {
            l.add(of(AdversarialCase.Kind.TAP, pen, 200, v));
        }
        for (AdversarialCase.Grip g : new AdversarialCase.Grip[] {AdversarialCase.Grip.STIFF_PINCH,
                AdversarialCase.Grip.LOOSE_HOLD}) {
            l.add(of(AdversarialCase.Kind.PRESS, g, 200, 0.02));
            l.add(of(AdversarialCase.Kind.SWITCH_ON, g, 200, 0.02));
            l.add(of(AdversarialCase.Kind.TAP, g, 400, 0.1));
        }
        l.add(of(AdversarialCase.Kind.PRESS, AdversarialCase.Grip.LOOSE_HOLD, 400, 0.005));
        for (AdversarialCase.Kind k : new AdversarialCase.Kind[] {AdversarialCase.Kind.PRESS,
                AdversarialCase.Kind.SWITCH_ON, AdversarialCase.Kind.STIFFEN, AdversarialCase.Kind.TAP}) {
            l.add(new AdversarialCase(k, pen, 200 * AdversarialCase.K0, k == AdversarialCase.Kind.TAP ? 0.1 : 0.02,
                    false, 0));
        }
        l.add(new AdversarialCase(AdversarialCase.Kind.SWITCH_ON, pen, 400 * AdversarialCase.K0, 0.02, true, 0.00037));
        return l;
    }

    /**
     * The least felt stiffness, as a fraction of the wall's stiffness or of the stiffest wall the pen grip holds without
     * control (20 K0), whichever is smaller, for a press or a stiffened wall: a configuration that passes by not
     * rendering the wall fails here.
     */
    public static final double FELT_FRACTION = 0.5;

    /** The least felt stiffness for this case (N/m); 0 where the suite does not ask for one. */
    public static double feltFloor(AdversarialCase c) {
        if (c.kind != AdversarialCase.Kind.PRESS && c.kind != AdversarialCase.Kind.STIFFEN) {
            return 0;   // taps and releases have no hold; a wall that appears around the handle need not push it out
        }
        return FELT_FRACTION * Math.min(c.stiffness, 20 * AdversarialCase.K0);
    }

    /**
     * True if the run passes: stable, energy to the hand within the tolerance, force steps within the limit, no tick
     * at which the loop refused the force (a wall the loop's force limit zeroes is not rendered at all), and the wall
     * felt at least {@link #feltFloor}.
     */
    public static boolean passes(AdversarialRig.Result r) {
        return passes(r, Touch.RESIDUAL_LIMIT);
    }

    /**
     * As {@link #passes(AdversarialRig.Result)} with another stillness limit (m): the loop did not fail and the
     * residual is below {@code stillness} instead of {@link Touch#RESIDUAL_LIMIT}.
     */
    public static boolean passes(AdversarialRig.Result r, double stillness) {
        double floor = feltFloor(r.c);
        return r.failure == null && r.residual < stillness && r.maxEnergyToHand <= ENERGY_TOLERANCE
                && withinStepLimit(r.forceStep) && r.faultTicks == 0 && (floor == 0 || r.felt >= floor);
    }

    /** One Markdown row of the table. */
    public static String row(String configuration, AdversarialRig.Result r) {
        return String.format(Locale.ROOT, "| %s | %s | %s | %.4f | %.4f | %.4f | %.2f (%s) | %d | %s | %s | %s |",
                configuration, r.c.label(), r.stable ? "yes" : String.format(Locale.ROOT, "**no** (%.1f um)",
                        r.residual * 1e6), r.maxEnergyToHand * 1e3, r.endEnergyToHand * 1e3,
                r.observerMaxEnergyToHand * 1e3, r.forceStep, r.forceStepRises ? "rise" : "fall", r.faultTicks,
                Double.isNaN(r.felt) ? "-" : String.format(Locale.ROOT, "%.0f", r.felt),
                Double.isNaN(r.feltSlope) ? "-" : String.format(Locale.ROOT, "%.0f", r.feltSlope),
                passes(r) ? "pass" : "**fails**");
    }

    /** The table's header. */
    public static final String HEADER = "| configuration | case | stable | max energy to hand (mJ) | at the end (mJ) "
            + "| observer's max (mJ) | largest force step (N) | refused ticks | felt (N/m) | press slope (N/m) | verdict |\n"
            + "|---|---|---|---|---|---|---|---|---|---|---|";

    /**
     * Prints the table for every configuration (or those whose names are given) over every case; with {@code --3dof}
     * first, on the emulated 3-DoF device ({@link AdversarialRig3D}) and its configurations.
     */
    public static void main(String[] args) {
        Locale.setDefault(Locale.ROOT);
        boolean threeDof = args.length > 0 && args[0].equals("--3dof");
        List<String> names = List.of(args).subList(threeDof ? 1 : 0, args.length);
        System.out.println(HEADER);
        for (Map.Entry<String, Consumer<HapticLoop>> e : (threeDof ? configurations3D() : configurations()).entrySet()) {
            if (!names.isEmpty() && !names.contains(e.getKey())) {
                continue;
            }
            int failed = 0;
            List<AdversarialCase> cs = cases();
            for (AdversarialCase c : cs) {
                AdversarialRig.Result r = threeDof ? AdversarialRig3D.run(c, e.getValue())
                        : AdversarialRig.run(c, e.getValue());
                failed += passes(r) ? 0 : 1;
                System.out.println(row(e.getKey(), r));
            }
            System.out.printf("%n%s: %d of %d cases fail%n%n", e.getKey(), failed, cs.size());
        }
    }
}
