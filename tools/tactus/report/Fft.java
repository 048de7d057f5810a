package tactus.report;

/** The fast Fourier transform that the demo's pitch measurement and the audio tests share. */
public final class Fft {
    private Fft() {
    }

    /**
     * Replaces (re, im) by its discrete Fourier transform, in place, by the radix-2 algorithm.
     *
     * @param re real parts; its length must be a power of two
     * @param im imaginary parts, the same length
     */
    public static void transform(double[] re, double[] im) {
        int n = re.length;
        for (int i = 1, j = 0; i < n; i++) {
            int bit = n >> 1;
            for (; (j & bit) != 0; bit >>= 1) {
                j ^= bit;
            }
            j ^= bit;
            if (i < j) {
                double t = re[i];
                re[i] = re[j];
                re[j] = t;
                t = im[i];
                im[i] = im[j];
                im[j] = t;
            }
        }
        for (int len = 2; len <= n; len <<= 1) {
            double angle = -2 * Math.PI / len;
            for (int i = 0; i < n; i += len) {
                for (int k = 0; k < len / 2; k++) {
                    double c = Math.cos(angle * k);
                    double s = Math.sin(angle * k);
                    int p = i + k;
                    int q = p + len / 2;
                    double xr = re[q] * c - im[q] * s;
                    double xi = re[q] * s + im[q] * c;
                    re[q] = re[p] - xr;
                    im[q] = im[p] - xi;
                    re[p] += xr;
                    im[p] += xi;
                }
            }
        }
    }
}
