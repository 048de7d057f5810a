package tactus.audio;

/**
 * A linear-phase FIR low-pass that turns k model steps into one audio sample (decimation by k). It is a
 * Kaiser-windowed sinc designed here, in code: the passband reaches {@link #PASS_EDGE} of the output rate,
 * the stopband starts at {@link #STOP_EDGE} of it (so nothing aliases below the passband edge) and is at
 * least {@link #STOP_ATTENUATION_DB} down. The design is checked on a dense frequency grid and lengthened
 * until it meets that specification. Its delay is (taps - 1) / 2 model steps.
 */
public final class DecimationFilter {
    /** Passband edge, as a fraction of the output sample rate. */
    public static final double PASS_EDGE = 0.40;
    /** Stopband edge, as a fraction of the output sample rate. */
    public static final double STOP_EDGE = 0.60;
    /** Minimum stopband attenuation, in dB. */
    public static final double STOP_ATTENUATION_DB = 80;
    /** Maximum passband deviation, in dB. */
    public static final double PASS_RIPPLE_DB = 0.01;

    private final int factor;
    private final double[] taps;
    private final double[] ring;
    private int pos;
    private int phase;

    /** Designs the filter for a decimation factor k in 2..16. */
    public DecimationFilter(int factor) {
        if (factor < 2 || factor > 16) {
            throw new IllegalArgumentException("DecimationFilter: the factor must be in 2..16, got " + factor);
        }
        this.factor = factor;
        this.taps = design(factor);
        this.ring = new double[2 * taps.length];
    }

    /** {@return the decimation factor k} */
    public int factor() {
        return factor;
    }

    /** {@return a copy of the impulse response (DC gain 1)} */
    public double[] taps() {
        return taps.clone();
    }

    /** {@return the delay in input samples (model steps)} */
    public double delaySteps() {
        return (taps.length - 1) / 2.0;
    }

    /**
     * Pushes one input sample (one model step).
     *
     * @return true when an output sample is due (every k-th input); read it with {@link #output()}
     */
    public boolean push(double x) {
        int n = taps.length;
        pos = pos == 0 ? n - 1 : pos - 1;
        ring[pos] = x;
        ring[pos + n] = x;
        if (++phase == factor) {
            phase = 0;
            return true;
        }
        return false;
    }

    /** {@return the filtered value at the latest input: sum of taps[j] x(n - j)} */
    public double output() {
        double[] h = taps;
        double[] r = ring;
        int p = pos;
        double acc = 0;
        for (int j = 0; j < h.length; j++) {
            acc += h[j] * r[p + j];
        }
        return acc;
    }

    /** Fills the history with a constant, as if that input had been applied forever. */
    public void reset(double x) {
        java.util.Arrays.fill(ring, x);
        phase = 0;
    }

    /**
     * {@return |H(f)| of impulse response h at frequency f, given as a fraction of the rate h runs at}
     */
    public static double magnitude(double[] h, double f) {
        double re = 0;
        double im = 0;
        for (int j = 0; j < h.length; j++) {
            double a = 2 * Math.PI * f * j;
            re += h[j] * Math.cos(a);
            im -= h[j] * Math.sin(a);
        }
        return Math.hypot(re, im);
    }

    static double[] design(int k) {
        double att = STOP_ATTENUATION_DB + 1; // a small margin over the target
        double beta = 0.1102 * (att - 8.7);
        double transition = 2 * Math.PI * (STOP_EDGE - PASS_EDGE) / k; // rad per input sample
        int n = (int) Math.ceil((att - 7.95) / (2.285 * transition)) + 1;
        if (n % 2 == 0) {
            n++;
        }
        for (int tries = 0; tries < 64; tries++, n += 2) {
            double[] h = kaiserSinc(n, 0.5 * (PASS_EDGE + STOP_EDGE) / k, beta);
            if (meetsSpec(h, k)) {
                return h;
            }
        }
        throw new IllegalStateException("DecimationFilter: no design met the specification for factor " + k);
    }

    private static double[] kaiserSinc(int n, double cutoff, double beta) {
        double[] h = new double[n];
        double mid = (n - 1) / 2.0;
        double i0b = besselI0(beta);
        double sum = 0;
        for (int j = 0; j < n; j++) {
            double t = j - mid;
            double sinc = t == 0 ? 2 * cutoff : Math.sin(2 * Math.PI * cutoff * t) / (Math.PI * t);
            double u = t / mid;
            double w = besselI0(beta * Math.sqrt(Math.max(0, 1 - u * u))) / i0b;
            h[j] = sinc * w;
            sum += h[j];
        }
        for (int j = 0; j < n; j++) {
            h[j] /= sum;
        }
        return h;
    }

    static boolean meetsSpec(double[] h, int k) {
        double passTol = Math.pow(10, PASS_RIPPLE_DB / 20) - 1;
        double stopMax = Math.pow(10, -STOP_ATTENUATION_DB / 20);
        int grid = 2000;
        for (int i = 0; i <= grid; i++) {
            double f = PASS_EDGE / k * i / grid;
            if (Math.abs(magnitude(h, f) - 1) > passTol) {
                return false;
            }
        }
        for (int i = 0; i <= grid * k; i++) {
            double f = STOP_EDGE / k + (0.5 - STOP_EDGE / k) * i / (grid * k);
            if (magnitude(h, f) > stopMax) {
                return false;
            }
        }
        return true;
    }

    private static double besselI0(double x) {
        double sum = 1;
        double term = 1;
        double q = x * x / 4;
        for (int m = 1; m < 200; m++) {
            term *= q / ((double) m * m);
            sum += term;
            if (term < 1e-17 * sum) {
                break;
            }
        }
        return sum;
    }
}
