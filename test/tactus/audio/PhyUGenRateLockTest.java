package tactus.audio;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import tactus.PhysicalModel;
import tactus.Vect3D;
import tactus.paramSystem;

/**
 * While a PhyUGen plays a model, its rate is the output's rate times the oversampling, so setSimRate from the sketch
 * is refused: before, setSimRate(48000) under a PhyUGen at 44.1 kHz left the model reporting 48,000 steps/s while
 * Minim stepped it 44,100 times a second (a REAL_UNITS model detuned in silence). The refusal names the PhyUGen and
 * the rates and leaves the model unchanged; the PhyUGen's own rate changes (output rate, oversampling) still work.
 */
class PhyUGenRateLockTest {

    /** A spring-mass in REAL_UNITS (its coefficients are re-derived when the rate changes). */
    private static PhysicalModel oscillator() {
        PhysicalModel m = new PhysicalModel(44100, 60, paramSystem.REAL_UNITS);
        m.addGround3D("g", new Vect3D(0, 0, 0));
        m.addMass3D("m", 0.001, new Vect3D(1, 0.01, 0), new Vect3D());
        m.addSpringDamper3D("s", 1, 2000, 0.0001, "g", "m");
        m.init();
        return m;
    }

    private static float[] play(PhyUGen u, int n) {
        float[] out = new float[n];
        float[] f = new float[1];
        for (int i = 0; i < n; i++) {
            u.tick(f);
            out[i] = f[0];
        }
        return out;
    }

    private static PhyUGen mono(PhyUGen u) {
        u.setSampleRate(44100);
        u.setChannelCount(1);
        u.listenToMass("m", SteppedModel.Y, 100, 0);
        return u;
    }

    @Test
    void setSimRateWhileAPhyUGenPlaysIsRefusedAndTheModelIsUnchanged() {
        PhysicalModel asked = oscillator();
        PhysicalModel twin = oscillator();
        PhyUGen u = mono(new PhyUGen(asked));
        PhyUGen v = mono(new PhyUGen(twin));
        assertArrayEquals(play(v, 1000), play(u, 1000));
        double k = asked.getLinkStiffness("s");
        IllegalStateException e = assertThrows(IllegalStateException.class, () -> asked.setSimRate(48000));
        String msg = e.getMessage();
        assertTrue(msg.startsWith("setSimRate(48000): refused, the model stays at 44100 steps/s"), msg);
        assertTrue(msg.contains("PhyUGen") && msg.contains("44100 Hz x 1 = 44100 steps/s")
                && msg.contains("setOversampling"), msg);
        assertEquals(44100, asked.getSimRate());
        assertEquals(k, asked.getLinkStiffness("s"));
        assertArrayEquals(play(v, 5000), play(u, 5000), "the model plays on exactly as if nothing was asked");
    }

    /** A sketch's own PhyUGen subclass. */
    static final class MyString extends PhyUGen {
        MyString() {
            super(44100);
            mdl.setSimRate(22050); // while building: nothing plays yet, allowed
            mdl.addGround3D("g", new Vect3D(0, 0, 0));
            mdl.addMass3D("m", 1, new Vect3D(1, 0.01, 0), new Vect3D());
            mdl.addSpringDamper3D("s", 1, 0.01, 0, "g", "m");
            mdl.init();
            listenToMass("m", SteppedModel.Y, 100, 0);
        }
    }

    @Test
    void thePhyUGenOwnRateChangesStillWorkAndTheRefusalSaysWhoHoldsTheRate() {
        MyString u = new MyString();
        PhysicalModel m = u.getModel();
        u.setSampleRate(48000); // patched into a 48 kHz output
        u.setChannelCount(1);
        assertEquals(48000, m.getSimRate());
        u.setOversampling(2);
        assertEquals(96000, m.getSimRate());
        play(u, 100);
        String msg = assertThrows(IllegalStateException.class, () -> m.setSimRate(44100)).getMessage();
        assertTrue(msg.contains("MyString (a PhyUGen)") && msg.contains("48000 Hz x 2 = 96000 steps/s")
                && msg.contains("stays at 96000"), msg);
        assertEquals(96000, m.getSimRate());
        u.setOversampling(1);
        assertEquals(48000, m.getSimRate());
        float[][] rendered = OfflineRenderer.renderToArray(u, 22050, 1, 0.1);
        assertEquals(2205, rendered[0].length);
        assertEquals(22050, m.getSimRate(), "rendering at 22.05 kHz sets the model's rate");
    }

    @Test
    void onceRealtimeSteppingEndsTheSketchSetsTheRateAgain() {
        PhysicalModel m = oscillator();
        PhyUGen u = mono(new PhyUGen(m));
        play(u, 100);
        assertThrows(IllegalStateException.class, () -> m.setSimRate(48000));
        m.endRealtimeStepping();
        m.setSimRate(48000);
        assertEquals(48000, m.getSimRate());
        assertThrows(IllegalArgumentException.class, () -> m.setSimRate(0), "the rate is still checked");
    }
}
