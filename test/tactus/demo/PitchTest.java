package tactus.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * The demo's FFT pitch measurement on signals whose frequencies are known exactly: decaying partials of a
 * string-like tone, with a DC offset and an offset start, are found to a small fraction of the resolution.
 */
class PitchTest {
    static final int RATE = 44100;

    private static float[] tone(int n, double[] hz, double[] amplitude, double decayPerSecond) {
        float[] x = new float[n];
        for (int i = 0; i < n; i++) {
            double t = i / (double) RATE;
            double v = 0.01; // a small DC offset
            for (int k = 0; k < hz.length; k++) {
                v += amplitude[k] * Math.exp(-decayPerSecond * t) * Math.sin(2 * Math.PI * hz[k] * t + k);
            }
            x[i] = (float) v;
        }
        return x;
    }

    @Test
    void findsDecayingPartialsToAFractionOfTheResolution() {
        double[] hz = {224.8431, 449.1665, 672.4506};
        float[] x = tone(3 * RATE, hz, new double[] {0.3, 0.2, 0.1}, 0.7);
        int from = RATE / 3;
        int count = 2 * RATE;
        Pitch p = new Pitch(x, from, count, RATE);
        assertEquals(RATE / (double) count, p.resolutionHz(), 1e-12);
        assertTrue(p.binHz() <= p.resolutionHz() / Pitch.PADDING, "zero-padded: " + p.binHz());
        for (double f : hz) {
            double measured = p.peakHz(f - 90, f + 90);
            assertEquals(0, Demo.cents(measured, f), 0.05, "partial at " + f + " Hz measured " + measured);
        }
        // a 0.5 % error in the frequency (8.6 cents) is far outside that
        float[] off = tone(3 * RATE, new double[] {hz[0] * 1.005}, new double[] {0.3}, 0.7);
        double measured = new Pitch(off, from, count, RATE).peakHz(hz[0] - 90, hz[0] + 90);
        assertEquals(8.63, Demo.cents(measured, hz[0]), 0.05);
    }

    @Test
    void rejectsBadArguments() {
        float[] x = new float[100];
        assertThrows(IllegalArgumentException.class, () -> new Pitch(x, 90, 20, RATE));
        assertThrows(IllegalArgumentException.class, () -> new Pitch(x, 0, 8, RATE));
        assertThrows(IllegalArgumentException.class, () -> new Pitch(x, 0, 50, 0));
        assertThrows(IllegalArgumentException.class, () -> new Pitch(x, 0, 50, RATE).peakHz(10, 11));
    }
}
