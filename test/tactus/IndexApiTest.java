package tactus;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Method;
import org.junit.jupiter.api.Test;

/** The original index-based API: indices are insertion order and shift down after removals, like names. */
class IndexApiTest {
    static final String[] MAT_NAMES = {"m3", "m2p", "m1", "o3", "o1", "g3", "g1", "h", "pi"};
    static final String[] MAT_TYPES = {"Mass3D", "Mass2DPlane", "Mass1D", "Osc3D", "Osc1D", "Ground3D", "Ground1D",
        "HapticInput3D", "PosInput3D"};
    static final String[] LINK_NAMES = {"sp", "da", "sd", "sd1", "ro", "co", "bu", "pl", "at"};
    static final String[] LINK_TYPES = {"Spring3D", "Damper3D", "SpringDamper3D", "SpringDamper1D", "Rope3D",
        "Contact3D", "Bubble3D", "PlaneContact3D", "Attractor3D"};

    /** One module of every kind, added in an order that differs from the engine's internal kind order. */
    static PhysicalModel everyKind() {
        PhysicalModel m = new PhysicalModel(1000, 50);
        m.addHapticInput3D("h_tmp", new Vect3D(9, 9, 9), 1);   // removed below, so indices start shifted
        m.addMass3D("m3", 1, new Vect3D(0, 0, 0), new Vect3D(0, 0, 0));
        m.addMass2DPlane("m2p", 2, new Vect3D(1, 0, 0), new Vect3D(0, 0, 0));
        m.addMass1D("m1", 3, new Vect3D(0, 0, 1), new Vect3D(0, 0, 0));
        m.addOsc3D("o3", 4, 0.1, 0.01, new Vect3D(0, 1, 0), new Vect3D(0, 0, 0));
        m.addOsc1D("o1", 5, 0.1, 0.01, new Vect3D(0, 2, 0), new Vect3D(0, 0, 0));
        m.addGround3D("g3", new Vect3D(-1, 0, 0));
        m.addGround1D("g1", new Vect3D(0, 0, -1));
        m.addHapticInput3D("h", new Vect3D(0, -1, 0), 3);
        m.addPosInput3D("pi", new Vect3D(0, -2, 0), 2);
        m.removeMatAndConnectedLinks("h_tmp");
        m.addSpring3D("sp", 1, 0.01, "m3", "g3");
        m.addDamper3D("da", 0.01, "m3", "m2p");
        m.addSpringDamper3D("sd", 1, 0.01, 0.001, "m2p", "g3");
        m.addSpringDamper1D("sd1", 1, 0.01, 0.001, "m1", "g1");
        m.addRope3D("ro", 2, 0.01, 0.001, "o3", "g3");
        m.addContact3D("co", 0.5, 0.01, 0.001, "h", "m3");
        m.addBubble3D("bu", 3, 0.01, 0.001, "o1", "g3");
        m.addPlaneContact("pl", 0.1, 0.01, 0.001, 2, -2, "m3");
        m.addAttractor3D("at", 0.1, 1e-5, "pi", "m3");
        m.init();
        return m;
    }

    @Test
    void indicesNamesAndTypesFollowInsertionOrder() {
        PhysicalModel m = everyKind();
        assertEquals(MAT_NAMES.length, m.getNumberOfMats());
        assertEquals(LINK_NAMES.length, m.getNumberOfLinks());
        for (int i = 0; i < MAT_NAMES.length; i++) {
            assertEquals(i, m.getMatIndex(MAT_NAMES[i]));
            assertEquals(MAT_NAMES[i], m.getMatNameAt(i));
            assertEquals(MAT_TYPES[i], m.getMatTypeAt(i).name(), MAT_NAMES[i]);
            assertEquals(MAT_TYPES[i], m.getMass(MAT_NAMES[i]).getType());
        }
        for (int i = 0; i < LINK_NAMES.length; i++) {
            assertEquals(i, m.getLinkIndex(LINK_NAMES[i]));
            assertEquals(LINK_NAMES[i], m.getLinkNameAt(i));
            assertEquals(LINK_TYPES[i], m.getLinkTypeAt(i).name(), LINK_NAMES[i]);
            assertEquals(LINK_TYPES[i], m.getInteraction(LINK_NAMES[i]).getType());
        }
        assertEquals(-1, m.getMatIndex("h_tmp"));
        assertEquals(-1, m.getMatIndex("nope"));
        assertEquals(-1, m.getLinkIndex("nope"));
        assertEquals(-1, m.getMatIndex(null));
        assertFalse(m.matExists("h_tmp"));
        assertTrue(m.matExists("pi"));
        assertFalse(m.matExists("sp"));
        assertTrue(m.linkExists("sp"));
        assertFalse(m.linkExists("m3"));
        assertArrayEquals(new String[] {"m3", "m3"}, m.getLinkMatNames("pl"));
        assertArrayEquals(new String[] {"pi", "m3"}, m.getLinkMatNames("at"));
    }

    @Test
    void indexGettersAgreeWithNameGetters() {
        PhysicalModel m = everyKind();
        m.setHapticPosition("h", new Vect3D(0.2, -0.8, 0.1));
        m.triggerForceImpulse("m3", 0.001, 0.002, 0.003);
        m.computeNSteps(13);
        for (int i = 0; i < MAT_NAMES.length; i++) {
            String n = MAT_NAMES[i];
            assertVect(m.getMatPosition(n), m.getMatPosAt(i), 0.0);
            assertVect(m.getMatVelocity(n), m.getMatVelAt(i), 0.0);
            assertVect(m.getMatForce(n), m.getMatFrcAt(i), 0.0);
        }
        for (int i = 0; i < LINK_NAMES.length; i++) {
            String n = LINK_NAMES[i];
            assertEquals(m.getLinkDistance(n), m.getLinkDistanceAt(i), 0.0);
            assertEquals(m.getLinkElongation(n), m.getLinkElongationAt(i), 0.0);
        }
    }

    @Test
    void linkDistanceAndElongationHaveTheDocumentedMeaning() {
        PhysicalModel m = new PhysicalModel(1000);
        m.addMass3D("a", 1, new Vect3D(1, 2, 3), new Vect3D(0, 0, 0));
        m.addGround3D("b", new Vect3D(4, 6, 3));
        m.addSpring3D("s", 2, 0.01, "a", "b");
        m.addSpringDamper1D("s1", 0.5, 0.01, 0.001, "a", "b");
        m.addPlaneContact("p", 0.25, 0.01, 0.001, 1, 1.5, "a");
        assertEquals(5.0, m.getLinkDistanceAt(0), 1e-15);
        assertEquals(3.0, m.getLinkElongationAt(0), 1e-15);
        assertEquals(0.0, m.getLinkDistanceAt(1), 0.0);        // signed z1 - z2
        assertEquals(-0.5, m.getLinkElongationAt(1), 0.0);
        assertEquals(0.5, m.getLinkDistanceAt(2), 0.0);        // gap y - plane position
        assertEquals(0.25, m.getLinkElongationAt(2), 0.0);     // gap - l0
    }

    @Test
    void indexSettersActOnTheModuleAtThatIndex() {
        PhysicalModel m = everyKind();
        int sd = m.getLinkIndex("sd");
        m.setLinkStiffnessAt(sd, 0.05);
        m.setLinkDampingAt(sd, 0.002);
        m.setLinkDRestAt(sd, 0.5);
        assertEquals(0.05, m.getLinkStiffness("sd"), 0.0);
        assertEquals(0.002, m.getLinkDamping("sd"), 0.0);
        assertEquals(0.5, m.getLinkDRest("sd"), 0.0);
        assertEquals(0.01, m.getLinkStiffness("sp"), 0.0);

        m.setMatMassAt(m.getMatIndex("m2p"), 7);
        assertEquals(7, m.getMatMass("m2p"), 0.0);
        assertEquals(7, m.getMatMassAt(1), 0.0);
        assertEquals(1, m.getMatMassAt(0), 0.0);

        int o3 = m.getMatIndex("o3");
        m.setMatStiffnessAt(o3, 0.3);
        m.setMatDampingAt(o3, 0.03);
        assertEquals(0.3, m.getMatStiffness("o3"), 0.0);
        assertEquals(0.03, m.getMatDamping("o3"), 0.0);
        assertEquals(0.1, m.getMatStiffness("o1"), 0.0);

        m.setMatPosAt(0, new Vect3D(0.5, 0.25, -0.5));
        assertVect(new Vect3D(0.5, 0.25, -0.5), m.getMatPosition("m3"), 0.0);
        assertVect(new Vect3D(0, 0, 0), m.getMatVelocity("m3"), 0.0);

        // an impulse by index acts once, on the module at that index
        PhysicalModel f = new PhysicalModel(1000);
        f.addMass3D("a", 2, new Vect3D(0, 0, 0), new Vect3D(0, 0, 0));
        f.addMass3D("b", 4, new Vect3D(0, 0, 0), new Vect3D(0, 0, 0));
        f.init();
        f.triggerForceImpulse(1, 0.008, 0, -0.004);
        f.computeStep();
        assertVect(new Vect3D(0, 0, 0), f.getMatPosition("a"), 0.0);
        assertVect(new Vect3D(0.002, 0, -0.001), f.getMatPosition("b"), 0.0);
        f.computeStep();   // no more force: constant velocity
        assertVect(new Vect3D(0.004, 0, -0.002), f.getMatPosition("b"), 0.0);
    }

    @Test
    void indicesShiftAfterRemovalsConsistentlyWithNames() {
        PhysicalModel m = everyKind();
        // remove link at index 1 ("da"): later links move down by one
        m.removeLink(1);
        assertEquals(LINK_NAMES.length - 1, m.getNumberOfLinks());
        assertFalse(m.linkExists("da"));
        for (int i = 0, j = 0; i < LINK_NAMES.length; i++) {
            if (LINK_NAMES[i].equals("da")) {
                continue;
            }
            assertEquals(j, m.getLinkIndex(LINK_NAMES[i]));
            assertEquals(LINK_NAMES[i], m.getLinkNameAt(j));
            assertEquals(LINK_TYPES[i], m.getLinkTypeAt(j).name());
            j++;
        }
        // remove mass "m3" by index: it takes sp, co, pl and at with it
        m.removeMatAndConnectedLinks(m.getMatIndex("m3"));
        assertArrayEquals(new String[] {"m2p", "m1", "o3", "o1", "g3", "g1", "h", "pi"}, matNames(m));
        assertArrayEquals(new String[] {"sd", "sd1", "ro", "bu"}, linkNames(m));
        assertEquals("Mass2DPlane", m.getMatTypeAt(0).name());
        assertEquals("PosInput3D", m.getMatTypeAt(7).name());
        assertEquals("Bubble3D", m.getLinkTypeAt(3).name());
        assertEquals("None", m.getMatNameAt(8), "past the end: the paper's engine answered \"None\"");
        assertEquals("None", m.getLinkNameAt(4));
        m.setStrict(true);
        assertThrows(IllegalArgumentException.class, () -> m.getMatNameAt(8));
        assertThrows(IllegalArgumentException.class, () -> m.getLinkNameAt(4));
        m.setStrict(false);
        // index setters now reach the shifted modules
        m.setMatMassAt(0, 11);
        assertEquals(11, m.getMatMass("m2p"), 0.0);
        m.setLinkStiffnessAt(2, 0.07);
        assertEquals(0.07, m.getLinkStiffness("ro"), 0.0);
        // the state read by index is the state of the named module
        m.computeNSteps(20);
        for (int i = 0; i < m.getNumberOfMats(); i++) {
            assertVect(m.getMatPosition(m.getMatNameAt(i)), m.getMatPosAt(i), 0.0);
        }
        // adding appends at the end
        m.addMass3D("new", 1, new Vect3D(0, 0, 0), new Vect3D(0, 0, 0));
        assertEquals(8, m.getMatIndex("new"));
        m.addSpring3D("newlink", 1, 0.1, "new", "g3");
        assertEquals(4, m.getLinkIndex("newlink"));
    }

    @Test
    void changeToFixedPointKeepsTheIndex() {
        PhysicalModel m = everyKind();
        int i = m.getMatIndex("o3");
        m.changeToFixedPoint("o3");
        assertEquals(i, m.getMatIndex("o3"));
        assertEquals("Ground3D", m.getMatTypeAt(i).name());
        assertEquals("o3", m.getMatNameAt(i));
    }

    @Test
    void velocityByIndexIsInUnitsPerSecond() {
        PhysicalModel m = new PhysicalModel(250);
        m.addMass3D("a", 1, new Vect3D(0, 0, 0), new Vect3D(2, -4, 8));
        m.init();
        assertVect(new Vect3D(2, -4, 8), m.getMatVelAt(0), 1e-12);
        m.computeNSteps(10);
        assertVect(new Vect3D(2, -4, 8), m.getMatVelAt(0), 1e-12);
        assertVect(new Vect3D(0.08, -0.16, 0.32), m.getMatPosAt(0), 1e-12);
    }

    /**
     * The original API had index getters to match the index setters; the setters exist here, the getters
     * should too (and must return, in REAL_UNITS, what was set: v1 got this wrong).
     */
    @Test
    void indexGettersMatchingTheIndexSettersExist() throws Exception {
        PhysicalModel m = new PhysicalModel(44100, 60, paramSystem.REAL_UNITS);
        m.addGround3D("g", new Vect3D(0, 0, 0));
        m.addOsc3D("o", 0.01, 1000, 0.5, new Vect3D(0, 1, 0), new Vect3D(0, 0, 0));
        m.addSpringDamper3D("s", 0.1, 500, 0.3, "o", "g");
        assertEquals(500, (double) callIndexGetter(m, "getLinkStiffnessAt", 0), 500 * 1e-12);
        assertEquals(0.3, (double) callIndexGetter(m, "getLinkDampingAt", 0), 0.3 * 1e-12);
        assertEquals(0.1, (double) callIndexGetter(m, "getLinkDRestAt", 0), 0.0);
        assertEquals(1000, (double) callIndexGetter(m, "getMatStiffnessAt", 1), 1000 * 1e-12);
        assertEquals(0.5, (double) callIndexGetter(m, "getMatDampingAt", 1), 0.5 * 1e-12);
    }

    private static Object callIndexGetter(PhysicalModel m, String name, int i) throws Exception {
        Method meth;
        try {
            meth = PhysicalModel.class.getMethod(name, int.class);
        } catch (NoSuchMethodException e) {
            fail("PhysicalModel." + name + "(int) is missing (the matching setter "
                    + name.replace("get", "set") + " exists)");
            return null;
        }
        try {
            Object r = meth.invoke(m, i);
            assertNotNull(r);
            return r;
        } catch (InvocationTargetException e) {
            throw (Exception) e.getCause();
        }
    }

    static String[] matNames(PhysicalModel m) {
        String[] r = new String[m.getNumberOfMats()];
        for (int i = 0; i < r.length; i++) {
            r[i] = m.getMatNameAt(i);
        }
        return r;
    }

    static String[] linkNames(PhysicalModel m) {
        String[] r = new String[m.getNumberOfLinks()];
        for (int i = 0; i < r.length; i++) {
            r[i] = m.getLinkNameAt(i);
        }
        return r;
    }

    static void assertVect(Vect3D expected, Vect3D actual, double tol) {
        assertEquals(expected.x, actual.x, tol, "x");
        assertEquals(expected.y, actual.y, tol, "y");
        assertEquals(expected.z, actual.z, tol, "z");
    }
}
