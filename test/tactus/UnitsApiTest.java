package tactus;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/**
 * The unit systems at the API boundary: REAL_UNITS getters return exactly what was set (v1 converted
 * twice), velocities are in units per second in both systems, forces in newtons, and setSimRate keeps a
 * REAL_UNITS model the same physical system while an ALGO_UNITS model keeps its per-step coefficients.
 */
class UnitsApiTest {
    static final double REL = 1e-12;

    static Vect3D v(double x, double y, double z) {
        return new Vect3D(x, y, z);
    }

    static void assertRel(double expected, double actual, String what) {
        assertEquals(expected, actual, Math.abs(expected) * REL, what);
    }

    /** A REAL_UNITS model with one of every parameterised module, at an awkward rate. */
    static PhysicalModel realModel(int fs) {
        PhysicalModel m = new PhysicalModel(fs, 60, paramSystem.REAL_UNITS);
        m.setGravity(9.81);
        m.setFriction(0.0123);
        m.addGround3D("g", v(0, 0, 0));
        m.addMass3D("a", 0.05, v(0.1, 0, 0), v(0.3, -0.2, 0.1));
        m.addMass3D("b", 0.07, v(0, 0.12, 0), v(0, 0, 0));
        m.addOsc3D("o", 0.02, 1234.5, 0.0789, v(0, 0, 0.2), v(0, 0, 0));
        m.addOsc1D("o1", 0.03, 987.6, 0.0456, v(0, 0, 0.3), v(0, 0, 0.5));
        m.addSpring3D("sp", 0.1, 321.5, "a", "g");
        m.addDamper3D("da", 0.654, "a", "b");
        m.addSpringDamper3D("sd", 0.11, 2500.25, 0.125, "a", "b");
        m.addSpringDamper1D("s1", 0.01, 1500.5, 0.0625, "o1", "g");
        m.addRope3D("ro", 0.3, 4000.75, 0.25, "b", "g");
        m.addContact3D("co", 0.05, 777.5, 0.33, "a", "o");
        m.addBubble3D("bu", 0.5, 111.125, 0.0777, "b", "o");
        m.addPlaneContact("pl", 0.01, 5555.5, 0.44, 2, -0.1, "b");
        m.addAttractor3D("at", 0.01, 0.00121, "a", "o");
        return m;
    }

    static void assertRealParams(PhysicalModel m) {
        assertRel(9.81, m.getGravity(), "gravity");
        assertRel(0.0123, m.getFriction(), "friction");
        assertRel(1234.5, m.getMatStiffness("o"), "osc K");
        assertRel(0.0789, m.getMatDamping("o"), "osc Z");
        assertRel(987.6, m.getMatStiffness("o1"), "osc1D K");
        assertRel(0.0456, m.getMatDamping("o1"), "osc1D Z");
        assertRel(321.5, m.getLinkStiffness("sp"), "spring K");
        assertRel(0.654, m.getLinkDamping("da"), "damper Z");
        assertRel(2500.25, m.getLinkStiffness("sd"), "spring-damper K");
        assertRel(0.125, m.getLinkDamping("sd"), "spring-damper Z");
        assertRel(1500.5, m.getLinkStiffness("s1"), "1D K");
        assertRel(0.0625, m.getLinkDamping("s1"), "1D Z");
        assertRel(4000.75, m.getLinkStiffness("ro"), "rope K");
        assertRel(0.25, m.getLinkDamping("ro"), "rope Z");
        assertRel(777.5, m.getLinkStiffness("co"), "contact K");
        assertRel(0.33, m.getLinkDamping("co"), "contact Z");
        assertRel(111.125, m.getLinkStiffness("bu"), "bubble K");
        assertRel(0.0777, m.getLinkDamping("bu"), "bubble Z");
        assertRel(5555.5, m.getLinkStiffness("pl"), "plane K");
        assertRel(0.44, m.getLinkDamping("pl"), "plane Z");
        assertRel(0.00121, ((Attractor3D) m.getInteraction("at")).getAttraction(), "attraction");
        assertEquals(0.11, m.getLinkDRest("sd"), 0.0);
        assertEquals(0.05, m.getMatMass("a"), 0.0);
    }

    @Test
    void realUnitGettersReturnExactlyWhatWasSet() {
        for (int fs : new int[] {44100, 997, 1000, 48000, 100000}) {
            PhysicalModel m = realModel(fs);
            assertRealParams(m);
            m.init();
            m.computeNSteps(3);
            assertRealParams(m);
        }
    }

    @Test
    void realUnitSettersRoundTrip() {
        PhysicalModel m = realModel(44100);
        m.setLinkStiffness("sd", 999.75);
        m.setLinkDamping("sd", 0.0321);
        m.setLinkStiffnessAt(m.getLinkIndex("ro"), 12345.5);
        m.setLinkDampingAt(m.getLinkIndex("ro"), 1.5);
        m.setLinkParams("co", 4444.25, 0.2, 0.06);
        m.setMatStiffness("o", 3210.5);
        m.setMatDamping("o", 0.0111);
        m.setMatStiffnessAt(m.getMatIndex("o1"), 55.5);
        m.setMatDampingAt(m.getMatIndex("o1"), 0.0222);
        ((Attractor3D) m.getInteraction("at")).setAttraction(-0.007);
        m.setGravity(1.62);
        m.setFriction(0.5);
        assertRel(999.75, m.getLinkStiffness("sd"), "K");
        assertRel(0.0321, m.getLinkDamping("sd"), "Z");
        assertRel(12345.5, m.getLinkStiffness("ro"), "K at");
        assertRel(1.5, m.getLinkDamping("ro"), "Z at");
        assertRel(4444.25, m.getLinkStiffness("co"), "params K");
        assertRel(0.2, m.getLinkDamping("co"), "params Z");
        assertEquals(0.06, m.getLinkDRest("co"), 0.0);
        assertRel(3210.5, m.getMatStiffness("o"), "osc K");
        assertRel(0.0111, m.getMatDamping("o"), "osc Z");
        assertRel(55.5, m.getMatStiffness("o1"), "osc K at");
        assertRel(0.0222, m.getMatDamping("o1"), "osc Z at");
        assertRel(-0.007, ((Attractor3D) m.getInteraction("at")).getAttraction(), "attraction");
        assertRel(1.62, m.getGravity(), "gravity");
        assertRel(0.5, m.getFriction(), "friction");
    }

    @Test
    void algoUnitGettersReturnTheCoefficientsAsGiven() {
        PhysicalModel m = new PhysicalModel(44100, 60, paramSystem.ALGO_UNITS);
        m.addGround3D("g", v(0, 0, 0));
        m.addMass3D("a", 3, v(1, 0, 0), v(0, 0, 0));
        m.addOsc3D("o", 2, 0.3, 0.02, v(0, 1, 0), v(0, 0, 0));
        m.addSpringDamper3D("s", 1, 0.1, 0.01, "a", "g");
        m.addAttractor3D("at", 0.01, 0.5, "a", "o");
        m.setGravity(0.001);
        m.setFriction(0.002);
        assertEquals(0.1, m.getLinkStiffness("s"), 0.0);
        assertEquals(0.01, m.getLinkDamping("s"), 0.0);
        assertEquals(0.3, m.getMatStiffness("o"), 0.0);
        assertEquals(0.02, m.getMatDamping("o"), 0.0);
        assertEquals(0.5, ((Attractor3D) m.getInteraction("at")).getAttraction(), 0.0);
        assertEquals(0.001, m.getGravity(), 0.0);
        assertEquals(0.002, m.getFriction(), 0.0);
    }

    @Test
    void initialVelocityIsInUnitsPerSecondInBothSystems() {
        for (paramSystem sys : paramSystem.values()) {
            int fs = 800;
            PhysicalModel m = new PhysicalModel(fs, 60, sys);
            Vect3D x0 = v(0.5, -0.25, 2);
            Vect3D vel = v(4, -8, 0.5);
            m.addMass3D("a", 2, x0, vel);
            m.addOsc3D("o", 2, 0, 0, x0, vel);   // K = Z = 0: moves freely
            // X(-1) = X0 - v/fs, so the velocity is readable before and after init ...
            assertVect(vel, m.getMatVelocity("a"), 1e-12, sys + " before init");
            m.init();
            assertVect(vel, m.getMatVelocity("a"), 1e-12, sys + " after init");
            // ... and one free step moves by exactly v/fs
            m.computeStep();
            Vect3D x1 = m.getMatPosition("a");
            assertEquals(x0.x + vel.x / fs, x1.x, 1e-15, sys + " x(1)");
            assertEquals(x0.y + vel.y / fs, x1.y, 1e-15, sys + " y(1)");
            assertEquals(x0.z + vel.z / fs, x1.z, 1e-15, sys + " z(1)");
            assertVect(x1, m.getMatPosition("o"), 1e-15, sys + " osc");
            m.computeNSteps(99);
            assertVect(vel, m.getMatVelocity("a"), 1e-9, sys + " after 100 steps");
            assertVect(vel, m.getMatVelAt(0), 1e-9, sys + " by index");
            assertEquals(x0.x + 100.0 * vel.x / fs, m.getMatPosition("a").x, 1e-12, sys + " x(100)");
        }
    }

    @Test
    void constrainedMassesTakeOnlyTheirFreeVelocityComponents() {
        PhysicalModel m = new PhysicalModel(100, 60, paramSystem.REAL_UNITS);
        m.addMass2DPlane("p", 1, v(0, 0, 1), v(1, 2, 3));
        m.addMass1D("l", 1, v(5, 6, 0), v(1, 2, 3));
        m.init();
        assertVect(v(1, 2, 0), m.getMatVelocity("p"), 1e-12, "plane");
        assertVect(v(0, 0, 3), m.getMatVelocity("l"), 1e-12, "line");
        m.computeNSteps(10);
        assertVect(v(0.1, 0.2, 1), m.getMatPosition("p"), 1e-12, "plane pos");
        assertVect(v(5, 6, 0.3), m.getMatPosition("l"), 1e-12, "line pos");
    }

    @Test
    void forceIsInNewtonsWithTheOneStepDelayOfTheScheme() {
        // k = 100 N/m, rest 1 m, stretched by 0.01 m: 1 N toward the ground
        PhysicalModel m = new PhysicalModel(1000, 60, paramSystem.REAL_UNITS);
        m.addGround3D("g", v(0, 0, 0));
        m.addMass3D("a", 1, v(1.01, 0, 0), v(0, 0, 0));
        m.addSpring3D("s", 1, 100, "a", "g");
        m.init();
        // nothing has been computed yet: the first mass phase uses zero force
        assertVect(v(0, 0, 0), m.getMatForce("a"), 0.0, "after init");
        m.computeStep();
        // the mass did not move in step 1 (zero force, zero velocity); the interaction phase then computed 1 N
        assertEquals(1.01, m.getMatPosition("a").x, 0.0);
        assertVect(v(-1, 0, 0), m.getMatForce("a"), 1e-12, "mass after one step");
        assertVect(v(1, 0, 0), m.getMatForce("g"), 1e-12, "ground after one step");
        assertVect(v(-1, 0, 0), m.getMatFrcAt(1), 1e-12, "by index");
        assertEquals(-1.0, m.getMatForcePVector("a").x, 1e-6);
        // step 2 applies that 1 N: x(2) = x(1) - (1 N / 1 kg) / fs^2
        m.computeStep();
        assertEquals(1.01 - 1e-6, m.getMatPosition("a").x, 1e-15);

        // the same model in ALGO_UNITS reports the per-step force
        PhysicalModel q = new PhysicalModel(1000, 60, paramSystem.ALGO_UNITS);
        q.addGround3D("g", v(0, 0, 0));
        q.addMass3D("a", 1, v(1.01, 0, 0), v(0, 0, 0));
        q.addSpring3D("s", 1, 100.0 / 1e6, "a", "g");
        q.init();
        q.computeStep();
        assertEquals(-1e-6, q.getMatForce("a").x, 1e-18);
    }

    @Test
    void forceImpulseAndHapticForceAreInNewtons() {
        PhysicalModel m = new PhysicalModel(500, 60, paramSystem.REAL_UNITS);
        m.addMass3D("a", 0.5, v(0, 0, 0), v(0, 0, 0));
        m.addHapticInput3D("h", v(1.2, 0, 0), 1);
        m.addSpring3D("s", 1, 50, "h", "a");
        m.init();
        m.triggerForceImpulse("a", 2, 0, 0);   // 2 N on 0.5 kg for one step: dx = 4 / 500^2
        m.computeStep();
        double x1 = m.getMatPosition("a").x;
        assertEquals(4.0 / 250000, x1, 1e-18);
        // the avatar received the spring force after each step: -50 (d - 1) along +x, summed
        double d1 = 1.2 - x1;
        Vect3D f = m.getHapticForce("h");
        assertEquals(-50 * (d1 - 1), f.x, 1e-9);
        // the next two steps accumulate into the avatar's buffer until it is read
        m.computeStep();
        double x2 = m.getMatPosition("a").x;
        m.computeStep();
        double x3 = m.getMatPosition("a").x;
        Vect3D f2 = m.getHapticForce("h");
        assertEquals(-50 * (1.2 - x2 - 1) - 50 * (1.2 - x3 - 1), f2.x, 1e-9);
        assertEquals(0, f2.y, 0.0);
        assertEquals(true, x3 > x2 && x2 > x1, "the spring pulls the mass toward the avatar");
    }

    @Test
    void setSimRateInRealUnitsPreservesParametersAndVelocity() {
        PhysicalModel m = realModel(1000);
        m.init();
        m.computeNSteps(20);
        Vect3D va = m.getMatVelocity("a");
        Vect3D vo1 = m.getMatVelocity("o1");
        Vect3D pa = m.getMatPosition("a");
        m.setSimRate(44100);
        assertEquals(44100, m.getSimRate());
        assertRealParams(m);
        assertVect(va, m.getMatVelocity("a"), 1e-9, "velocity kept");
        assertVect(vo1, m.getMatVelocity("o1"), 1e-9, "osc velocity kept");
        assertVect(pa, m.getMatPosition("a"), 0.0, "position kept");
        m.setSimRate(333);
        assertRealParams(m);
        assertVect(va, m.getMatVelocity("a"), 1e-9, "velocity kept twice");
    }

    /**
     * The force buffer holds what the last interaction phase computed and acts in the next step. After
     * setSimRate in REAL_UNITS it must still be the same number of newtons (and so act correctly).
     */
    @Test
    void setSimRateInRealUnitsPreservesThePendingForce() {
        PhysicalModel m = new PhysicalModel(1000, 60, paramSystem.REAL_UNITS);
        m.addGround3D("g", v(0, 0, 0));
        m.addMass3D("a", 1, v(1.01, 0, 0), v(0, 0, 0));
        m.addSpring3D("s", 1, 100, "a", "g");
        m.init();
        m.computeStep();
        assertEquals(-1.0, m.getMatForce("a").x, 1e-12);
        m.setSimRate(2000);
        assertEquals(-1.0, m.getMatForce("a").x, 1e-12, "getMatForce after setSimRate(2000)");
        // and the next step applies 1 N over 1/2000 s: x = 1.01 - 1 / 2000^2
        m.computeStep();
        assertEquals(1.01 - 1.0 / 4e6, m.getMatPosition("a").x, 1e-15);
    }

    @Test
    void setSimRateInRealUnitsPreservesTheAccumulatedHapticForce() {
        PhysicalModel m = new PhysicalModel(1000, 60, paramSystem.REAL_UNITS);
        m.addGround3D("g", v(0, 0, 0));
        m.addHapticInput3D("h", v(1.01, 0, 0), 1);
        m.addSpring3D("s", 1, 100, "h", "g");
        m.init();
        m.computeNSteps(3);   // 3 x -1 N accumulated
        m.setSimRate(4000);
        assertEquals(-3.0, m.getHapticForce("h").x, 1e-9);
    }

    @Test
    void setSimRateInRealUnitsKeepsThePhysicalPeriod() {
        // m = 1 kg on k = 100 N/m: omega = 10 rad/s, period 2 pi / 10 s
        PhysicalModel m = new PhysicalModel(1000, 60, paramSystem.REAL_UNITS);
        m.addGround3D("g", v(0, 0, 0));
        m.addMass3D("a", 1, v(1.1, 0, 0), v(0, 0, 0));
        m.addSpring3D("s", 1, 100, "a", "g");
        m.init();
        double t1 = firstUpwardCrossingsPeriod(m, 1000, 1.5);
        m.setSimRate(8000);
        double t2 = firstUpwardCrossingsPeriod(m, 8000, 1.5);
        double expected = 2 * Math.PI / 10;
        assertEquals(expected, t1, expected * 2e-3);
        assertEquals(expected, t2, expected * 2e-3);
        // amplitude is kept across the switch (energy is not injected by the rate change)
        double peak = 0;
        for (int i = 0; i < 8000; i++) {
            m.computeStep();
            peak = Math.max(peak, Math.abs(m.getMatPosition("a").x - 1));
        }
        assertEquals(0.1, peak, 0.002);
    }

    /** Runs for {@code seconds} and returns the mean period in seconds between upward crossings of x = 1. */
    static double firstUpwardCrossingsPeriod(PhysicalModel m, int fs, double seconds) {
        int steps = (int) Math.round(seconds * fs);
        double prev = m.getMatPosition("a").x - 1;
        double first = -1;
        double last = -1;
        int count = 0;
        for (int n = 1; n <= steps; n++) {
            m.computeStep();
            double x = m.getMatPosition("a").x - 1;
            if (prev < 0 && x >= 0) {
                double t = (n - 1 + (-prev) / (x - prev)) / fs;
                if (first < 0) {
                    first = t;
                } else {
                    count++;
                }
                last = t;
            }
            prev = x;
        }
        return (last - first) / count;
    }

    @Test
    void setSimRateInAlgoUnitsLeavesCoefficientsAndTheStepTrajectoryUntouched() {
        PhysicalModel changed = algoModel();
        PhysicalModel same = algoModel();
        changed.computeNSteps(10);
        same.computeNSteps(10);
        changed.setSimRate(4410);
        assertEquals(4410, changed.getSimRate());
        assertEquals(0.01, changed.getLinkStiffness("s"), 0.0);
        assertEquals(0.001, changed.getLinkDamping("s"), 0.0);
        assertEquals(0.02, changed.getMatStiffness("o"), 0.0);
        assertEquals(0.003, changed.getMatDamping("o"), 0.0);
        assertEquals(1e-5, changed.getGravity(), 0.0);
        assertEquals(1e-4, changed.getFriction(), 0.0);
        for (int n = 0; n < 300; n++) {
            changed.computeStep();
            same.computeStep();
            for (String name : new String[] {"a", "o"}) {
                assertVect(same.getMatPosition(name), changed.getMatPosition(name), 0.0, name + " step " + n);
                assertVect(same.getMatForce(name), changed.getMatForce(name), 0.0, name + " force step " + n);
            }
        }
        // velocities are per second, so they scale with the new rate
        assertVect(same.getMatVelocity("a").mult(4410.0 / 441), changed.getMatVelocity("a"), 1e-12, "velocity");
    }

    static PhysicalModel algoModel() {
        PhysicalModel m = new PhysicalModel(441, 60, paramSystem.ALGO_UNITS);
        m.setGravity(1e-5);
        m.setFriction(1e-4);
        m.addGround3D("g", v(0, 0, 0));
        m.addMass3D("a", 1, v(1.2, 0.1, 0), v(1, 0, 0));
        m.addOsc3D("o", 1, 0.02, 0.003, v(0, 1, 0), v(0, 2, 0));
        m.addSpringDamper3D("s", 1, 0.01, 0.001, "a", "g");
        m.addSpringDamper3D("so", 1, 0.01, 0.001, "a", "o");
        m.init();
        return m;
    }

    static void assertVect(Vect3D expected, Vect3D actual, double tol, String what) {
        assertEquals(expected.x, actual.x, tol, what + " x");
        assertEquals(expected.y, actual.y, tol, what + " y");
        assertEquals(expected.z, actual.z, tol, what + " z");
    }
}
