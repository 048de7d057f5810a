package tactus.engine;

/**
 * Conversions between SI units and the engine's algorithmic (per-step) units.
 *
 * <p>The engine integrates {@code X(n+1) = 2X(n) - X(n-1) + F/M}, so every coefficient is
 * expressed per simulation step. With a sample rate {@code fs} (steps per second):
 * <ul>
 *   <li>stiffness: {@code K_algo = k / fs^2} (k in N/m);</li>
 *   <li>damping and air friction: {@code Z_algo = z / fs} (z in N·s/m);</li>
 *   <li>acceleration (gravity): {@code g_algo = g / fs^2} (g in m/s^2);</li>
 *   <li>force: {@code F_algo = F / fs^2} (F in N);</li>
 *   <li>attraction factor: {@code A_algo = A / fs^2} (A in N·m^2);</li>
 *   <li>velocity: {@code v_algo = v / fs} (v in m/s, a displacement per step);</li>
 *   <li>energy: {@code E_algo = E / fs^2} (E in J);</li>
 *   <li>mass and length are the same in both systems.</li>
 * </ul>
 * Each conversion has an exact inverse; both directions use the same rate.
 */
public final class Units {
    private Units() {
    }

    /** @return stiffness in per-step units from N/m at {@code fs} steps per second. */
    public static double stiffnessToAlgo(double kNewtonPerMetre, double fs) {
        return kNewtonPerMetre / (fs * fs);
    }

    /** @return stiffness in N/m from per-step units at {@code fs} steps per second. */
    public static double stiffnessToReal(double kAlgo, double fs) {
        return kAlgo * (fs * fs);
    }

    /** @return damping (or friction) in per-step units from N·s/m. */
    public static double dampingToAlgo(double zNewtonSecondPerMetre, double fs) {
        return zNewtonSecondPerMetre / fs;
    }

    /** @return damping (or friction) in N·s/m from per-step units. */
    public static double dampingToReal(double zAlgo, double fs) {
        return zAlgo * fs;
    }

    /** @return an acceleration in units per step squared from m/s^2. */
    public static double accelerationToAlgo(double metresPerSecondSquared, double fs) {
        return metresPerSecondSquared / (fs * fs);
    }

    /** @return an acceleration in m/s^2 from units per step squared. */
    public static double accelerationToReal(double perStepSquared, double fs) {
        return perStepSquared * (fs * fs);
    }

    /** @return a force in per-step units from newtons (also used for the attraction factor and energy). */
    public static double forceToAlgo(double newtons, double fs) {
        return newtons / (fs * fs);
    }

    /** @return a force in newtons from per-step units (also used for the attraction factor and energy). */
    public static double forceToReal(double algo, double fs) {
        return algo * (fs * fs);
    }

    /** @return a displacement per step from a velocity in units per second. */
    public static double velocityToStep(double unitsPerSecond, double fs) {
        return unitsPerSecond / fs;
    }

    /** @return a velocity in units per second from a displacement per step. */
    public static double velocityToSecond(double perStep, double fs) {
        return perStep * fs;
    }
}
