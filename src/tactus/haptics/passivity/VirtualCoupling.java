package tactus.haptics.passivity;

import tactus.haptics.HapticLoop;

/**
 * A virtual coupling (Colgate, Stanley &amp; Brown 1995; Adams &amp; Hannaford 1999): a spring-damper between the handle
 * and a small proxy mass, and the model's avatar follows the proxy instead of the handle. The model pushes the proxy;
 * the hand feels only the coupling. However stiff a contact in the model is, the handle never feels more than the
 * coupling's stiffness, which is chosen so that the sampled loop stays passive on the device
 * ({@link #forDevice}); the proxy, integrated at the loop's rate, carries the stiff contact. The price: a wall feels
 * at most as stiff as the coupling (a contact K in series with the coupling k feels like K k / (K + k)), and the
 * proxy's mass adds to the handle's inertia.
 *
 * <p>Immutable settings, in newtons, metres, seconds and kilograms along the device's axes; give them to
 * {@link HapticLoop#setVirtualCoupling(VirtualCoupling)}, before the loop starts or while it runs.
 */
public final class VirtualCoupling {
    private final double stiffness;
    private final double damping;
    private final double mass;

    /**
     * A coupling of this stiffness (N/m, > 0) and damping (N s/m, >= 0) to a proxy of this mass (kg, > 0).
     *
     * @throws IllegalArgumentException naming the value when one is out of range or not finite
     */
    public VirtualCoupling(double stiffness, double damping, double mass) {
        if (!(stiffness > 0) || !Double.isFinite(stiffness)) {
            throw new IllegalArgumentException("VirtualCoupling: stiffness must be a finite number > 0 N/m, got " + stiffness);
        }
        if (!(damping >= 0) || !Double.isFinite(damping)) {
            throw new IllegalArgumentException("VirtualCoupling: damping must be a finite number >= 0 N s/m, got " + damping);
        }
        if (!(mass > 0) || !Double.isFinite(mass)) {
            throw new IllegalArgumentException("VirtualCoupling: mass must be a finite number > 0 kg, got " + mass);
        }
        this.stiffness = stiffness;
        this.damping = damping;
        this.mass = mass;
    }

    /**
     * The coupling for a device of physical damping b (N s/m, > 0) driven at period T (s, > 0) with d ticks of delay
     * between reading the position and the force taking effect (>= 0; 0 for a hold alone). The sampled spring-damper
     * (k, c) is passive on the device while {@code b > k T (d + 1/2) + c} (Colgate &amp; Schenkel 1997, with the delay);
     * this takes c = b / 4 and half of the stiffness that bound allows, {@code k = (b - c) / (2 T (d + 1/2))}, and a
     * proxy of {@code m = 25 k T^2 (d + 1)^2} kg: the proxy, integrated explicitly at the loop's rate, stays stable
     * against contacts up to {@code 4 m / T^2 = 100 (d + 1)^2 k} (see docs/haptics-stability.md, "Passivity
     * control").
     *
     * @throws IllegalArgumentException naming the value when one is out of range
     */
    public static VirtualCoupling forDevice(double deviceDamping, double periodSeconds, int delayTicks) {
        if (!(deviceDamping > 0) || !Double.isFinite(deviceDamping)) {
            throw new IllegalArgumentException("VirtualCoupling.forDevice: device damping must be a finite number > 0 N s/m, got "
                    + deviceDamping);
        }
        if (!(periodSeconds > 0) || !Double.isFinite(periodSeconds)) {
            throw new IllegalArgumentException("VirtualCoupling.forDevice: period must be a finite number > 0 s, got " + periodSeconds);
        }
        if (delayTicks < 0) {
            throw new IllegalArgumentException("VirtualCoupling.forDevice: delay must be >= 0 ticks, got " + delayTicks);
        }
        double c = deviceDamping / 4;
        double k = (deviceDamping - c) / (2 * periodSeconds * (delayTicks + 0.5));
        double m = 25 * k * periodSeconds * periodSeconds * (delayTicks + 1) * (delayTicks + 1);
        return new VirtualCoupling(k, c, m);
    }

    /**
     * A coupling of this stiffness (N/m, > 0) and damping (N s/m, >= 0) whose proxy is heavy enough to carry contacts
     * up to {@code largestContact} (N/m, > 0) at period T (s, > 0): the proxy's mass is {@code largestContact T^2}
     * kg, a quarter of what its explicit integration needs ({@code 4 m / T^2} N/m is where it diverges). For a hand
     * on the handle: a coupling stiffer than {@link #forDevice} allows is not passive on the device by itself, so
     * use it with the passivity controller on ({@link HapticLoop#setPassivityControl}); choose k about the stiffest
     * wall that holds without control with that grip, and damping well above the device's (on the emulated 2DIY with
     * a pen grip, which holds 814 N/m: k = 800 N/m, c = 1 N s/m and largestContact = 20 kN/m held walls of 4 N/m to
     * 16 kN/m stably and passively; twice that k did not, docs/haptics-stability.md). The hand feels at most k (a contact K in series: {@code K k / (K + k)}), and the
     * proxy's mass adds to the handle's inertia through the spring.
     *
     * @throws IllegalArgumentException naming the value when one is out of range or not finite
     */
    public static VirtualCoupling forContacts(double stiffness, double damping, double largestContact,
                                              double periodSeconds) {
        if (!(largestContact > 0) || !Double.isFinite(largestContact)) {
            throw new IllegalArgumentException("VirtualCoupling.forContacts: largest contact stiffness must be a finite number > 0 N/m, got "
                    + largestContact);
        }
        if (!(periodSeconds > 0) || !Double.isFinite(periodSeconds)) {
            throw new IllegalArgumentException("VirtualCoupling.forContacts: period must be a finite number > 0 s, got "
                    + periodSeconds);
        }
        return new VirtualCoupling(stiffness, damping, largestContact * periodSeconds * periodSeconds);
    }

    /** The coupling spring's stiffness, N/m. */
    public double stiffness() {
        return stiffness;
    }

    /** The coupling's damping, N s/m. */
    public double damping() {
        return damping;
    }

    /** The proxy's mass, kg. */
    public double mass() {
        return mass;
    }

    @Override
    public String toString() {
        return "VirtualCoupling(" + stiffness + " N/m, " + damping + " N s/m, " + mass + " kg)";
    }
}
