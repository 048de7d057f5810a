package tactus.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import tactus.PhysicalModel;
import tactus.Vect3D;

/**
 * Mass2DPlane moves in its initial z plane and Mass1D along z only, whatever forces, gravity or initial
 * velocity act on the constrained coordinates. On their free coordinates they obey the Mass3D update, so
 * under gravity alone (acceleration a per step^2 along minus the direction) a free coordinate follows the
 * discrete free fall q(n) = q0 + D0 n - a_q n (n + 1) / 2. Round-off: a rounding error on X(k) stays in every
 * later displacement X(n) - X(n-1), so after n steps the position error is below n^2 ulp(max |q|).
 */
class ConstrainedMassTest {

    // Gravity along -(1, 1, 1)/sqrt 3, a velocity with a z part and a spring pulling obliquely: z never moves.
    @Test
    void mass2dPlaneKeepsZ() {
        PhysicalModel pm = new PhysicalModel(1000, 30);
        double g = 1e-6;
        pm.setGravity(g);
        pm.setGravityDirection(new Vect3D(1, 1, 1));
        pm.addMass2DPlane("p", 1, new Vect3D(0.5, 0.25, 0.75), new Vect3D(2, -3, 40));
        pm.addMass2DPlane("free", 1, new Vect3D(0, 0, 0.75), new Vect3D(2, -3, 40));
        pm.addGround3D("g", new Vect3D(-1, 2, 5));
        pm.addSpringDamper3D("s", 0.5, 0.01, 0.001, "p", "g");
        pm.init();
        double ax = g / Math.sqrt(3);
        for (int n = 1; n <= 3000; n++) {
            pm.computeStep();
            assertEquals(0.75, pm.getMatPosition("p").z, 0.0, "step " + n);
            Vect3D f = pm.getMatPosition("free");
            assertEquals(0.75, f.z, 0.0);
            double tol = (double) n * n * Math.ulp(10.0);
            assertEquals(0.002 * n - ax * n * (n + 1) / 2.0, f.x, tol);
            assertEquals(-0.003 * n - ax * n * (n + 1) / 2.0, f.y, tol);
        }
        // the spring did move p in its plane
        Vect3D p = pm.getMatPosition("p");
        assertTrue(Math.abs(p.x - (0.5 + 0.002 * 3000)) > 1e-3);
        assertEquals(0.0, pm.getMatVelocity("p").z, 0.0);
    }

    // Same disturbances on a Mass1D: x and y never move, z follows the discrete free fall with its own velocity.
    @Test
    void mass1dKeepsXAndY() {
        PhysicalModel pm = new PhysicalModel(1000, 30);
        double g = 1e-6;
        pm.setGravity(g);
        pm.setGravityDirection(new Vect3D(1, 1, 1));
        pm.addMass1D("l", 1, new Vect3D(0.5, 0.25, 0.75), new Vect3D(20, -30, 4));
        pm.addMass1D("free", 1, new Vect3D(0.5, 0.25, 0), new Vect3D(20, -30, 4));
        pm.addGround3D("g", new Vect3D(-1, 2, 5));
        pm.addSpringDamper3D("s", 0.5, 0.01, 0.001, "l", "g");
        pm.init();
        double az = g / Math.sqrt(3);
        for (int n = 1; n <= 3000; n++) {
            pm.computeStep();
            Vect3D l = pm.getMatPosition("l");
            assertEquals(0.5, l.x, 0.0, "step " + n);
            assertEquals(0.25, l.y, 0.0, "step " + n);
            Vect3D f = pm.getMatPosition("free");
            assertEquals(0.5, f.x, 0.0);
            assertEquals(0.25, f.y, 0.0);
            assertEquals(0.004 * n - az * n * (n + 1) / 2.0, f.z, (double) n * n * Math.ulp(10.0));
        }
        Vect3D v = pm.getMatVelocity("l");
        assertEquals(0.0, v.x, 0.0);
        assertEquals(0.0, v.y, 0.0);
    }
}
