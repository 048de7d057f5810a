package tactus.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.function.DoubleUnaryOperator;
import org.junit.jupiter.api.Test;
import tactus.Attractor3D;
import tactus.PhysicalModel;
import tactus.Vect3D;
import tactus.paramSystem;

/**
 * REAL_UNITS and ALGO_UNITS describe the same system. With fs steps per second the engine works with
 * K/fs^2 (stiffness, N/m), Z/fs (damping and friction, N·s/m), g/fs^2 (gravity, m/s^2), A/fs^2 (attraction,
 * N·m^2) and F/fs^2 (forces and energies, N and J); masses and lengths are the same in both systems and
 * velocities are given in units per second in both. A REAL model and an ALGO model fed with the converted
 * coefficients must therefore produce the same trajectories, and a value set in REAL units must read back
 * unchanged.
 */
class UnitsEquivalenceTest {
    private static final int FS = 1000;
    private static final String[] MASSES = {"m1", "m2", "m3", "m4", "m5", "o"};

    private static final double FS2 = (double) FS * FS;

    /** A chain of spring-dampers with an oscillator, an attractor, a contact and a floor. */
    private static PhysicalModel network(paramSystem sys) {
        boolean real = sys == paramSystem.REAL_UNITS;
        // stiffness, gravity and attraction are divided by fs^2 for the ALGO model, damping and friction by fs
        DoubleUnaryOperator s2 = v -> real ? v : v / FS2;
        DoubleUnaryOperator s1 = v -> real ? v : v / FS;
        PhysicalModel pm = new PhysicalModel(FS, 30, sys);
        pm.setGravity(s2.applyAsDouble(9.81));
        pm.setFriction(s1.applyAsDouble(0.001));
        pm.addGround3D("g0", new Vect3D(0, 0, 0));
        for (int i = 1; i <= 5; i++) {
            pm.addMass3D("m" + i, 0.01 + 0.002 * i, new Vect3D(0.1 * i, 0.01 * (i % 2), 0.005 * i),
                    new Vect3D(0.1 * i, -0.2, 0.3 * (i - 3)));
        }
        pm.addGround3D("g6", new Vect3D(0.6, 0, 0));
        for (int i = 0; i < 6; i++) {
            String a = i == 0 ? "g0" : "m" + i;
            String b = i == 5 ? "g6" : "m" + (i + 1);
            pm.addSpringDamper3D("sd" + i, 0.1, s2.applyAsDouble(200), s1.applyAsDouble(0.05), a, b);
        }
        pm.addOsc3D("o", 0.02, s2.applyAsDouble(50), s1.applyAsDouble(0.01), new Vect3D(0.3, 0.1, 0),
                new Vect3D(0, 0.5, 0));
        pm.addSpringDamper3D("so", 0.1, s2.applyAsDouble(100), s1.applyAsDouble(0.02), "o", "m3");
        pm.addAttractor3D("att", 0.05, s2.applyAsDouble(0.01), "m1", "o");
        pm.addContact3D("c", 0.08, s2.applyAsDouble(500), s1.applyAsDouble(0.05), "m5", "o");
        pm.addPlaneContact("floor", 0, s2.applyAsDouble(1000), s1.applyAsDouble(0.1), 2, -0.01, "m2");
        pm.init();
        return pm;
    }

    // Step by step for 5000 steps: same positions (1e-12 of the model size, 1 m), forces scaled by fs^2.
    @Test
    void realAndConvertedAlgoModelsFollowTheSameTrajectory() {
        PhysicalModel real = network(paramSystem.REAL_UNITS);
        PhysicalModel algo = network(paramSystem.ALGO_UNITS);
        for (int n = 1; n <= 5000; n++) {
            real.computeStep();
            algo.computeStep();
            for (String m : MASSES) {
                Vect3D pr = real.getMatPosition(m);
                Vect3D pa = algo.getMatPosition(m);
                assertEquals(pa.x, pr.x, 1e-12, m + " x at step " + n);
                assertEquals(pa.y, pr.y, 1e-12, m + " y at step " + n);
                assertEquals(pa.z, pr.z, 1e-12, m + " z at step " + n);
                Vect3D fr = real.getMatForce(m);
                Vect3D fa = algo.getMatForce(m).mult(FS2);
                // a net force is a sum of link forces of up to ~2 N that largely cancel: compare to that scale
                double scale = 1e-12 * 2;
                assertEquals(fa.x, fr.x, scale, m + " force x (N) at step " + n);
                assertEquals(fa.z, fr.z, scale, m + " force z (N) at step " + n);
            }
        }
        double e = algo.getTotalEnergy() * FS2;
        assertEquals(e, real.getTotalEnergy(), 1e-12 * Math.abs(e), "energy in joules");
        // the model did something: the chain moved well beyond round-off
        assertTrue(Math.abs(real.getMatPosition("m3").y) > 1e-4);
    }

    // Values set in REAL units read back unchanged, through every getter, at an awkward rate.
    @Test
    void realUnitValuesRoundTrip() {
        PhysicalModel pm = new PhysicalModel(44100, 30, paramSystem.REAL_UNITS);
        pm.addMass3D("a", 0.3, new Vect3D(0, 0, 0), new Vect3D(0, 0, 0));
        pm.addOsc3D("o", 0.3, 1234.5, 0.75, new Vect3D(1, 0, 0), new Vect3D(0, 0, 0));
        pm.addSpringDamper3D("s", 0.5, 987.25, 3.3, "a", "o");
        Attractor3D att = pm.addAttractor3D("att", 0.1, 0.0123, "a", "o");
        pm.createLinkSubset("L");
        pm.addLinkToSubset("s", "L");
        pm.createMatSubset("O");
        pm.addMatToSubset("o", "O");
        pm.setFriction(0.07);
        pm.setGravity(9.81);
        pm.init();
        double tol = 1e-12;
        assertTrue(Signals.relErr(pm.getMatStiffness("o"), 1234.5) < tol);
        assertTrue(Signals.relErr(pm.getMatDamping("o"), 0.75) < tol);
        assertTrue(Signals.relErr(pm.getLinkStiffness("s"), 987.25) < tol);
        assertTrue(Signals.relErr(pm.getLinkDamping("s"), 3.3) < tol);
        assertTrue(Signals.relErr(att.getAttraction(), 0.0123) < tol);
        assertEquals(0.07, pm.getFriction(), 0.0);
        assertEquals(9.81, pm.getGravity(), 0.0);
        pm.changeStiffnessParamOfSubset(555.5, "L");
        pm.changeDampingParamOfSubset(1.25, "L");
        assertTrue(Signals.relErr(pm.getParamValueOfSubset("L", "stiffness"), 555.5) < tol);
        assertTrue(Signals.relErr(pm.getParamValueOfSubset("L", "damping"), 1.25) < tol);
        assertTrue(Signals.relErr(pm.getLinkDamping("s"), 1.25) < tol);
        pm.changeStiffnessParamOfSubset(4321, "O");
        pm.changeDampingParamOfSubset(0.5, "O");
        assertTrue(Signals.relErr(pm.getParamValueOfSubset("O", "stiffness"), 4321) < tol);
        assertTrue(Signals.relErr(pm.getParamValueOfSubset("O", "damping"), 0.5) < tol);
        pm.setLinkParams("s", 10, 0.2, 0.4);
        assertTrue(Signals.relErr(pm.getLinkStiffness("s"), 10) < tol);
        assertTrue(Signals.relErr(pm.getLinkDamping("s"), 0.2) < tol);
        att.setAttraction(-0.5);
        assertTrue(Signals.relErr(att.getAttraction(), -0.5) < tol);
    }

    // Damping set through a subset in REAL units acts as z / fs per step (the reference divided by fs^2):
    // the pole radius of a mass on a spring-damper to ground is sqrt(1 - z / (M fs)).
    @Test
    void subsetDampingActsWithTheRightScale() {
        double m = 0.05;
        double k = 100;
        double z = 0.5;
        PhysicalModel pm = new PhysicalModel(FS, 30, paramSystem.REAL_UNITS);
        pm.addGround3D("g", new Vect3D(0, 0, 0));
        pm.addMass3D("m", m, new Vect3D(0, 0, 0.6), new Vect3D(0, 0, 0));
        pm.addSpringDamper3D("s", 0.5, k, 0, "m", "g");
        pm.createLinkSubset("L");
        pm.addLinkToSubset("s", "L");
        pm.changeDampingParamOfSubset(z, "L");
        pm.init();
        double[] y = Signals.record(pm, "m", 2, 0.5, 3000);
        double[] ab = Signals.fitAr2(y, 2, y.length - 1);
        assertEquals(1 - z / (m * FS), ab[1], 1e-10, "rho^2 = 1 - Z/M per step");
        assertEquals(2 - (k / ((double) FS * FS) + z / FS) / m, ab[0], 1e-10);
    }

    // Forces and energies come back in N and J; an impulse given in N moves the mass by F / (M fs^2).
    @Test
    void forcesAndEnergiesAreReportedInSiUnits() {
        PhysicalModel pm = new PhysicalModel(FS, 30, paramSystem.REAL_UNITS);
        pm.addGround3D("g", new Vect3D(0, 0, 0));
        pm.addMass3D("m", 0.2, new Vect3D(0, 0, 0.55), new Vect3D(0, 0, 0));
        pm.addMass3D("free", 0.2, new Vect3D(5, 0, 0), new Vect3D(0, 0, 0));
        pm.addSpring3D("s", 0.5, 200, "m", "g");
        pm.init();
        assertEquals(0.5 * 200 * 0.05 * 0.05, pm.getPotentialEnergy(), 1e-12, "1/2 k e^2 in J");
        pm.computeStep();
        assertEquals(-200 * 0.05, pm.getMatForce("m").z, 1e-10, "-k e in N");
        pm.triggerForceImpulse("free", 3.0, 0, 0);
        pm.computeStep();
        assertEquals(5 + 3.0 / 0.2 / ((double) FS * FS), pm.getMatPosition("free").x, 1e-15);
        // it now moves at (F / M) / fs m/s and carries 1/2 M v^2 J
        double v = 3.0 / 0.2 / FS;
        assertEquals(v, pm.getMatVelocity("free").x, 1e-12);
    }
}
