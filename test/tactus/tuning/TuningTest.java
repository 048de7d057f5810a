package tactus.tuning;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;
import tactus.Mass;
import tactus.PhysicalModel;
import tactus.Vect3D;
import tactus.engine.Tuning;
import tactus.report.Measure;
import tactus.paramSystem;

/**
 * {@link Tuning} against simulations run through the {@link PhysicalModel} facade and measured with the model-free
 * estimators of {@link Measure} (spectral peak, zero crossings, envelope), not with the scheme's own recurrence.
 */
class TuningTest {
    private static final double FS = 44100;

    /** Records z − rest of an Osc1D started at its rest position with velocity v0, for n + 1 samples. */
    private static double[] ringOsc1D(double kOverM, double zOverM, double fs, int n) {
        double m = 0.37;
        PhysicalModel pm = new PhysicalModel((int) fs, 30);
        pm.addOsc1D("o", m, kOverM * m, zOverM * m, new Vect3D(0, 0, 1.0), new Vect3D(0, 0, 1000));
        pm.init();
        double[] y = new double[n + 1];
        Vect3D p = new Vect3D();
        for (int i = 0; i <= n; i++) {
            if (i > 0) {
                pm.computeStep();
            }
            pm.getMatPosition("o", p);
            y[i] = p.z - 1.0;
        }
        return y;
    }

    /**
     * Simulates a fixed-fixed chain of n Mass1D linked by SpringDamper1D (stiffness ratio kappa) between two
     * Ground1D, from a seeded random displacement at rest, and returns the displacements u[t][j].
     */
    private static double[][] ringChain(int n, double kappa, double fs, int samples, long seed) {
        double m = 0.01;
        PhysicalModel pm = new PhysicalModel((int) fs, 30);
        Random rnd = new Random(seed);
        pm.addGround1D("g0", new Vect3D(0, 0, 0));
        Mass[] masses = new Mass[n];
        for (int j = 1; j <= n; j++) {
            masses[j - 1] = pm.addMass1D("m" + j, m, new Vect3D(j, 0, rnd.nextDouble() - 0.5), new Vect3D());
        }
        pm.addGround1D("g1", new Vect3D(n + 1, 0, 0));
        for (int j = 0; j <= n; j++) {
            String a = j == 0 ? "g0" : "m" + j;
            String b = j == n ? "g1" : "m" + (j + 1);
            pm.addSpringDamper1D("s" + j, 0, kappa * m, 0, a, b);
        }
        pm.init();
        double[][] u = new double[samples][n];
        Vect3D p = new Vect3D();
        for (int t = 0; t < samples; t++) {
            if (t > 0) {
                pm.computeStep();
            }
            for (int j = 0; j < n; j++) {
                u[t][j] = masses[j].getPosition(p).z;
            }
        }
        return u;
    }

    private static double relErr(double a, double b) {
        return Math.abs(a - b) / Math.abs(b);
    }

    // ------------------------------------------------------------------ closed forms

    @Test
    void oscillatorFormulasInvertEachOther() {
        for (double f : new double[] {20, 100, 440, 1000, 5000, 10000, 20000}) {
            double k = Tuning.oscillatorStiffness(f, FS);
            assertEquals(f, Tuning.discreteFrequency(k, FS), 1e-9 * f, "undamped round trip at " + f);
            for (double t60 : new double[] {0.01, 0.3, 2, 60}) {
                double[] kz = Tuning.oscillatorCoefficients(f, t60, FS);
                assertEquals(f, Tuning.discreteFrequency(kz[0], kz[1], FS), 1e-9 * f, "damped f " + f + ", " + t60);
                assertEquals(t60, Tuning.decayTime60(kz[1], FS), 1e-9 * t60, "T60 " + f + ", " + t60);
                // the coefficients are where the characteristic polynomial r² + (k + z − 2) r + (1 − z) has its
                // roots: product ρ² = e^(−2σ/fs), sum 2ρ cos θ with θ = 2πf/fs
                double rho = Math.exp(-Math.log(1000) / t60 / FS);
                assertEquals(rho * rho, 1 - kz[1], 1e-15);
                assertEquals(2 * rho * Math.cos(2 * Math.PI * f / FS), 2 - kz[0] - kz[1], 1e-14);
                assertTrue(kz[0] + 2 * kz[1] < 4, "inside the stability region");
            }
        }
        double[] none = Tuning.oscillatorCoefficients(440, Double.POSITIVE_INFINITY, FS);
        assertEquals(0.0, none[1], 0.0);
        assertEquals(Tuning.oscillatorStiffness(440, FS), none[0], 1e-16);
        assertEquals(Double.POSITIVE_INFINITY, Tuning.decayTime60(0, FS));
    }

    @Test
    void naiveMappingIsSharpByTheDocumentedCents() {
        // numerics §1.4: +1.47 c at 1 kHz, +5.9 c at 2 kHz, +38.4 c at 5 kHz, +185 c at 10 kHz (44.1 kHz)
        double[][] table = {{1000, 1.47}, {2000, 5.9}, {5000, 38.4}, {10000, 185}};
        for (double[] row : table) {
            double c = Tuning.cents(Tuning.discreteFrequency(Tuning.naiveStiffness(row[0], FS), FS), row[0]);
            assertEquals(row[1], c, 0.01 * row[1] + 0.01, "naive mapping at " + row[0] + " Hz");
        }
    }

    // ------------------------------------------------------------------ simulated oscillators

    @Test
    void poleMatchedOscillatorRingsAtExactlyF() {
        for (double f : new double[] {100, 1000, 5000, 15000}) {
            double[] y = ringOsc1D(Tuning.oscillatorStiffness(f, FS), 0, FS, (int) FS);
            double measured = Measure.frequency(y, FS);
            assertTrue(relErr(measured, f) < 1e-6, f + " Hz: measured " + measured);
            // it starts at its rest position, so it is A sin(2πft) with no phase error either
            double[] fit = Measure.sinePhase(y, f, FS);
            assertEquals(0.0, fit[1], 1e-6, "phase at " + f + " Hz");
        }
    }

    @Test
    void naiveOscillatorIsSharpAsPredicted() {
        double f = 5000;
        double k = Tuning.naiveStiffness(f, FS);
        double[] y = ringOsc1D(k, 0, FS, (int) FS);
        double measuredCents = Tuning.cents(Measure.frequency(y, FS), f);
        double predicted = Tuning.cents(Tuning.discreteFrequency(k, FS), f);
        assertEquals(predicted, measuredCents, 1e-3);
        assertEquals(38.4, measuredCents, 0.1, "+38 c at 5 kHz");
    }

    @Test
    void poleMatchedDampedOscillatorHasExactFrequencyAndT60() {
        double[][] cases = {{5000, 0.3}, {440, 1.5}, {100, 0.5}, {12000, 0.02}};
        for (double[] c : cases) {
            double f = c[0];
            double t60 = c[1];
            double[] kz = Tuning.oscillatorCoefficients(f, t60, FS);
            int n = (int) Math.min(FS, 1.5 * t60 * FS);     // down 90 dB at most: far from round-off
            double[] y = ringOsc1D(kz[0], kz[1], FS, n);
            double measured = Measure.frequency(y, FS);
            assertTrue(relErr(measured, f) < 1e-6, f + " Hz, T60 " + t60 + ": measured " + measured + " Hz");
            double t = Measure.decayTime60(y, 1, n, FS);
            assertTrue(relErr(t, t60) < 1e-6, f + " Hz, T60 " + t60 + ": measured T60 " + t + " s");
        }
        // the naive mapping of the same 5 kHz / 0.3 s tone (numerics §1.4: about 5113.66 Hz and 0.2998 s):
        // k = (ω² + σ²)/fs², z = 2σ/fs with σ = ln(1000)/T60, written out here; the scheme's recurrence
        // y(n+1) = (2 - k - z) y(n) - (1 - z) y(n-1) has poles r e^{±iθ}, r = sqrt(1 - z), cos θ = (2 - k - z)/(2r),
        // so it rings at θ fs/2π and decays by 60 dB in ln(1000)/(-ln r) steps
        double sigma = Math.log(1000) / 0.3;
        double w = 2 * Math.PI * 5000;
        double k = (w * w + sigma * sigma) / (FS * FS);
        double z = 2 * sigma / FS;
        double[] naive = Tuning.naiveCoefficients(5000, 0.3, FS);
        assertEquals(k, naive[0], 1e-15 * k);
        assertEquals(z, naive[1], 1e-15 * z);
        double r = Math.sqrt(1 - z);
        double naivePitch = Math.acos((2 - k - z) / (2 * r)) * FS / (2 * Math.PI);
        double naiveT60 = Math.log(1000) / (-Math.log(r)) / FS;
        double[] y = ringOsc1D(naive[0], naive[1], FS, (int) (0.45 * FS));
        assertEquals(naivePitch, Measure.frequency(y, FS), 1e-6 * naivePitch);
        assertEquals(naiveT60, Measure.decayTime60(y, 1, y.length - 1, FS), 1e-6 * naiveT60);
        assertEquals(5113.66, naivePitch, 0.01, "numerics §1.4");
        assertTrue(naivePitch - 5000 > 100, "the naive mapping is sharp");
    }

    // ------------------------------------------------------------------ strings

    @Test
    void stringStiffnessGivesTheRequestedFundamental() {
        int n = 30;
        double f1 = 440;
        double kappa = Tuning.stringStiffnessForFundamental(f1, n, FS);
        assertEquals(f1, Tuning.stringFundamental(kappa, n, FS), 1e-9 * f1);
        double[][] u = ringChain(n, kappa, FS, 22050, 1);
        double measured = Measure.frequency(Measure.modeProjection(u, 1), FS);
        assertTrue(relErr(measured, f1) < 1e-6, "fundamental " + measured + " Hz, wanted " + f1);
        // the upper partials follow the dispersion formula (κ ≈ 0.63 here: compressed, not harmonic)
        for (int m : new int[] {2, 5, 9}) {
            double fm = Measure.frequency(Measure.modeProjection(u, m), FS);
            double expected = Tuning.stringPartial(kappa, n, m, FS);
            assertTrue(relErr(fm, expected) < 1e-6, "partial " + m + ": " + fm + " vs " + expected);
            assertTrue(fm < m * f1, "κ < 1 gives flat upper partials");
        }
    }

    @Test
    void unitStiffnessStringIsExactlyHarmonic() {
        double f1 = 220;
        int n = Tuning.stringMassesForFundamental(f1, FS);
        assertEquals(99, n, "N + 1 = round(44100 / 440) = 100");
        double fundamental = Tuning.harmonicStringFundamental(n, FS);
        assertEquals(220.5, fundamental, 1e-12);
        assertEquals(Tuning.cents(220.5, 220), Tuning.stringRoundingCents(f1, FS), 1e-12);
        assertEquals(3.93, Tuning.stringRoundingCents(f1, FS), 0.01);
        double[][] u = ringChain(n, 1.0, FS, 44100, 2);
        for (int m = 1; m <= 10; m++) {
            double fm = Measure.frequency(Measure.modeProjection(u, m), FS);
            double err = Tuning.cents(fm, m * fundamental);
            assertTrue(Math.abs(err) < 1e-4, "partial " + m + " off by " + err + " cents (" + fm + " Hz)");
        }
        // the same chain at K/M = 0.5 is not harmonic: partial 10 is flat by several cents
        double[][] soft = ringChain(n, 0.5, FS, 44100, 2);
        double f1s = Measure.frequency(Measure.modeProjection(soft, 1), FS);
        double f10s = Measure.frequency(Measure.modeProjection(soft, 10), FS);
        assertTrue(Tuning.cents(f10s, 10 * f1s) < -3, "K/M = 0.5: partial 10 at " + f10s / f1s + " x f1");
        assertEquals(Tuning.stringPartial(0.5, n, 10, FS), f10s, 1e-6 * f10s);
    }

    @Test
    void retunedStringHasTheExactFundamentalAndNearlyHarmonicPartials() {
        double f1 = 440;
        int n = Tuning.stringMassesForRetuning(f1, FS);
        assertEquals(49, n, "N + 1 = floor(44100 / 880) = 50");
        double kappa = Tuning.stringStiffnessForFundamental(f1, n, FS);
        assertTrue(kappa <= 1 && kappa > 0.99, "K/M just below 1: " + kappa);
        double[][] u = ringChain(n, kappa, FS, 22050, 3);
        for (int m = 1; m <= 10; m++) {
            double fm = Measure.frequency(Measure.modeProjection(u, m), FS);
            assertEquals(Tuning.stringPartial(kappa, n, m, FS), fm, 1e-6 * fm, "partial " + m);
            double err = Tuning.cents(fm, m * f1);
            assertTrue(m == 1 ? Math.abs(err) < 1e-4 : err < 0 && err > -0.2, "partial " + m + ": " + err + " c");
        }
        // whatever f1, the retuned K/M never exceeds 1, so it is always stable
        for (double f = 20; f < FS / 4; f *= 1.037) {
            int nn = Tuning.stringMassesForRetuning(f, FS);
            double k = Tuning.stringStiffnessForFundamental(f, nn, FS);
            assertTrue(k <= 1 + 1e-12, f + " Hz: K/M " + k);
        }
    }

    @Test
    void stringLimitsAreEnforcedWithNamedValues() {
        // 4 masses at 44.1 kHz reach at most (fs/π) asin(tan(π/10)) ≈ 4.6 kHz
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> Tuning.stringStiffnessForFundamental(6000, 4, FS));
        assertTrue(e.getMessage().contains("6000") && e.getMessage().contains("stability limit"), e.getMessage());
        assertTrue(e.getMessage().contains(String.valueOf(Tuning.stringStabilityLimit(4))), e.getMessage());
        double below = Tuning.stringStiffnessForFundamental(4500, 4, FS);
        assertTrue(below < Tuning.stringStabilityLimit(4));
        assertEquals(2.0, Tuning.stringStabilityLimit(1), 1e-12);
        assertEquals(1 / Math.pow(Math.cos(Math.PI / (2 * 101)), 2), Tuning.stringStabilityLimit(100), 1e-15);
        e = assertThrows(IllegalArgumentException.class, () -> Tuning.stringStiffnessForFundamental(30000, 4, FS));
        assertTrue(e.getMessage().contains("Nyquist"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> Tuning.stringMassesForFundamental(12000, FS));
        assertTrue(e.getMessage().contains("12000") && e.getMessage().contains("11025"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> Tuning.oscillatorStiffness(22050, FS));
        assertTrue(e.getMessage().contains("22050") && e.getMessage().contains("Nyquist"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> Tuning.oscillatorCoefficients(440, 0, FS));
        assertThrows(IllegalArgumentException.class, () -> Tuning.discreteFrequency(4.5, FS));
        assertThrows(IllegalArgumentException.class, () -> Tuning.discreteFrequency(1.0, 1.0, FS));
        assertThrows(IllegalArgumentException.class, () -> Tuning.decayTime60(-0.1, FS));
        assertThrows(IllegalArgumentException.class, () -> Tuning.oscillatorStiffness(440, 0));
    }

    // ------------------------------------------------------------------ start-up

    @Test
    void startVelocityMakesFreeFallExact() {
        int fs = 44100;
        double g = 9.81;
        double v0 = 2.0;
        double[] err = new double[2];
        for (int corrected = 0; corrected < 2; corrected++) {
            PhysicalModel pm = new PhysicalModel(fs, 30, paramSystem.REAL_UNITS);
            pm.setGravity(g);
            double v = corrected == 1 ? Tuning.startVelocity(v0, -g, fs) : v0;
            pm.addMass3D("m", 1, new Vect3D(0, 0, 0), new Vect3D(0, 0, v));
            pm.init();
            pm.computeNSteps(fs);
            err[corrected] = pm.getMatPosition("m").z - (v0 * 1.0 - g / 2);
        }
        // round-off: about n^1.5 ulp(3 m) ~ 1e-8 m after n = 44100 steps (see FreeFallTest for the bound)
        assertEquals(-g / (2 * fs), err[0], 1e-7, "the plain start is ahead by g t / (2 fs)");
        assertEquals(0.0, err[1], 1e-7, "the corrected start is exact up to round-off");
    }
}
