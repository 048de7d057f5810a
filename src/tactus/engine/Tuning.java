package tactus.engine;

/**
 * Parameter tuning for the explicit mass-interaction scheme: pure functions that turn a wanted pitch and decay
 * into per-step coefficients, and back. They cost nothing while the model runs; they only choose better numbers.
 *
 * <h2>Why it is needed</h2>
 * The engine integrates {@code X(n+1) = 2X(n) - X(n-1) + F(n)/M}. A mass on a spring K with a damper Z on its
 * backward difference {@code X(n) - X(n-1)} then obeys
 * {@code X(n+1) = (2 - K/M - Z/M) X(n) - (1 - Z/M) X(n-1)}, whose characteristic polynomial is
 * <pre>    r² + (K/M + Z/M - 2) r + (1 - Z/M) = 0.</pre>
 * While it oscillates, its poles are {@code ρ e^(±iθ)} with radius {@code ρ = √(1 - Z/M)} per step and angle
 * {@code cos θ = (2 - (K+Z)/M) / (2√(1 - Z/M))}. The continuous mapping {@code k = m ω²} (here
 * {@link #naiveStiffness}) puts the pole at {@code cos θ = 1 - (ωT)²/2} instead of {@code θ = ωT}, so the simulated
 * pitch comes out sharp: +1.5 cents at 1 kHz, +38 cents at 5 kHz, +185 cents at 10 kHz, all at 44.1 kHz.
 * {@link #oscillatorStiffness} and {@link #oscillatorCoefficients} place the poles exactly where the continuous
 * oscillator has them (pole matching), so pitch and decay are exact for an isolated oscillator.
 *
 * <h2>Units</h2>
 * Every ratio here is in the engine's algorithmic units: {@code K/M} and {@code Z/M} are per step squared and per
 * step, that is dimensionless numbers for one step of length {@code 1/fs}. Frequencies are in hertz, times in
 * seconds, and {@code fs} is the <em>simulation</em> rate in steps per second (with oversampling by k, pass k times
 * the output rate). In {@code ALGO_UNITS} give the facade {@code K = (K/M)·M} and {@code Z = (Z/M)·M}; in
 * {@code REAL_UNITS} give {@code k = (K/M)·m·fs²} (N/m) and {@code z = (Z/M)·m·fs} (N·s/m). Air friction f adds to
 * an oscillator's own damping, so subtract {@code f/M} from {@code Z/M} when the model has some.
 *
 * <h2>Strings</h2>
 * The string functions are exact for a chain of N equal {@code Mass1D} linked in a row by {@code SpringDamper1D}
 * (no damping) to a fixed point at each end, N + 1 links, each with stiffness ratio {@code κ = K/M}; the chain is
 * linear at any amplitude. Its modes are {@code sin(π m j / (N+1))} and its partials
 * <pre>    f_m = (fs/π) asin(√κ · sin(π m / (2(N+1))))     for m = 1 .. N.</pre>
 * At {@code κ = 1} this is exactly {@code m · fs / (2(N+1))}: a perfectly harmonic string (the spatial dispersion
 * of the chain and the time warping of the scheme cancel, as in the 1-D wave equation at Courant number 1).
 * The same formulas hold for small transverse motion of a string of {@code Mass2DPlane} or {@code Mass3D} under
 * tension, with the transverse stiffness ratio {@code κ = K (1 - l0/d) / M} (d the stretched spacing, l0 the rest
 * length); there they are a small-amplitude approximation, since the 3-D springs are geometrically nonlinear.
 *
 * <p>All methods are static, allocate nothing but their results, and reject arguments outside their domain with an
 * {@link IllegalArgumentException} that names the value and the limit.
 */
public final class Tuning {
    /** {@code ln(1000)}: a decay of 60 dB in amplitude. */
    private static final double LN_1000 = Math.log(1000.0);

    private Tuning() {
    }

    // ================================================================ single oscillator

    /**
     * The stiffness ratio of an undamped oscillator that rings at exactly {@code freqHz}: {@code K/M = 4 sin²(π f / fs)}.
     *
     * @param freqHz the wanted frequency in Hz, {@code 0 <= f < fs/2}
     * @param fs the simulation rate in steps per second, &gt; 0
     * @return K/M per step squared, in [0, 4)
     */
    public static double oscillatorStiffness(double freqHz, double fs) {
        checkRate("oscillatorStiffness", fs);
        checkFrequency("oscillatorStiffness", freqHz, fs, true);
        double s = Math.sin(Math.PI * freqHz / fs);
        return 4 * s * s;
    }

    /**
     * The stiffness and damping ratios of a damped oscillator whose poles match the continuous one exactly: it rings
     * at exactly {@code freqHz} (the damped frequency) and its amplitude falls by 60 dB in exactly {@code t60Seconds}.
     * With {@code σ = ln(1000)/T60} (amplitude ∝ e^(−σt)) and {@code r = e^(−σ/fs)}:
     * {@code Z/M = 1 − r²} and {@code K/M = 1 + r² − 2r cos(2πf/fs)}. The result is always inside the stability
     * region ({@code K + 2Z < 4M}) and always oscillates.
     *
     * @param freqHz the damped frequency in Hz, {@code 0 < f < fs/2}
     * @param t60Seconds the time for a 60 dB decay in seconds, &gt; 0; {@link Double#POSITIVE_INFINITY} for none
     * @param fs the simulation rate in steps per second, &gt; 0
     * @return {K/M, Z/M}: stiffness per step squared and damping per step
     */
    public static double[] oscillatorCoefficients(double freqHz, double t60Seconds, double fs) {
        checkRate("oscillatorCoefficients", fs);
        checkFrequency("oscillatorCoefficients", freqHz, fs, false);
        checkT60("oscillatorCoefficients", t60Seconds);
        double sigma = LN_1000 / t60Seconds;
        double r = Math.exp(-sigma / fs);
        double zOverM = -Math.expm1(-2 * sigma / fs);         // 1 - r², accurate when r is close to 1
        double theta = 2 * Math.PI * freqHz / fs;
        // 1 + r² - 2r cos θ = (1 - r)² + 4r sin²(θ/2), written so that no cancellation occurs for small θ
        double oneMinusR = -Math.expm1(-sigma / fs);
        double half = Math.sin(theta / 2);
        double kOverM = oneMinusR * oneMinusR + 4 * r * half * half;
        return new double[] {kOverM, zOverM};
    }

    /**
     * The stiffness and damping ratios given by the continuous mapping ({@code k = m ω0²}, {@code z = 2 m σ} with
     * {@code ω0² = (2πf)² + σ²}), for comparison with {@link #oscillatorCoefficients}: it is how a sketch that
     * converts textbook values with {@code REAL_UNITS} ends up. Its pitch is sharp by about {@code (2πf/fs)²/24}.
     *
     * @param freqHz the wanted damped frequency in Hz, &gt; 0
     * @param t60Seconds the wanted 60 dB decay time in seconds, &gt; 0 (infinite for none)
     * @param fs the simulation rate in steps per second, &gt; 0
     * @return {K/M, Z/M}
     */
    public static double[] naiveCoefficients(double freqHz, double t60Seconds, double fs) {
        checkRate("naiveCoefficients", fs);
        if (!(freqHz > 0) || Double.isInfinite(freqHz)) {
            throw new IllegalArgumentException("naiveCoefficients: freqHz must be a finite number > 0, got " + freqHz);
        }
        checkT60("naiveCoefficients", t60Seconds);
        double sigma = LN_1000 / t60Seconds;
        double w = 2 * Math.PI * freqHz;
        return new double[] {(w * w + sigma * sigma) / (fs * fs), 2 * sigma / fs};
    }

    /**
     * The stiffness ratio given by the continuous mapping {@code k = m ω²}: {@code K/M = (2πf/fs)²}. Kept for
     * comparison: it makes the oscillator sharp (see the class comment).
     *
     * @param freqHz the frequency in Hz, &ge; 0
     * @param fs the simulation rate in steps per second, &gt; 0
     * @return K/M per step squared
     */
    public static double naiveStiffness(double freqHz, double fs) {
        checkRate("naiveStiffness", fs);
        if (!(freqHz >= 0) || Double.isInfinite(freqHz)) {
            throw new IllegalArgumentException("naiveStiffness: freqHz must be a finite number >= 0, got " + freqHz);
        }
        double w = 2 * Math.PI * freqHz / fs;
        return w * w;
    }

    /**
     * The frequency at which an undamped oscillator with stiffness ratio {@code K/M} rings in the simulation:
     * {@code f = (fs/π) asin(√(K/M) / 2)}.
     *
     * @param kOverM the stiffness ratio per step squared, {@code 0 <= K/M <= 4} (4 is the stability limit)
     * @param fs the simulation rate in steps per second, &gt; 0
     * @return the frequency in Hz, in [0, fs/2]
     */
    public static double discreteFrequency(double kOverM, double fs) {
        checkRate("discreteFrequency", fs);
        if (!(kOverM >= 0 && kOverM <= 4)) {
            throw new IllegalArgumentException("discreteFrequency: K/M = " + kOverM
                    + " is outside [0, 4], the range where the undamped scheme oscillates without growing");
        }
        return fs / Math.PI * Math.asin(Math.sqrt(kOverM) / 2);
    }

    /**
     * The damped frequency at which an oscillator with stiffness ratio {@code K/M} and damping ratio {@code Z/M} rings
     * in the simulation: {@code f = fs θ / 2π} with {@code cos θ = (2 − (K+Z)/M) / (2√(1 − Z/M))}.
     *
     * @param kOverM the stiffness ratio per step squared, &gt; 0
     * @param zOverM the damping ratio per step, {@code 0 <= Z/M < 1}
     * @param fs the simulation rate in steps per second, &gt; 0
     * @return the frequency in Hz, in (0, fs/2)
     * @throws IllegalArgumentException also when the poles are real (the oscillator is overdamped and does not ring)
     */
    public static double discreteFrequency(double kOverM, double zOverM, double fs) {
        checkRate("discreteFrequency", fs);
        checkDamping("discreteFrequency", zOverM);
        if (!(kOverM > 0) || Double.isInfinite(kOverM)) {
            throw new IllegalArgumentException("discreteFrequency: K/M must be a finite number > 0, got " + kOverM);
        }
        double rho = Math.sqrt(1 - zOverM);
        double c = (2 - kOverM - zOverM) / (2 * rho);
        if (!(c > -1 && c < 1)) {
            throw new IllegalArgumentException("discreteFrequency: K/M = " + kOverM + " with Z/M = " + zOverM
                    + " has real poles (cos θ = " + c + " is outside (-1, 1)): the oscillator does not ring");
        }
        return fs * Math.acos(c) / (2 * Math.PI);
    }

    /**
     * The time an oscillator with damping ratio {@code Z/M} takes to lose 60 dB of amplitude while it rings: its poles
     * have radius {@code ρ = √(1 − Z/M)} per step, so {@code T60 = ln(1000) / (−fs ln ρ)}. Valid whenever the
     * oscillator rings (complex poles); the stiffness does not enter.
     *
     * @param zOverM the damping ratio per step, {@code 0 <= Z/M < 1}
     * @param fs the simulation rate in steps per second, &gt; 0
     * @return T60 in seconds; {@link Double#POSITIVE_INFINITY} for Z/M = 0
     */
    public static double decayTime60(double zOverM, double fs) {
        checkRate("decayTime60", fs);
        checkDamping("decayTime60", zOverM);
        if (zOverM == 0) {
            return Double.POSITIVE_INFINITY;
        }
        return 2 * LN_1000 / (-fs * Math.log1p(-zOverM));
    }

    /**
     * The initial velocity to give a mass so that its trajectory starts like the continuous one, to second order.
     * The facade starts a mass from {@code X(-1) = X(0) − v/fs}, which is the velocity half a step before t = 0;
     * under a constant acceleration {@code a} the trajectory is then off by {@code a·t/(2fs)} (a free fall at
     * 44.1 kHz is 0.11 mm ahead after 1 s). Passing {@code v0 − a/(2fs)} instead makes a free fall exact.
     *
     * @param v0 the wanted velocity at t = 0, in units per second
     * @param acceleration the acceleration at t = 0 along the same axis, in units per second squared (for gravity g
     *     along −z, pass −g)
     * @param fs the simulation rate in steps per second, &gt; 0
     * @return the velocity to pass as {@code initVel}, in units per second
     */
    public static double startVelocity(double v0, double acceleration, double fs) {
        checkRate("startVelocity", fs);
        return v0 - acceleration / (2 * fs);
    }

    // ================================================================ strings

    /**
     * The fundamental of a fixed-fixed chain of {@code n} masses with stiffness ratio {@code κ}:
     * {@code f1 = (fs/π) asin(√κ sin(π / (2(N+1))))} (see the class comment for the chain meant).
     *
     * @param kOverM the stiffness ratio κ of each link, per step squared, &gt; 0
     * @param n the number of moving masses, &ge; 1
     * @param fs the simulation rate in steps per second, &gt; 0
     * @return the fundamental in Hz
     */
    public static double stringFundamental(double kOverM, int n, double fs) {
        return stringPartial(kOverM, n, 1, fs);
    }

    /**
     * Partial {@code m} of a fixed-fixed chain of {@code n} masses with stiffness ratio {@code κ}:
     * {@code f_m = (fs/π) asin(√κ sin(π m / (2(N+1))))}.
     *
     * @param kOverM the stiffness ratio κ, per step squared, &gt; 0 and below the stability limit
     *     {@link #stringStabilityLimit(int)}
     * @param n the number of moving masses, &ge; 1
     * @param m the partial (mode) number, {@code 1 <= m <= n}
     * @param fs the simulation rate in steps per second, &gt; 0
     * @return the frequency of partial m in Hz
     */
    public static double stringPartial(double kOverM, int n, int m, double fs) {
        checkRate("stringPartial", fs);
        checkMasses("stringPartial", n);
        if (m < 1 || m > n) {
            throw new IllegalArgumentException("stringPartial: partial " + m + " does not exist in a chain of " + n
                    + " masses (1.." + n + ")");
        }
        double limit = stringStabilityLimit(n);
        if (!(kOverM > 0 && kOverM < limit)) {
            throw new IllegalArgumentException("stringPartial: K/M = " + kOverM + " is outside (0, " + limit
                    + "), the stable range for a chain of " + n + " masses");
        }
        return fs / Math.PI * Math.asin(Math.sqrt(kOverM) * Math.sin(Math.PI * m / (2.0 * (n + 1))));
    }

    /**
     * The largest stiffness ratio at which a fixed-fixed chain of {@code n} masses is stable:
     * {@code 1 / cos²(π / (2(N+1)))} (its highest mode reaches the Nyquist frequency there). It is 2 for one mass and
     * approaches 1 from above for long chains.
     *
     * @param n the number of moving masses, &ge; 1
     * @return the limit of K/M (exclusive)
     */
    public static double stringStabilityLimit(int n) {
        checkMasses("stringStabilityLimit", n);
        double c = Math.cos(Math.PI / (2.0 * (n + 1)));
        return 1 / (c * c);
    }

    /**
     * The stiffness ratio that gives a fixed-fixed chain of {@code n} masses the fundamental {@code f1} exactly:
     * {@code κ = (sin(π f1/fs) / sin(π / (2(N+1))))²}, the inverse of {@link #stringFundamental}. With κ below 1
     * the upper partials come out flat (compressed, the opposite of a real stiff string); κ = 1 is exactly harmonic;
     * above 1 they are stretched, up to the stability limit. For a given f1, pick N with
     * {@link #stringMassesForRetuning} to stay as close to 1 as possible.
     *
     * @param f1 the wanted fundamental in Hz, &gt; 0
     * @param n the number of moving masses, &ge; 1
     * @param fs the simulation rate in steps per second, &gt; 0
     * @return κ = K/M for every link, per step squared
     * @throws IllegalArgumentException if f1 is not below the highest fundamental that n masses can reach stably,
     *     {@code (fs/π) asin(tan(π / (2(N+1))))}; the message names both
     */
    public static double stringStiffnessForFundamental(double f1, int n, double fs) {
        checkRate("stringStiffnessForFundamental", fs);
        checkMasses("stringStiffnessForFundamental", n);
        if (!(f1 > 0) || Double.isInfinite(f1)) {
            throw new IllegalArgumentException("stringStiffnessForFundamental: f1 must be a finite number > 0 Hz, got "
                    + f1);
        }
        double half = Math.PI / (2.0 * (n + 1));
        double t = Math.tan(half);
        double fMax = t >= 1 ? fs / 2 : fs / Math.PI * Math.asin(t);
        double limit = stringStabilityLimit(n);
        if (f1 >= fs / 2) {
            throw new IllegalArgumentException("stringStiffnessForFundamental: f1 = " + f1
                    + " Hz is not below the Nyquist frequency " + fs / 2 + " Hz (fs = " + fs + ")");
        }
        double ratio = Math.sin(Math.PI * f1 / fs) / Math.sin(half);
        double kappa = ratio * ratio;
        if (!(kappa < limit)) {
            throw new IllegalArgumentException("stringStiffnessForFundamental: f1 = " + f1 + " Hz with " + n
                    + " masses needs K/M = " + kappa + ", not below the stability limit " + limit
                    + "; the highest stable fundamental for " + n + " masses at fs = " + fs + " is " + fMax
                    + " Hz (use fewer masses or a higher rate)");
        }
        return kappa;
    }

    /**
     * The number of masses N that makes a harmonic string (κ = K/M = 1) closest to the fundamental {@code f1}: its
     * fundamental is {@code fs / (2(N+1))}, so N + 1 is {@code fs / (2 f1)} rounded to the nearest integer. The
     * rounding error is {@link #stringRoundingCents(double, double)}. To remove it, take N from
     * {@link #stringMassesForRetuning} instead and retune with {@link #stringStiffnessForFundamental} (not with this
     * N: when the rounding went up, the retuned κ would be above 1, and a long chain's stability limit is barely
     * above 1).
     *
     * @param f1 the wanted fundamental in Hz, {@code 0 < f1 <= fs/4} (one mass at least)
     * @param fs the simulation rate in steps per second, &gt; 0
     * @return N, the number of moving masses, &ge; 1
     */
    public static int stringMassesForFundamental(double f1, double fs) {
        checkRate("stringMassesForFundamental", fs);
        if (!(f1 > 0) || !(f1 <= fs / 4)) {
            throw new IllegalArgumentException("stringMassesForFundamental: f1 = " + f1
                    + " Hz is outside (0, " + fs / 4 + "] Hz, the range a harmonic string (K/M = 1) can reach at fs = "
                    + fs + " (at least one mass, fundamental fs / 4)");
        }
        double links = fs / (2 * f1);
        if (links > Integer.MAX_VALUE - 1.0) {
            throw new IllegalArgumentException("stringMassesForFundamental: f1 = " + f1 + " Hz needs "
                    + links + " links, more than an int can count");
        }
        return Math.max(1, (int) Math.round(links) - 1);
    }

    /**
     * The number of masses to retune for an exact fundamental: the largest N whose harmonic fundamental
     * {@code fs / (2(N+1))} is not below {@code f1}, that is N + 1 = floor(fs / (2 f1)). Then
     * {@code stringStiffnessForFundamental(f1, N, fs)} is at most 1 (always stable) and as close to 1 as the rounding
     * allows, so the string has exactly the fundamental f1 and nearly harmonic partials: partials 1 to 10 stay within
     * 1 cent of m·f1 for every f1 up to about fs/104 (424 Hz at 44.1 kHz; the limit grows in proportion to fs).
     *
     * @param f1 the wanted fundamental in Hz, {@code 0 < f1 <= fs/4} (one mass at least)
     * @param fs the simulation rate in steps per second, &gt; 0
     * @return N, the number of moving masses, &ge; 1
     */
    public static int stringMassesForRetuning(double f1, double fs) {
        checkRate("stringMassesForRetuning", fs);
        if (!(f1 > 0) || !(f1 <= fs / 4)) {
            throw new IllegalArgumentException("stringMassesForRetuning: f1 = " + f1 + " Hz is outside (0, " + fs / 4
                    + "] Hz, the range a string with K/M at most 1 can reach at fs = " + fs + " (at least one mass)");
        }
        double links = Math.floor(fs / (2 * f1));
        if (links > Integer.MAX_VALUE - 1.0) {
            throw new IllegalArgumentException("stringMassesForRetuning: f1 = " + f1 + " Hz needs " + links
                    + " links, more than an int can count");
        }
        return Math.max(1, (int) links - 1);
    }

    /**
     * The fundamental of a harmonic string (κ = 1) of {@code n} masses: exactly {@code fs / (2(N+1))}.
     *
     * @param n the number of moving masses, &ge; 1
     * @param fs the simulation rate in steps per second, &gt; 0
     * @return the fundamental in Hz
     */
    public static double harmonicStringFundamental(int n, double fs) {
        checkRate("harmonicStringFundamental", fs);
        checkMasses("harmonicStringFundamental", n);
        return fs / (2.0 * (n + 1));
    }

    /**
     * How far the harmonic string chosen by {@link #stringMassesForFundamental} is from {@code f1}, in cents
     * (positive: sharp). At most about {@code 866 / (N+1)} cents in magnitude.
     *
     * @param f1 the wanted fundamental in Hz, {@code 0 < f1 <= fs/4}
     * @param fs the simulation rate in steps per second, &gt; 0
     * @return the error of the fundamental (and of every partial) in cents
     */
    public static double stringRoundingCents(double f1, double fs) {
        int n = stringMassesForFundamental(f1, fs);
        return cents(harmonicStringFundamental(n, fs), f1);
    }

    /**
     * The interval from {@code refHz} to {@code freqHz} in cents: {@code 1200 log2(f / ref)}.
     *
     * @param freqHz a frequency in Hz, &gt; 0
     * @param refHz the reference frequency in Hz, &gt; 0
     * @return the interval in cents (positive when {@code freqHz} is higher)
     */
    public static double cents(double freqHz, double refHz) {
        if (!(freqHz > 0) || !(refHz > 0)) {
            throw new IllegalArgumentException("cents: both frequencies must be > 0, got " + freqHz + " and " + refHz);
        }
        return 1200 * Math.log(freqHz / refHz) / Math.log(2);
    }

    // ================================================================ checks

    private static void checkRate(String op, double fs) {
        if (!(fs > 0) || Double.isInfinite(fs)) {
            throw new IllegalArgumentException(op + ": fs must be a finite rate > 0 steps per second, got " + fs);
        }
    }

    private static void checkFrequency(String op, double f, double fs, boolean zeroAllowed) {
        boolean low = zeroAllowed ? f >= 0 : f > 0;
        if (!low || !(f < fs / 2)) {
            throw new IllegalArgumentException(op + ": freqHz = " + f + " is outside " + (zeroAllowed ? "[0, " : "(0, ")
                    + fs / 2 + ") Hz: the scheme can only ring below the Nyquist frequency fs/2 (fs = " + fs + ")");
        }
    }

    private static void checkT60(String op, double t60) {
        if (!(t60 > 0)) {
            throw new IllegalArgumentException(op + ": t60Seconds must be > 0 (or infinite for no decay), got " + t60);
        }
    }

    private static void checkDamping(String op, double zOverM) {
        if (!(zOverM >= 0 && zOverM < 1)) {
            throw new IllegalArgumentException(op + ": Z/M = " + zOverM
                    + " is outside [0, 1), the range where the pole radius sqrt(1 - Z/M) is real and positive");
        }
    }

    private static void checkMasses(String op, int n) {
        if (n < 1) {
            throw new IllegalArgumentException(op + ": the chain needs at least 1 mass, got " + n);
        }
    }
}
