package tactus.haptics;

import java.util.List;
import tactus.hapticstability.WallRig;

/**
 * The controlled variants of the stability sweep (docs/haptics-stability.md): the time-domain passivity controller,
 * a virtual coupling chosen from the device's damping and period, and both, each run as a {@link PortLink} around the
 * model's avatar (calibrated units: gains 1, no mirror), with the plant's exchange delay.
 */
public final class PassivityVariants {
    private PassivityVariants() {
    }

    /** One variant: a name and the port's options. */
    private static WallRig.Variant variant(String name, boolean control, double deviceDamping, int delayTicks, boolean coupled) {
        return new WallRig.Variant() {
            @Override
            public String name() {
                return name;
            }

            @Override
            public AvatarLink wrap(AvatarLink model, double period) {
                PortLink p = new PortLink(model, period, 1, 1, false).delay(delayTicks).control(control);
                if (coupled) {
                    p.coupling(VirtualCoupling.forDevice(deviceDamping, period, delayTicks));
                }
                return p;
            }
        };
    }

    /**
     * The passivity controller ("passivity control"), the coupling ("virtual coupling") and both ("coupling + PC"),
     * for a device of this damping along the wall's axis (N s/m) and exchange delay (ticks).
     */
    public static List<WallRig.Variant> all(double deviceDamping, int delayTicks) {
        return List.of(variant("passivity control", true, deviceDamping, delayTicks, false),
                variant("virtual coupling", false, deviceDamping, delayTicks, true),
                variant("coupling + PC", true, deviceDamping, delayTicks, true));
    }
}
