package tactus.report;

/**
 * Model-free estimators for recorded signals, shared by the accuracy report and the tuning tests
 * ({@code tactus.tuning.TuningTest}). None of them uses the scheme's recurrence: they only assume that the signal
 * is a (possibly decaying) sinusoid.
 *
 * <ul>
 *   <li>{@link #crossingFrequency}: mean spacing of upward zero crossings (a coarse, robust first guess);</li>
 *   <li>{@link #peakFrequency}: the maximum of the Hann-windowed discrete-time Fourier transform, refined by
 *       golden-section search around a guess. For y(n) = A w(n) ρ^n cos(θn + φ) the spectrum magnitude near θ is
 *       that of a real, symmetric-spectrum window shifted to θ, so its maximum sits at θ up to the leakage of the
 *       negative-frequency image (negligible with a Hann window over many periods);</li>
 *   <li>{@link #decayTime60}: for y(n) = C ρ^n cos(θn + φ), y(n)² − y(n+1) y(n−1) = C² sin²θ ρ^(2n) exactly, so a
 *       straight-line fit of its logarithm gives ln ρ;</li>
 *   <li>{@link #sinePhase}: least-squares fit of a sin(ωn) + b cos(ωn) at a given frequency.</li>
 * </ul>
 */
public final class Measure {
    private static final double GOLDEN = (Math.sqrt(5) - 1) / 2;

    private Measure() {
    }

    /**
     * @return the frequency in Hz from the mean spacing of upward zero crossings of y (linear interpolation between
     *     samples), or NaN when y crosses zero upward fewer than twice
     */
    public static double crossingFrequency(double[] y, double fs) {
        double first = Double.NaN;
        double last = Double.NaN;
        int count = 0;
        for (int n = 1; n < y.length; n++) {
            if (y[n - 1] < 0 && y[n] >= 0) {
                double t = n - 1 + y[n - 1] / (y[n - 1] - y[n]);
                if (count == 0) {
                    first = t;
                }
                last = t;
                count++;
            }
        }
        if (count < 2) {
            return Double.NaN;
        }
        return fs * (count - 1) / (last - first);
    }

    /** @return the squared magnitude of the Hann-windowed DTFT of y[from, to) at angular frequency w (rad/sample). */
    public static double windowedPower(double[] y, int from, int to, double w) {
        int len = to - from;
        double re = 0;
        double im = 0;
        // rotate a phasor instead of calling cos/sin per sample; re-anchor every 1024 samples against drift
        double cw = Math.cos(w);
        double sw = Math.sin(w);
        double c = 1;
        double s = 0;
        for (int i = 0; i < len; i++) {
            if ((i & 1023) == 0) {
                c = Math.cos(w * i);
                s = Math.sin(w * i);
            }
            double win = 0.5 - 0.5 * Math.cos(2 * Math.PI * (i + 0.5) / len);
            double v = win * y[from + i];
            re += v * c;
            im -= v * s;
            double nc = c * cw - s * sw;
            s = s * cw + c * sw;
            c = nc;
        }
        return re * re + im * im;
    }

    /**
     * Refines a frequency guess to the peak of the Hann-windowed spectrum of y[from, to). The guess must lie within
     * about one frequency bin (fs / (to − from)) of the peak; {@link #crossingFrequency} gives one.
     *
     * @return the peak frequency in Hz
     */
    public static double peakFrequency(double[] y, int from, int to, double fs, double guessHz) {
        double bin = 2 * Math.PI / (to - from);
        double w0 = 2 * Math.PI * guessHz / fs;
        double a = Math.max(1e-9, w0 - 1.5 * bin);
        double b = Math.min(Math.PI - 1e-9, w0 + 1.5 * bin);
        double x1 = b - GOLDEN * (b - a);
        double x2 = a + GOLDEN * (b - a);
        double p1 = windowedPower(y, from, to, x1);
        double p2 = windowedPower(y, from, to, x2);
        while (b - a > 1e-14 * Math.max(1, w0)) {
            if (p1 > p2) {
                b = x2;
                x2 = x1;
                p2 = p1;
                x1 = b - GOLDEN * (b - a);
                p1 = windowedPower(y, from, to, x1);
            } else {
                a = x1;
                x1 = x2;
                p1 = p2;
                x2 = a + GOLDEN * (b - a);
                p2 = windowedPower(y, from, to, x2);
            }
        }
        return (a + b) / 2 * fs / (2 * Math.PI);
    }

    /** @return the peak frequency of the whole signal, starting from its zero-crossing frequency. */
    public static double frequency(double[] y, double fs) {
        double guess = crossingFrequency(y, fs);
        return peakFrequency(y, 0, y.length, fs, guess);
    }

    /**
     * @return the 60 dB decay time in seconds of a decaying sinusoid, from a least-squares line through
     *     ln(y(n)² − y(n+1) y(n−1)) over n in [from, to); infinite when the fitted envelope does not decay
     */
    public static double decayTime60(double[] y, int from, int to, double fs) {
        double sx = 0, sy = 0, sxx = 0, sxy = 0;
        int count = 0;
        for (int n = Math.max(1, from); n < to && n + 1 < y.length; n++) {
            double q = y[n] * y[n] - y[n + 1] * y[n - 1];
            if (!(q > 0)) {
                continue;
            }
            double l = Math.log(q);
            sx += n;
            sy += l;
            sxx += (double) n * n;
            sxy += n * l;
            count++;
        }
        double slope = (count * sxy - sx * sy) / (count * sxx - sx * sx);   // 2 ln ρ per sample
        if (!(slope < 0)) {
            return Double.POSITIVE_INFINITY;
        }
        return 2 * Math.log(1000) / (-slope * fs);
    }

    /**
     * Fits y(n) ≈ A sin(ωn + φ) over the whole signal at the given frequency (least squares on sin and cos).
     *
     * @return {A, φ} with φ in (−π, π]
     */
    public static double[] sinePhase(double[] y, double freqHz, double fs) {
        double w = 2 * Math.PI * freqHz / fs;
        double ss = 0, sc = 0, cc = 0, ys = 0, yc = 0;
        for (int n = 0; n < y.length; n++) {
            double s = Math.sin(w * n);
            double c = Math.cos(w * n);
            ss += s * s;
            sc += s * c;
            cc += c * c;
            ys += y[n] * s;
            yc += y[n] * c;
        }
        double det = ss * cc - sc * sc;
        double a = (ys * cc - yc * sc) / det;   // coefficient of sin
        double b = (yc * ss - ys * sc) / det;   // coefficient of cos
        return new double[] {Math.hypot(a, b), Math.atan2(b, a)};
    }

    /**
     * Projects the displacements of a fixed-fixed chain on its mode m: q(n) = Σ_j u_j(n) sin(π m j / (N+1)), with
     * u[n][j − 1] the displacement of mass j (1..N) at sample n.
     */
    public static double[] modeProjection(double[][] u, int m) {
        int n = u[0].length;
        double[] shape = new double[n];
        for (int j = 1; j <= n; j++) {
            shape[j - 1] = Math.sin(Math.PI * m * j / (n + 1.0));
        }
        double[] q = new double[u.length];
        for (int t = 0; t < u.length; t++) {
            double acc = 0;
            double[] row = u[t];
            for (int j = 0; j < n; j++) {
                acc += row[j] * shape[j];
            }
            q[t] = acc;
        }
        return q;
    }

    /** @return 1200 log2(f / ref). */
    public static double cents(double f, double ref) {
        return 1200 * Math.log(f / ref) / Math.log(2);
    }
}
