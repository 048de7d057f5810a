package tactus.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import tactus.PhysicalModel;
import tactus.Vect3D;

/**
 * The simulation is a deterministic function of the model and its inputs: the same model built twice gives
 * bit-identical states after 10^4 steps, and recompiling the plan (a topology change elsewhere, a parameter
 * set to its own value) does not perturb the state by a single bit.
 */
class DeterminismTest {
    private static final String[] MASSES = {"m1", "m2", "m3", "p", "l", "o", "o1", "h"};

    private static PhysicalModel build() {
        PhysicalModel pm = new PhysicalModel(1000, 30);
        pm.setGravity(1e-7);
        pm.setFriction(1e-4);
        pm.addGround3D("g", new Vect3D(0, 0, 0));
        pm.addMass3D("m1", 1, new Vect3D(1, 0.1, 0), new Vect3D(3, 1, 0));
        pm.addMass3D("m2", 1.2, new Vect3D(2, -0.1, 0.2), new Vect3D(0, 2, -4));
        pm.addMass3D("m3", 0.9, new Vect3D(2.5, 0.5, 0), new Vect3D(-5, 0, 0));
        pm.addMass2DPlane("p", 1, new Vect3D(3, 0, 0), new Vect3D(1, 1, 1));
        pm.addMass1D("l", 1, new Vect3D(1, 1, 1), new Vect3D(0, 0, 2));
        pm.addOsc3D("o", 1, 0.05, 0.001, new Vect3D(0, 1, 0), new Vect3D(2, 2, 2));
        pm.addOsc1D("o1", 1, 0.05, 0.001, new Vect3D(1, 1, 2), new Vect3D(0, 0, 2));
        pm.addHapticInput3D("h", new Vect3D(4, 0, 0), 3);
        pm.addSpringDamper3D("s1", 1, 0.05, 0.002, "g", "m1");
        pm.addSpringDamper3D("s2", 1, 0.05, 0.002, "m1", "m2");
        pm.addSpring3D("s3", 1, 0.05, "m2", "p");
        pm.addRope3D("r", 0.8, 0.05, 0.002, "m2", "m3");
        pm.addContact3D("c", 0.7, 0.05, 0.002, "m3", "p");
        pm.addBubble3D("b", 1.5, 0.05, 0.002, "o", "m1");
        pm.addDamper3D("d", 0.01, "m3", "o");
        pm.addSpringDamper1D("sd", 1, 0.05, 0.002, "l", "o1");
        pm.addPlaneContact("pl", 0, 0.05, 0.002, 2, -0.05, "m2");
        pm.addAttractor3D("a", 0.5, 1e-5, "m3", "m1");
        pm.addSpringDamper3D("sh", 1, 0.05, 0.002, "h", "p");
        pm.init();
        return pm;
    }

    private static void assertSameState(PhysicalModel a, PhysicalModel b, String what) {
        for (String m : MASSES) {
            Vect3D pa = a.getMatPosition(m);
            Vect3D pb = b.getMatPosition(m);
            Vect3D va = a.getMatVelocity(m);
            Vect3D vb = b.getMatVelocity(m);
            assertEquals(pa.x, pb.x, 0.0, what + " " + m);
            assertEquals(pa.y, pb.y, 0.0, what + " " + m);
            assertEquals(pa.z, pb.z, 0.0, what + " " + m);
            assertEquals(va.x, vb.x, 0.0, what + " " + m);
            assertEquals(va.y, vb.y, 0.0, what + " " + m);
            assertEquals(va.z, vb.z, 0.0, what + " " + m);
        }
    }

    @Test
    void sameModelTwiceIsBitIdentical() {
        PhysicalModel a = build();
        PhysicalModel b = build();
        a.setHapticPosition("h", new Vect3D(4, 0.5, 0));
        b.setHapticPosition("h", new Vect3D(4, 0.5, 0));
        a.computeNSteps(10000);
        for (int i = 0; i < 100; i++) {
            b.computeNSteps(100);   // chunking does not matter either
        }
        assertSameState(a, b, "after 10^4 steps");
        assertEquals(a.getHapticForce("h").x, b.getHapticForce("h").x, 0.0);
        assertTrue(Math.abs(a.getMatPosition("m1").x - 1) > 1e-3, "the model moved");
    }

    @Test
    void recompilingThePlanDoesNotPerturbTheState() {
        PhysicalModel a = build();
        PhysicalModel b = build();
        for (int k = 0; k < 10; k++) {
            a.computeNSteps(1000);
            b.computeNSteps(1000);
            // b: add and remove an unrelated mass and link, re-set parameters to their own values
            b.addMass3D("tmp", 1, new Vect3D(50, 50, 50), new Vect3D(0, 0, 0));
            b.addSpring3D("tmp-s", 1, 0.01, "tmp", "g");
            b.computeNSteps(0);
            b.removeMatAndConnectedLinks("tmp");
            b.setLinkStiffness("s2", b.getLinkStiffness("s2"));
            b.setMatStiffness("o", b.getMatStiffness("o"));
            b.setFriction(b.getFriction());
            b.init();
            assertSameState(a, b, "after recompiling at block " + k);
        }
        a.computeNSteps(1000);
        b.computeNSteps(1000);
        assertSameState(a, b, "1000 steps after the last recompilation");
    }
}
