package tactus.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;
import tactus.PhysicalModel;
import tactus.Vect3D;
import tactus.paramSystem;

/**
 * Attractor3D (f = -A / d^2 along u = (X1 - X2)/d on mass 1, only while d > dLim) and Damper3D
 * (f = -Z (d(n) - d(n-1)) along u, no spring at all).
 */
class AttractorDamperTest {

    // REAL_UNITS: A = 2 N·m^2 at d = 0.5 m gives 8 N of attraction, reported in newtons.
    @Test
    void attractorInverseSquareBeyondTheLimit() {
        PhysicalModel pm = new PhysicalModel(1000, 30, paramSystem.REAL_UNITS);
        pm.addMass3D("a", 1, new Vect3D(0.3, 0.4, 0), new Vect3D(0, 0, 0));
        pm.addMass3D("b", 1, new Vect3D(0, 0, 0), new Vect3D(0, 0, 0));
        pm.addAttractor3D("att", 0.1, 2.0, "a", "b");
        pm.init();
        pm.computeStep();
        Vect3D f = pm.getMatForce("a");
        assertEquals(-8 * 0.6, f.x, 1e-12);
        assertEquals(-8 * 0.8, f.y, 1e-12);
        assertEquals(0.0, f.z, 0.0);
        assertEquals(8 * 0.6, pm.getMatForce("b").x, 1e-12);
    }

    // Doubling the distance divides the force by four; a negative factor repels.
    @Test
    void attractorScalesAsInverseSquareAndRepelsWhenNegative() {
        double[] forces = new double[3];
        double[] dist = {0.5, 1.0, 2.0};
        for (int i = 0; i < 3; i++) {
            PhysicalModel pm = new PhysicalModel(1000, 30);
            pm.addGround3D("b", new Vect3D(0, 0, 0));
            pm.addMass3D("a", 1, new Vect3D(0, 0, dist[i]), new Vect3D(0, 0, 0));
            pm.addAttractor3D("att", 0.2, i == 2 ? -1e-3 : 1e-3, "a", "b");
            pm.init();
            pm.computeStep();
            forces[i] = pm.getMatForce("a").z;
        }
        assertEquals(-1e-3 / 0.25, forces[0], 1e-18);
        assertEquals(forces[0] / 4, forces[1], 1e-18);
        assertEquals(-forces[1] / 4, forces[2], 1e-18, "A < 0 pushes a away from b");
    }

    // Within dLim nothing acts: two masses at rest 0.05 apart with dLim = 0.1 stay exactly where they are.
    @Test
    void attractorSilentWithinTheLimit() {
        PhysicalModel pm = new PhysicalModel(1000, 30);
        pm.addMass3D("a", 1, new Vect3D(0.05, 0, 0), new Vect3D(0, 0, 0));
        pm.addMass3D("b", 1, new Vect3D(0, 0, 0), new Vect3D(0, 0, 0));
        pm.addAttractor3D("att", 0.1, 1e-5, "a", "b");
        pm.init();
        pm.computeNSteps(100);
        assertEquals(0.0, pm.getMatForce("a").norm(), 0.0);
        assertEquals(0.05, pm.getMatPosition("a").x, 0.0);
        assertEquals(0.0, pm.getMatPosition("b").x, 0.0);
    }

    // Damper3D at rest exerts nothing at any separation (it has no rest length).
    @Test
    void damperAtRestExertsNothingAtAnyDistance() {
        for (double d : new double[] {0.01, 0.7, 3.1}) {
            PhysicalModel pm = new PhysicalModel(1000, 30);
            pm.addMass3D("a", 1, new Vect3D(0, d, 0), new Vect3D(0, 0, 0));
            pm.addMass3D("b", 1, new Vect3D(0, 0, 0), new Vect3D(0, 0, 0));
            pm.addDamper3D("dmp", 0.5, "a", "b");
            pm.init();
            pm.computeNSteps(200);
            assertEquals(0.0, pm.getMatForce("a").norm(), 0.0);
            assertEquals(d, pm.getMatPosition("a").y, 0.0);
        }
    }

    // Radial separation at 0.002 per step: after step 1 the damper sees d(1) - d(0) = 0.002 and pushes back with
    // -Z 0.002 along u. Then, with M = 1 per mass and only the damper acting, the relative radial rate obeys
    // v(n+1) = (1 - 2 Z/M) v(n): a pure exponential decay (each mass receives the same opposite force).
    @Test
    void damperOpposesTheRadialRateAndDecaysIt() {
        double z = 0.05;
        PhysicalModel pm = new PhysicalModel(1000, 30);
        pm.addMass3D("a", 1, new Vect3D(0, 0, 1), new Vect3D(0, 0, 1));   // +0.001 per step
        pm.addMass3D("b", 1, new Vect3D(0, 0, 0), new Vect3D(0, 0, -1));  // -0.001 per step
        pm.addDamper3D("dmp", z, "a", "b");
        pm.init();
        pm.computeStep();
        // d(1) - d(0) = 1.002 - 1 carries the rounding of 1.002 (1e-16), hence the 1e-12 relative tolerance
        assertEquals(-z * 0.002, pm.getMatForce("a").z, 1e-12 * z * 0.002);
        assertEquals(z * 0.002, pm.getMatForce("b").z, 1e-12 * z * 0.002);
        double rate = 0.002;
        for (int n = 2; n < 60; n++) {
            pm.computeStep();
            rate *= 1 - 2 * z;
            double va = pm.getMatVelocity("a").z / 1000;
            double vb = pm.getMatVelocity("b").z / 1000;
            assertEquals(rate, va - vb, 1e-12 * 0.002, "relative rate at step " + n);
        }
    }
}
