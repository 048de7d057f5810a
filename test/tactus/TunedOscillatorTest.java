package tactus;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * Pole-matched oscillators from the facade: they must ring at exactly the requested pitch and decay in
 * exactly the requested time, in both unit systems and with air friction, which a naive k = m(2πf)²
 * mapping does not (it is sharp by about (2πf/fs)²/24).
 */
class TunedOscillatorTest {

    /** Measures the ringing frequency from the exact recurrence of the last three samples' zero crossings. */
    private static double measuredFrequency(PhysicalModel m, String name, int steps) {
        double prev = m.getMatPosition(name).z;
        double first = -1;
        double last = -1;
        int crossings = 0;
        for (int i = 1; i <= steps; i++) {
            m.computeStep();
            double z = m.getMatPosition(name).z;
            if (prev > 0 && z <= 0) {
                double t = i - 1 + prev / (prev - z);
                if (first < 0) {
                    first = t;
                }
                last = t;
                crossings++;
            }
            prev = z;
        }
        return m.getSimRate() * (crossings - 1) / (last - first);
    }

    @Test
    void tunedOscillatorRingsAtThePitchAskedFor() {
        for (paramSystem sys : paramSystem.values()) {
            PhysicalModel m = new PhysicalModel(44100, 60, sys);
            m.setFriction(sys == paramSystem.REAL_UNITS ? 1e-4 : 1e-6);
            m.addOsc3DTuned("o", 0.01, 5000, 2.0, new Vect3D(), new Vect3D(0, 0, 1));
            m.init();
            assertEquals(5000, m.getOscFrequency("o"), 1e-6);
            double f = measuredFrequency(m, "o", 20000);
            assertEquals(5000, f, 5000 * 2e-6, sys + ": measured pitch");
        }
    }

    @Test
    void tunedDecayTimeIsExact() {
        PhysicalModel m = new PhysicalModel(44100, 60, paramSystem.REAL_UNITS);
        m.addOsc1DTuned("o", 0.002, 440, 0.5, new Vect3D(), new Vect3D(0, 0, 1));
        m.init();
        assertEquals(0.5, m.getOscT60("o"), 1e-9);
        // envelope: after 0.5 s the peak amplitude has fallen by 1000x (60 dB)
        double early = 0;
        for (int i = 0; i < 200; i++) {
            m.computeStep();
            early = Math.max(early, Math.abs(m.getMatPosition("o").z));
        }
        m.computeNSteps(22050 - 200);
        double late = 0;
        for (int i = 0; i < 200; i++) {
            m.computeStep();
            late = Math.max(late, Math.abs(m.getMatPosition("o").z));
        }
        assertEquals(1e-3, late / early, 1e-4);
    }

    /**
     * Fits the two-term recurrence z(n+1) = a z(n) - b z(n-1) that a free linear oscillator obeys exactly to
     * {@code steps} simulated samples (least squares), and returns {pitch in Hz, T60 in s, worst residual /
     * amplitude}: the poles are r e^{±iω} with b = r², a = 2 r cos ω, so the pitch is ω fs / 2π and the
     * amplitude falls by 1000x when r^n = 1e-3, after ln(1000) / (-ln r) steps.
     */
    private static double[] measurePitchAndT60(PhysicalModel m, String name, int steps) {
        double[] z = new double[steps + 1];
        z[0] = m.getMatPosition(name).z;
        for (int i = 1; i <= steps; i++) {
            m.computeStep();
            z[i] = m.getMatPosition(name).z;
        }
        double suu = 0, suw = 0, sww = 0, syu = 0, syw = 0;
        for (int n = 1; n < steps; n++) {
            double u = z[n], w = -z[n - 1], y = z[n + 1];
            suu += u * u;
            suw += u * w;
            sww += w * w;
            syu += y * u;
            syw += y * w;
        }
        double det = suu * sww - suw * suw;
        double a = (syu * sww - syw * suw) / det;
        double b = (suu * syw - suw * syu) / det;
        double worst = 0, amp = 0;
        for (int n = 1; n < steps; n++) {
            worst = Math.max(worst, Math.abs(z[n + 1] - a * z[n] + b * z[n - 1]));
            amp = Math.max(amp, Math.abs(z[n]));
        }
        double r = Math.sqrt(b);
        double omega = Math.acos(a / (2 * r));
        double fs = m.getSimRate();
        return new double[] {omega * fs / (2 * Math.PI), Math.log(1000) / (-Math.log(r)) / fs, worst / amp};
    }

    /**
     * An oscillator tuned at 44.1 kHz is moved to 22.05 kHz (REAL_UNITS: K and Z keep their physical values,
     * so the scheme's frequency warping changes), simulated, and measured from its signal: it now rings away
     * from the requested pitch, at the frequency the discrete scheme predicts for the same K/M. After
     * {@link PhysicalModel#tuneOsc} it must ring at exactly the requested pitch and decay in exactly the
     * requested T60, measured from the simulated signal.
     */
    @Test
    void retuningAfterARateChangeKeepsThePitch() {
        double f0 = 3000;
        double t60 = 0.25;
        double mass = 0.01;
        PhysicalModel m = new PhysicalModel(44100, 60, paramSystem.REAL_UNITS);
        m.addOsc3DTuned("o", mass, f0, t60, new Vect3D(), new Vect3D(0, 0, 1));
        m.init();
        double[] at44 = measurePitchAndT60(m, "o", 4000);
        assertEquals(f0, at44[0], f0 * 1e-7, "pitch at 44.1 kHz");
        assertEquals(t60, at44[1], t60 * 1e-6, "T60 at 44.1 kHz");

        m.setSimRate(22050);
        double[] warped = measurePitchAndT60(m, "o", 4000);
        assertTrue(warped[2] < 1e-9, "the oscillator follows a two-term recurrence: residual " + warped[2]);
        // the same K/M on a coarser grid: the explicit scheme's cos ω = 1 - (k + z)/(2 sqrt(1 - z)) per step,
        // with k = K/(M fs^2) and z = Z/(M fs)
        double fs = 22050;
        double k = m.getMatStiffness("o") / mass / (fs * fs);
        double zd = m.getMatDamping("o") / mass / fs;
        double b = 1 - zd;
        double predicted = Math.acos((2 - k - zd) / (2 * Math.sqrt(b))) * fs / (2 * Math.PI);
        assertEquals(predicted, warped[0], predicted * 1e-7, "warped pitch at 22.05 kHz");
        assertTrue(Math.abs(warped[0] - f0) > 10, "a plain rescale keeps K in N/m, so the pitch moves: " + warped[0]);

        m.tuneOsc("o", f0, t60);
        double[] retuned = measurePitchAndT60(m, "o", 4000);
        assertTrue(retuned[2] < 1e-9, "residual " + retuned[2]);
        assertEquals(f0, retuned[0], f0 * 1e-7, "measured pitch after retuning at 22.05 kHz");
        assertEquals(t60, retuned[1], t60 * 1e-6, "measured T60 after retuning at 22.05 kHz");
    }

    @Test
    void impossibleRequestsAreRejected() {
        PhysicalModel m = new PhysicalModel(1000, 60);
        assertThrows(IllegalArgumentException.class,
                () -> m.addOsc3DTuned("o", 1, 600, 1, new Vect3D(), new Vect3D()));
        m.setFriction(0.5);
        assertThrows(IllegalArgumentException.class,
                () -> m.addOsc3DTuned("o", 1, 100, 10, new Vect3D(), new Vect3D()));
        assertEquals(0, m.getNumberOfMats());
    }
}
