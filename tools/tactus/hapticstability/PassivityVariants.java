package tactus.hapticstability;

import java.util.List;
import java.util.function.DoubleFunction;
import tactus.haptics.passivity.VirtualCoupling;
import tactus.haptics.AvatarLink;

/**
 * The controlled variants of the stability sweep (docs/haptics-stability.md): the time-domain passivity controller,
 * a virtual coupling chosen from the device's damping and period, and both, each run as a {@link PortLink} around the
 * model's avatar (calibrated units: gains 1, no mirror), with the plant's exchange delay.
 */
public final class PassivityVariants {
    private PassivityVariants() {
    }

    /**
     * The coupling sized for a pen grip on the 2DIY (with the controller on): about the stiffest wall the grip holds
     * without control (814 N/m), with damping (1 N s/m, 16 times the device's) that the controller keeps passive, and
     * a proxy for contacts to 20 kN/m; chosen from the scan in docs/haptics-stability.md (`PenGripDiagnosis`).
     */
    static final double GRIP_COUPLING_STIFFNESS = 800;
    /** Its damping, N s/m. */
    static final double GRIP_COUPLING_DAMPING = 1;
    /**
     * The controller's tolerance with the grip coupling, J: without it the controller chases the energy the encoders'
     * steps seem to create through the stiff coupling and damps in bursts (a buzz of about 1.7 N, measured).
     */
    static final double GRIP_TOLERANCE = 1e-3;
    /** The largest contact (N/m) the grip coupling's proxy is sized for. */
    static final double GRIP_LARGEST_CONTACT = 20_000;

    /** One variant: a name and the port's options. */
    private static WallRig.Variant variant(String name, boolean control, double deviceDamping, int delayTicks, boolean coupled) {
        return variant(name, control, delayTicks, coupled ? t -> VirtualCoupling.forDevice(deviceDamping, t, delayTicks) : null);
    }

    /** One variant with the coupling made for the period (s) by this function (null: no coupling). */
    private static WallRig.Variant variant(String name, boolean control, int delayTicks,
                                           DoubleFunction<VirtualCoupling> coupling) {
        return variant(name, control, 0, delayTicks, coupling);
    }

    private static WallRig.Variant variant(String name, boolean control, double tolerance, int delayTicks,
                                           DoubleFunction<VirtualCoupling> coupling) {
        return new WallRig.Variant() {
            @Override
            public String name() {
                return name;
            }

            @Override
            public AvatarLink wrap(AvatarLink model, double period) {
                PortLink p = new PortLink(model, period, 1, 1, false).delay(delayTicks).control(control)
                        .tolerance(tolerance);
                if (coupling != null) {
                    p.coupling(coupling.apply(period));
                }
                return p;
            }
        };
    }

    /**
     * The recommended configuration for stiff walls ("stiff contacts"): the energy bound at
     * {@code HapticLoop.TWO_DIY_STIFF_CONTACT}, its seed, its rise limit and the contact play, as
     * {@code HapticLoop.useStiffContacts} sets them, with the plant's exchange delay.
     */
    static WallRig.Variant stiffContacts(int delayTicks) {
        return new WallRig.Variant() {
            @Override
            public String name() {
                return "stiff contacts";
            }

            @Override
            public AvatarLink wrap(AvatarLink model, double period) {
                double[] q = twoDiyQuantum();
                double w = tactus.haptics.HapticLoop.CONTACT_PLAY_COUNTS;
                return new PortLink(model, period, 1, 1, false).delay(delayTicks)
                        .energyBound(tactus.haptics.HapticLoop.TWO_DIY_STIFF_CONTACT).energyBoundSeed(1e-5)
                        .forceRiseLimit(0.5).contactPlay(w * q[0], w * q[1], 0);
            }
        };
    }

    /** The 2DIY's position quantum (m, x and y) at the sweep's pose, as {@code PantographDevice} computes it. */
    static double[] twoDiyQuantum() {
        tactus.haptics.HaplyPreset preset = tactus.haptics.HaplyPreset.TWO_DIY_V3;
        tactus.haptics.pantograph.PantographKinematics k = preset.newKinematics();
        double[] th = new double[2];
        if (!k.inverse(preset.d() / 2, WallRig.START_Y, th) || !k.forward(th[0], th[1])) {
            throw new IllegalStateException("PassivityVariants: the sweep's pose is out of the 2DIY's reach");
        }
        double[] q = new double[2];
        k.quantum(2 * Math.PI / preset.encoderResolution(1), 2 * Math.PI / preset.encoderResolution(2), q);
        return q;
    }

    /**
     * The passivity controller ("passivity control"), the coupling ("virtual coupling"), both ("coupling + PC") and
     * the coupling sized for the grip with the controller and its 1 mJ tolerance ("grip coupling + PC") and the
     * recommended configuration for stiff walls ("stiff contacts", {@link #stiffContacts}), for a device
     * of this damping along the wall's axis (N s/m) and exchange delay (ticks).
     */
    public static List<WallRig.Variant> all(double deviceDamping, int delayTicks) {
        return List.of(variant("passivity control", true, deviceDamping, delayTicks, false),
                variant("virtual coupling", false, deviceDamping, delayTicks, true),
                variant("coupling + PC", true, deviceDamping, delayTicks, true),
                variant("grip coupling + PC", true, GRIP_TOLERANCE, delayTicks,
                        t -> VirtualCoupling.forContacts(GRIP_COUPLING_STIFFNESS, GRIP_COUPLING_DAMPING,
                                GRIP_LARGEST_CONTACT, t)),
                stiffContacts(delayTicks));
    }
}
