package tactus.demo;

/**
 * Measures the frequency of a spectral peak of a recorded signal: a Hann window over the part that is
 * analysed, zero-padded to a power of two at least {@value #PADDING} times as long (so the peak lies within a
 * fraction of a padded bin), an FFT, the largest magnitude in a band, and a parabola through the logarithms
 * of the three magnitudes around it (for a Gaussian-like main lobe, such as the Hann window's, this places
 * the peak to a small fraction of a bin).
 */
public final class Pitch {
    /** Zero-padding factor: the FFT is at least this many times longer than the analysed samples. */
    public static final int PADDING = 4;

    private final double[] magnitude;
    private final double binHz;
    private final int analysed;
    private final double rate;

    /**
     * Computes the spectrum of {@code samples[from .. from + count)}.
     *
     * @param samples the signal
     * @param from    first sample analysed
     * @param count   number of samples analysed (at least 16)
     * @param rate    samples per second
     */
    public Pitch(float[] samples, int from, int count, double rate) {
        if (from < 0 || count < 16 || from + count > samples.length || !(rate > 0)) {
            throw new IllegalArgumentException("Pitch: need 0 <= from, 16 <= count, from + count <= "
                    + samples.length + " and rate > 0; got from " + from + ", count " + count + ", rate " + rate);
        }
        int n = Integer.highestOneBit(count * PADDING - 1) << 1;
        double[] re = new double[n];
        double[] im = new double[n];
        for (int i = 0; i < count; i++) {
            double w = 0.5 * (1 - Math.cos(2 * Math.PI * i / (count - 1)));
            re[i] = w * samples[from + i];
        }
        tactus.report.Fft.transform(re, im);
        magnitude = new double[n / 2 + 1];
        for (int k = 0; k <= n / 2; k++) {
            magnitude[k] = Math.hypot(re[k], im[k]);
        }
        binHz = rate / n;
        analysed = count;
        this.rate = rate;
    }

    /** @return the width of one FFT bin (after zero-padding), Hz. */
    public double binHz() {
        return binHz;
    }

    /** @return the frequency resolution of the analysed stretch, {@code rate / count}, Hz. */
    public double resolutionHz() {
        return rate / analysed;
    }

    /**
     * @return the interpolated frequency of the largest peak between {@code lowHz} and {@code highHz}, Hz
     */
    public double peakHz(double lowHz, double highHz) {
        int k = peakBin(lowHz, highHz);
        if (k <= 0 || k >= magnitude.length - 1) {
            return k * binHz;
        }
        double a = Math.log(magnitude[k - 1] + 1e-300);
        double b = Math.log(magnitude[k] + 1e-300);
        double c = Math.log(magnitude[k + 1] + 1e-300);
        double denominator = a - 2 * b + c;
        double offset = denominator == 0 ? 0 : 0.5 * (a - c) / denominator;
        return (k + offset) * binHz;
    }

    /** @return the largest magnitude between {@code lowHz} and {@code highHz} (arbitrary units). */
    public double peakMagnitude(double lowHz, double highHz) {
        return magnitude[peakBin(lowHz, highHz)];
    }

    private int peakBin(double lowHz, double highHz) {
        int lo = Math.max(0, (int) Math.ceil(lowHz / binHz));
        int hi = Math.min(magnitude.length - 1, (int) Math.floor(highHz / binHz));
        if (hi < lo) {
            throw new IllegalArgumentException("Pitch: the band " + lowHz + " to " + highHz + " Hz holds no bin");
        }
        int best = lo;
        for (int k = lo + 1; k <= hi; k++) {
            if (magnitude[k] > magnitude[best]) {
                best = k;
            }
        }
        return best;
    }
}
