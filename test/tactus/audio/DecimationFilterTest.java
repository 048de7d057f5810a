package tactus.audio;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.junit.jupiter.api.Test;

/**
 * The decimation low-pass meets its specification: measured here by an independent DTFT on a finer grid
 * than the designer's own check, and by running sines through the streaming decimator.
 */
class DecimationFilterTest {

    /** |H| at f (fraction of the input rate), computed directly from the taps. */
    private static double gain(double[] h, double f) {
        double re = 0;
        double im = 0;
        for (int j = 0; j < h.length; j++) {
            re += h[j] * Math.cos(2 * Math.PI * f * j);
            im += h[j] * Math.sin(2 * Math.PI * f * j);
        }
        return Math.sqrt(re * re + im * im);
    }

    private static double db(double g) {
        return 20 * Math.log10(g);
    }

    @ParameterizedTest
    @ValueSource(ints = {2, 3, 4, 8})
    void responseMeetsTheSpecification(int k) {
        double[] h = new DecimationFilter(k).taps();
        double sum = 0;
        for (int j = 0; j < h.length; j++) {
            sum += h[j];
            assertEquals(h[j], h[h.length - 1 - j], 1e-15, "linear phase: symmetric taps");
        }
        assertEquals(1, sum, 1e-12, "DC gain");
        int grid = 5000;
        double worstPass = 0;
        for (int i = 0; i <= grid; i++) {
            double f = DecimationFilter.PASS_EDGE / k * i / grid;
            worstPass = Math.max(worstPass, Math.abs(db(gain(h, f))));
        }
        assertTrue(worstPass <= DecimationFilter.PASS_RIPPLE_DB,
                "k=" + k + ": passband deviation " + worstPass + " dB");
        double worstStop = -1000;
        for (int i = 0; i <= grid * k; i++) {
            double f = DecimationFilter.STOP_EDGE / k + (0.5 - DecimationFilter.STOP_EDGE / k) * i / (grid * k);
            worstStop = Math.max(worstStop, db(gain(h, f)));
        }
        assertTrue(worstStop <= -DecimationFilter.STOP_ATTENUATION_DB, "k=" + k + ": stopband at " + worstStop + " dB");
        // and it is a low-pass, not something that only happens to meet the grid: the transition is monotone-ish
        assertTrue(gain(h, 0.5 / k) < 0.9 && gain(h, 0.5 / k) > 0.1, "half gain near the output Nyquist");
    }

    /** Feeds a sine and returns the steady output amplitude, sqrt(2 mean y^2) over the last 2000 outputs. */
    private static double throughDecimator(int k, double fOut) {
        DecimationFilter d = new DecimationFilter(k);
        double w = 2 * Math.PI * fOut / k;
        int outputs = 4000;
        double energy = 0;
        int out = 0;
        for (int n = 0; out < outputs; n++) {
            if (d.push(Math.sin(w * n + 0.3))) {
                out++;
                if (out > outputs / 2) {
                    double y = d.output();
                    energy += y * y;
                }
            }
        }
        return Math.sqrt(2 * energy / (outputs / 2));
    }

    @Test
    void sinesPassOrAreRejectedWhenStreaming() {
        for (int k : new int[] {2, 4}) {
            assertEquals(1, throughDecimator(k, 0.1), 1e-3, "k=" + k + ": 0.1 fs passes");
            assertEquals(1, throughDecimator(k, 0.38), 2e-3, "k=" + k + ": 0.38 fs passes");
            // 0.7 fs would alias to 0.3 fs: it must be at least 80 dB down
            assertTrue(throughDecimator(k, 0.7) < 1e-4, "k=" + k + ": 0.7 fs rejected");
            assertTrue(throughDecimator(k, 0.95) < 1e-4, "k=" + k + ": 0.95 fs rejected");
        }
    }

    @Test
    void outputComesEveryKthInputAndDelayIsHalfTheLength() {
        DecimationFilter d = new DecimationFilter(4);
        int due = 0;
        for (int n = 1; n <= 40; n++) {
            if (d.push(0)) {
                due++;
                assertEquals(0, n % 4);
            }
        }
        assertEquals(10, due);
        assertEquals((d.taps().length - 1) / 2.0, d.delaySteps(), 0);
        assertThrows(IllegalArgumentException.class, () -> new DecimationFilter(1));
    }
}
