package tactus.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** The demo's hand waits at the start of its script until the loop ticks, then plays it from its time 0. */
class HeldScriptTest {
    /** A script whose x is its time and whose y is twice its time. */
    private static final tactus.haptics.emulator.Hand.Script RAMP = (t, out) -> {
        out[0] = t;
        out[1] = 2 * t;
    };

    @Test
    void holdsAtTheFirstPointUntilStartedWhateverTheEmulatorsTime() {
        HeldScript s = new HeldScript(RAMP);
        double[] out = new double[2];
        for (double t : new double[] {0, 0.4, 1.3, 7.5}) {
            s.at(t, out);
            assertEquals(0, out[0], 0, "x before the start, emulator time " + t);
            assertEquals(0, out[1], 0, "y before the start, emulator time " + t);
        }
        assertFalse(s.started());
    }

    @Test
    void playsFromItsTimeZeroAtTheEmulatorsTimeOfTheStart() {
        for (double origin : new double[] {0.2, 1.26, 3.0}) {
            HeldScript s = new HeldScript(RAMP);
            s.startAt(origin);
            assertTrue(s.started());
            double[] out = new double[2];
            s.at(origin - 0.1, out);
            assertEquals(0, out[0], 0, "just before the start");
            for (double after : new double[] {0, 0.25, 2.0}) {
                s.at(origin + after, out);
                assertEquals(after, out[0], 1e-12, "x at " + after + " s into the script, origin " + origin);
                assertEquals(2 * after, out[1], 1e-12, "y at " + after + " s into the script, origin " + origin);
            }
        }
    }

    @Test
    void rejectsANonFiniteStartAndANullScript() {
        HeldScript s = new HeldScript(RAMP);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> s.startAt(Double.NaN));
        assertTrue(e.getMessage().contains("NaN"), e.getMessage());
        assertFalse(s.started());
        assertThrows(IllegalArgumentException.class, () -> new HeldScript(null));
    }
}
