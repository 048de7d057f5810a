package tactus.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import tactus.PhysicalModel;
import tactus.Vect3D;
import tactus.paramSystem;

/**
 * setSimRate in REAL_UNITS keeps the physical system: positions stay, velocities in units per second stay,
 * and every coefficient is re-derived for the new rate. An oscillator of k N/m and m kg then rings at the
 * discrete frequency of the new rate, fd(fs) = fs / (2 pi) acos(1 - k / (2 m fs^2)) Hz, which differs from the
 * one before the change only by the frequency warping of the scheme, about (w0/fs)^2 / 24 relative.
 */
class SimRateChangeTest {

    private static double discreteHz(double k, double m, double fs) {
        return fs / (2 * Math.PI) * Math.acos(1 - k / (2 * m * fs * fs));
    }

    // An Osc3D (10 Hz) switched from 1 kHz to 2 kHz: frequency in Hz within warping, velocity unchanged.
    @Test
    void oscillatorKeepsItsFrequencyInHertzAndItsVelocity() {
        double m = 0.01;
        double k = 40;
        PhysicalModel pm = new PhysicalModel(1000, 30, paramSystem.REAL_UNITS);
        pm.addOsc3D("o", m, k, 0, new Vect3D(0, 0, 0), new Vect3D(0, 0, 1));
        pm.init();
        double[] before = Signals.record(pm, "o", 2, 0, 5000);
        Vect3D v = pm.getMatVelocity("o");
        Vect3D p = pm.getMatPosition("o");
        pm.setSimRate(2000);
        assertEquals(p.z, pm.getMatPosition("o").z, 0.0, "position kept");
        assertEquals(v.z, pm.getMatVelocity("o").z, 1e-12 * Math.abs(v.z), "velocity in m/s kept");
        assertTrue(Signals.relErr(pm.getMatStiffness("o"), k) < 1e-12, "stiffness in N/m kept");
        double[] after = Signals.record(pm, "o", 2, 0, 10000);
        double f1 = 1000 / Signals.fittedPeriod(before, 1, before.length - 1);
        double f2 = 2000 / Signals.fittedPeriod(after, 1, after.length - 1);
        assertTrue(Signals.relErr(f1, discreteHz(k, m, 1000)) < 1e-9, "f at 1 kHz " + f1);
        assertTrue(Signals.relErr(f2, discreteHz(k, m, 2000)) < 1e-9, "f at 2 kHz " + f2);
        double w0 = Math.sqrt(k / m);
        double warp = (w0 / 1000) * (w0 / 1000) / 24;
        assertTrue(Math.abs(f2 - f1) / f1 < 1.01 * warp, "Hz drift " + (f2 - f1) / f1 + " beyond warping " + warp);
        assertTrue(Math.abs(f2 - f1) / f1 > 0.5 * warp, "the warping really is the difference");
    }

    // A falling mass at its terminal velocity -g M / f stays there when the rate changes (the displacement per
    // step is rescaled to the new fixed point -g M / (f fs)).
    @Test
    void terminalVelocityIsKeptAcrossARateChange() {
        PhysicalModel pm = new PhysicalModel(1000, 30, paramSystem.REAL_UNITS);
        pm.setGravity(9.81);
        pm.setFriction(4);
        pm.addMass3D("m", 0.5, new Vect3D(0, 0, 0), new Vect3D(0, 0, 0));
        pm.init();
        pm.computeNSteps(5000);   // 40 time constants M/f
        double vInf = -9.81 * 0.5 / 4;
        assertEquals(vInf, pm.getMatVelocity("m").z, 1e-9);
        pm.setSimRate(3000);
        for (int i = 0; i < 10; i++) {
            pm.computeNSteps(300);
            assertEquals(vInf, pm.getMatVelocity("m").z, 1e-9);
        }
    }

    // A Mass3D on a Spring3D to ground: after the switch, the very next step must follow the new-rate scheme
    // Y(n+1) = 2 Y(n) - Y'(n-1) - (k / (m fs'^2)) Y(n), where Y'(n-1) = Y(n) - v / fs' is the rescaled previous
    // position. The spring force pending in the force buffer was computed in per-step units of the old rate
    // and must be rescaled with the other coefficients (by (fs / fs')^2), or the mass receives a one-step
    // impulse error of (fs'^2 / fs^2 - 1) times the spring force.
    @Test
    void pendingLinkForceIsRescaledWithTheRate() {
        double m = 0.01;
        double k = 40;
        PhysicalModel pm = new PhysicalModel(1000, 30, paramSystem.REAL_UNITS);
        pm.addGround3D("g", new Vect3D(0, 0, 0));
        pm.addMass3D("m", m, new Vect3D(0, 0, 0.6), new Vect3D(0, 0, 0));
        pm.addSpring3D("s", 0.5, k, "m", "g");
        pm.init();
        pm.computeNSteps(5);
        double y = pm.getMatPosition("m").z - 0.5;
        pm.setSimRate(2000);
        double yPrev = y - pm.getMatVelocity("m").z / 2000;
        double kAlgo = k / (2000.0 * 2000.0);
        double expected = 2 * y - yPrev - kAlgo / m * y;
        pm.computeStep();
        double actual = pm.getMatPosition("m").z - 0.5;
        // the one-step force term is about 1e-4 m here; 1e-12 m is round-off
        assertEquals(expected, actual, 1e-12, "first step after setSimRate(2000)");
    }

    // The haptic accumulator holds a force summed in per-step units; across a rate change it must still read
    // back in newtons: 7 steps of 100 N before the switch and 3 after give 1000 N.
    @Test
    void accumulatedHapticForceKeepsItsNewtons() {
        PhysicalModel pm = new PhysicalModel(1000, 30, paramSystem.REAL_UNITS);
        pm.addHapticInput3D("h", new Vect3D(0, 0, 0), 1);
        pm.addGround3D("g", new Vect3D(0, 0, 1));
        pm.addSpring3D("s", 0.5, 200, "h", "g");
        pm.init();
        pm.computeNSteps(7);
        pm.setSimRate(4000);
        pm.computeNSteps(3);
        assertEquals(1000.0, pm.getHapticForce("h").z, 1e-9);
    }

    // In ALGO_UNITS coefficients are per step, so changing the rate changes nothing per step: the trajectory
    // in steps is bit-identical to an untouched model (only the velocity reading in units/s scales with fs).
    @Test
    void algoUnitsRateChangeKeepsThePerStepDynamics() {
        PhysicalModel a = new PhysicalModel(1000, 30);
        PhysicalModel b = new PhysicalModel(1000, 30);
        for (PhysicalModel pm : new PhysicalModel[] {a, b}) {
            pm.setGravity(1e-7);
            pm.setFriction(1e-4);
            pm.addGround3D("g", new Vect3D(0, 0, 0));
            pm.addMass3D("m", 1, new Vect3D(0, 0, 1.1), new Vect3D(0, 0, 0));
            pm.addSpringDamper3D("s", 1, 0.1, 0.01, "m", "g");
            pm.init();
            pm.computeNSteps(100);
        }
        double v = a.getMatVelocity("m").z;
        b.setSimRate(3000);
        assertEquals(3 * v, b.getMatVelocity("m").z, 1e-12 * Math.abs(v), "per-step displacement kept");
        a.computeNSteps(2000);
        b.computeNSteps(2000);
        assertEquals(a.getMatPosition("m").z, b.getMatPosition("m").z, 0.0);
    }
}
