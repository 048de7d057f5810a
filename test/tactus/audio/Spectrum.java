package tactus.audio;

/** FFT peak measurement for the audio tests: Hann window, radix-2 FFT, log-parabolic peak interpolation. */
final class Spectrum {
    private final double[] magnitude;
    private final double binHz;

    /** Analyses the first power-of-two samples of x (at least 2^k &le; x.length). */
    Spectrum(float[] x, int offset, int n, double sampleRate) {
        if (Integer.bitCount(n) != 1 || offset + n > x.length) {
            throw new IllegalArgumentException("Spectrum: n must be a power of two within the signal");
        }
        double[] re = new double[n];
        double[] im = new double[n];
        for (int i = 0; i < n; i++) {
            double w = 0.5 - 0.5 * Math.cos(2 * Math.PI * i / n);
            re[i] = x[offset + i] * w;
        }
        tactus.report.Fft.transform(re, im);
        magnitude = new double[n / 2];
        for (int i = 0; i < n / 2; i++) {
            magnitude[i] = Math.hypot(re[i], im[i]);
        }
        binHz = sampleRate / n;
    }

    /** @return the interpolated frequency of the largest peak between lo and hi Hz. */
    double peakHz(double loHz, double hiHz) {
        int lo = Math.max(1, (int) Math.floor(loHz / binHz));
        int hi = Math.min(magnitude.length - 2, (int) Math.ceil(hiHz / binHz));
        int best = lo;
        for (int i = lo; i <= hi; i++) {
            if (magnitude[i] > magnitude[best]) {
                best = i;
            }
        }
        double a = Math.log(magnitude[best - 1]);
        double b = Math.log(magnitude[best]);
        double c = Math.log(magnitude[best + 1]);
        double delta = 0.5 * (a - c) / (a - 2 * b + c);
        return (best + delta) * binHz;
    }

    /** @return the largest magnitude between lo and hi Hz. */
    double peakMagnitude(double loHz, double hiHz) {
        int lo = Math.max(1, (int) Math.floor(loHz / binHz));
        int hi = Math.min(magnitude.length - 1, (int) Math.ceil(hiHz / binHz));
        double best = 0;
        for (int i = lo; i <= hi; i++) {
            best = Math.max(best, magnitude[i]);
        }
        return best;
    }

    static double cents(double f, double reference) {
        return 1200 * Math.log(f / reference) / Math.log(2);
    }
}
