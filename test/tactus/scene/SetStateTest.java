package tactus.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;
import tactus.PhysicalModel;
import tactus.Vect3D;

/**
 * Setting state mid-run. setMatPosition moves a mass "with zero velocity": both its current and previous
 * positions are the new point. A damper measures the radial rate d(n) - d(n-1) of its link, so right after
 * such a move, with both ends at rest, it must see no rate and exert no force: the jump itself is not a
 * velocity. setMatVelocity keeps the position and sets X(n-1) = X(n) - v/fs, so the next step moves the mass by
 * exactly v/fs plus the force term.
 */
class SetStateTest {

    // A mass resting at the spring-damper's rest length (no force pending) is moved 0.2 further out. It stays
    // there for the first step (zero velocity, zero pending force), and the force computed then is the spring's
    // alone, -K (d - l0) = -0.002, with no damping term -Z (1.2 - 1.0) = -0.01 from the jump.
    @Test
    void teleportIsNotSeenAsVelocityByDampers() {
        for (String kind : new String[] {"SpringDamper3D", "Damper3D", "SpringDamper1D"}) {
            PhysicalModel pm = new PhysicalModel(1000, 30);
            boolean oneD = kind.equals("SpringDamper1D");
            if (oneD) {
                pm.addGround1D("g", new Vect3D(0, 0, 0));
                pm.addMass1D("m", 1, new Vect3D(0, 0, 1), new Vect3D(0, 0, 0));
                pm.addSpringDamper1D("s", 1, 0.01, 0.05, "m", "g");
            } else {
                pm.addGround3D("g", new Vect3D(0, 0, 0));
                pm.addMass3D("m", 1, new Vect3D(0, 0, 1), new Vect3D(0, 0, 0));
                if (kind.equals("Damper3D")) {
                    pm.addDamper3D("s", 0.05, "m", "g");
                } else {
                    pm.addSpringDamper3D("s", 1, 0.01, 0.05, "m", "g");
                }
            }
            pm.init();
            pm.computeNSteps(10);
            assertEquals(0.0, pm.getMatForce("m").z, 0.0, kind + ": at rest before the move");
            pm.setMatPosition("m", new Vect3D(0, 0, 1.2));
            assertEquals(0.0, pm.getMatVelocity("m").z, 0.0);
            pm.computeStep();
            assertEquals(1.2, pm.getMatPosition("m").z, 0.0, kind + ": no velocity, no pending force");
            double spring = kind.equals("Damper3D") ? 0 : -0.01 * (1.2 - 1);
            assertEquals(spring, pm.getMatForce("m").z, 1e-15, kind + ": force right after the move");
        }
    }

    // setMatVelocity mid-run on a free mass: the next displacement is exactly v/fs (fs = 1024 keeps it exact).
    @Test
    void setVelocityGivesTheNextDisplacement() {
        PhysicalModel pm = new PhysicalModel(1024, 30);
        pm.addMass3D("m", 1, new Vect3D(1, 2, 3), new Vect3D(10, 0, 0));
        pm.init();
        pm.computeNSteps(100);
        Vect3D p = pm.getMatPosition("m");
        pm.setMatVelocity("m", new Vect3D(-64, 128, 32));
        assertEquals(p.x, pm.getMatPosition("m").x, 0.0);
        pm.computeStep();
        Vect3D q = pm.getMatPosition("m");
        assertEquals(p.x - 64.0 / 1024, q.x, 1e-15);
        assertEquals(p.y + 128.0 / 1024, q.y, 1e-15);
        assertEquals(p.z + 32.0 / 1024, q.z, 1e-15);
    }

    // A damper sees a velocity set with setMatVelocity at once: a radial rate v/fs gives -Z v/fs.
    @Test
    void dampersSeeAVelocitySetMidRun() {
        PhysicalModel pm = new PhysicalModel(1000, 30);
        pm.addGround3D("g", new Vect3D(0, 0, 0));
        pm.addMass3D("m", 1, new Vect3D(0, 0, 1), new Vect3D(0, 0, 0));
        pm.addDamper3D("d", 0.05, "m", "g");
        pm.init();
        pm.computeNSteps(10);
        pm.setMatVelocity("m", new Vect3D(0, 0, 2));   // 0.002 per step, radially outwards
        pm.computeStep();
        assertEquals(-0.05 * 0.002, pm.getMatForce("m").z, 1e-12 * 0.05 * 0.002);
    }
}
