package tactus;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

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

    @Test
    void retuningAfterARateChangeKeepsThePitch() {
        PhysicalModel m = new PhysicalModel(44100, 60, paramSystem.REAL_UNITS);
        m.addOsc3DTuned("o", 0.01, 3000, Double.POSITIVE_INFINITY, new Vect3D(), new Vect3D(0, 0, 1));
        m.setSimRate(22050);
        double warped = m.getOscFrequency("o");
        m.tuneOsc("o", 3000, Double.POSITIVE_INFINITY);
        assertEquals(3000, m.getOscFrequency("o"), 1e-6);
        // the plain rescaling kept k in N/m, so the scheme's warping came back
        assertEquals(true, Math.abs(warped - 3000) > 1.0);
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
