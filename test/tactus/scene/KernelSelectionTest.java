package tactus.scene;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;
import tactus.PhysicalModel;
import tactus.Vect3D;

/**
 * The compiled plan runs one kernel per module kind present in the scene, and only those: no contact loop in a
 * scene without contacts, no gravity or friction work when both are off. Kernels run masses first (in
 * declaration order of the kinds), then interactions.
 */
class KernelSelectionTest {

    private static PhysicalModel springsOnly() {
        PhysicalModel pm = new PhysicalModel(1000, 30);
        pm.addGround3D("g", new Vect3D(0, 0, 0));
        pm.addMass3D("a", 1, new Vect3D(1, 0, 0), new Vect3D(0, 0, 0));
        pm.addMass3D("b", 1, new Vect3D(2, 0, 0), new Vect3D(0, 0, 0));
        pm.addSpring3D("s1", 1, 0.1, "g", "a");
        pm.addSpring3D("s2", 1, 0.1, "a", "b");
        pm.init();
        return pm;
    }

    @Test
    void springsOnlySceneRunsThreeKernels() {
        assertArrayEquals(new String[] {"free 3D masses", "fixed points", "springs"}, springsOnly().getSimulatedEffects());
    }

    @Test
    void gravityAndFrictionSwitchTheMassKernel() {
        PhysicalModel pm = springsOnly();
        pm.computeNSteps(10);
        pm.setGravity(1e-6);
        assertArrayEquals(new String[] {"3D masses with gravity or friction", "fixed points", "springs"}, pm.getSimulatedEffects());
        pm.setGravity(0);
        assertArrayEquals(new String[] {"free 3D masses", "fixed points", "springs"}, pm.getSimulatedEffects());
        pm.setFriction(0.01);
        assertArrayEquals(new String[] {"3D masses with gravity or friction", "fixed points", "springs"}, pm.getSimulatedEffects());
    }

    @Test
    void contactKernelComesAndGoesWithContacts() {
        PhysicalModel pm = springsOnly();
        pm.addContact3D("c", 0.5, 0.1, 0, "g", "b");
        assertArrayEquals(new String[] {"free 3D masses", "fixed points", "springs", "contacts"}, pm.getSimulatedEffects());
        pm.computeNSteps(10);
        pm.removeLink("c");
        assertArrayEquals(new String[] {"free 3D masses", "fixed points", "springs"}, pm.getSimulatedEffects());
    }

    // One module of every kind: one kernel each, masses first, in kind order.
    @Test
    void everyKindGetsExactlyOneKernel() {
        PhysicalModel pm = new PhysicalModel(1000, 30);
        // added in scrambled order: the plan groups by kind, not by insertion
        pm.addGround1D("g1", new Vect3D(0, 0, -1));
        pm.addPosInput3D("pi", new Vect3D(0, 5, 0), 1);
        pm.addOsc1D("o1", 1, 0.1, 0, new Vect3D(0, 0, 4), new Vect3D(0, 0, 0));
        pm.addMass3D("m3", 1, new Vect3D(0, 0, 0), new Vect3D(0, 0, 0));
        pm.addMass3D("m3b", 1, new Vect3D(0, 0, 1), new Vect3D(0, 0, 0));
        pm.addMass2DPlane("m2", 1, new Vect3D(1, 0, 0), new Vect3D(0, 0, 0));
        pm.addMass1D("m1", 1, new Vect3D(2, 0, 0), new Vect3D(0, 0, 0));
        pm.addOsc3D("o3", 1, 0.1, 0, new Vect3D(3, 0, 0), new Vect3D(0, 0, 0));
        pm.addHapticInput3D("h", new Vect3D(0, 6, 0), 1);
        pm.addGround3D("g3", new Vect3D(0, 7, 0));
        pm.addAttractor3D("at", 0.1, 1e-6, "m3", "o3");
        pm.addPlaneContact("pl", 0, 0.1, 0, 2, -5, "m3");
        pm.addBubble3D("bu", 3, 0.1, 0, "m3", "g3");
        pm.addContact3D("co", 0.5, 0.1, 0, "m3", "m2");
        pm.addRope3D("ro", 3, 0.1, 0, "m3", "m1");
        pm.addSpringDamper1D("sd1", 5, 0.1, 0, "o1", "g1");
        pm.addSpringDamper3D("sd3", 1, 0.1, 0, "m3", "m3b");
        pm.addDamper3D("da", 0.1, "m3b", "m2");
        pm.addSpring3D("sp", 1, 0.1, "m3b", "pi");
        pm.init();
        String[] expected = {"free 3D masses", "masses in a plane", "1D masses", "3D oscillators", "1D oscillators", "input modules", "input modules", "fixed points", "fixed points",
                             "springs", "dampers", "spring-dampers", "1D spring-dampers", "ropes and bubbles", "contacts",
                             "ropes and bubbles", "plane contacts", "attractors"};
        assertArrayEquals(expected, pm.getSimulatedEffects());
        // 10 masses of 9 kinds and 9 links of 9 kinds: 18 kernels, the two Mass3D share one
        assertEquals(10, pm.getNumberOfMats());
        assertEquals(9, pm.getNumberOfLinks());
    }
}
