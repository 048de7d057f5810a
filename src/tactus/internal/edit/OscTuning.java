package tactus.internal.edit;

import tactus.engine.Tuning;
import tactus.internal.model.Check;
import tactus.internal.model.ModelBase;

/**
 * Pole-matched oscillator tuning in the model's units: the stiffness and damping that make an oscillator ring
 * at exactly a given pitch and decay by 60 dB in exactly a given time at the current simulation rate, air
 * friction included, and the pitch and decay an oscillator actually has. The caller holds the model's lock.
 */
public final class OscTuning {
    private OscTuning() {
    }

    /** @return {K, Z} in model units for a pole-matched oscillator of the given inertia. */
    public static double[] coefficients(ModelBase c, ParamEditor params, String op, String name, double mass, double freqHz, double t60) {
        int rate = c.time.simRate();
        Check.positive(op, String.valueOf(name), "mass", mass);
        if (!(freqHz > 0) || !(freqHz < rate / 2.0)) {
            throw Check.fail(op, String.valueOf(name), "freqHz must be in (0, " + rate / 2.0
                    + ") Hz at this simulation rate, got " + freqHz);
        }
        if (!(t60 > 0)) {
            throw Check.fail(op, String.valueOf(name), "t60 must be > 0 s, got " + t60);
        }
        double[] r = Tuning.oscillatorCoefficients(freqHz, t60, rate);
        double k = r[0] * mass;
        double z = r[1] * mass - c.engine.friction();
        if (z < 0) {
            throw Check.fail(op, String.valueOf(name), "air friction alone already decays faster than t60 = "
                    + t60 + " s; use a longer t60 or less friction");
        }
        return new double[] {c.units().stiffnessOut(k), c.units().dampingOut(z)};
    }

    /** Retunes a live oscillator. */
    public static void tune(ModelBase c, ParamEditor params, String op, int id, double freqHz, double t60) {
        params.requireOsc(op, id);
        double[] kz = coefficients(c, params, op, c.dir.massName(id), c.engine.mass(id), freqHz, t60);
        params.setOsc(op, id, kz[0], kz[1]);
    }

    /** @return the frequency (Hz) at which an oscillator rings in this scheme, friction included. */
    public static double frequency(ModelBase c, ParamEditor params, String op, int id) {
        params.requireOsc(op, id);
        double m = c.engine.mass(id);
        return Tuning.discreteFrequency(c.engine.oscStiffness(id) / m,
                (c.engine.oscDamping(id) + c.engine.friction()) / m, c.time.simRate());
    }

    /** @return the 60 dB decay time (s) of an oscillator in this scheme, friction included. */
    public static double t60(ModelBase c, ParamEditor params, String op, int id) {
        params.requireOsc(op, id);
        return Tuning.decayTime60((c.engine.oscDamping(id) + c.engine.friction()) / c.engine.mass(id),
                c.time.simRate());
    }
}
