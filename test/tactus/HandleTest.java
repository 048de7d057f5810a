package tactus;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.function.Executable;

/** Typed handles returned by add*: agreement with the name-based API, invalidation, re-wiring. */
class HandleTest {
    static Vect3D v(double x, double y, double z) {
        return new Vect3D(x, y, z);
    }

    @Test
    void addReturnsTypedHandlesThatKnowTheirNameAndType() {
        PhysicalModel m = new PhysicalModel(1000);
        Mass3D a = m.addMass3D("a", 1, v(0, 0, 0), v(0, 0, 0));
        Mass2DPlane p = m.addMass2DPlane("p", 1, v(1, 0, 0), v(0, 0, 0));
        Mass1D l = m.addMass1D("l", 1, v(0, 1, 0), v(0, 0, 0));
        Osc3D o = m.addOsc3D("o", 1, 0.1, 0.01, v(0, 0, 1), v(0, 0, 0));
        Osc1D o1 = m.addOsc1D("o1", 1, 0.1, 0.01, v(0, 0, 2), v(0, 0, 0));
        Ground3D g = m.addGround3D("g", v(2, 0, 0));
        Ground1D g1 = m.addGround1D("g1", v(0, 0, -2));
        HapticInput3D h = m.addHapticInput3D("h", v(0, -1, 0), 2);
        PosInput3D pi = m.addPosInput3D("pi", v(0, -2, 0), 2);
        Spring3D sp = m.addSpring3D("sp", 1, 0.1, "a", "g");
        Damper3D da = m.addDamper3D("da", 0.1, "a", "p");
        SpringDamper3D sd = m.addSpringDamper3D("sd", 1, 0.1, 0.01, "a", "o");
        SpringDamper1D sd1 = m.addSpringDamper1D("sd1", 1, 0.1, 0.01, "l", "g1");
        Rope3D ro = m.addRope3D("ro", 1, 0.1, 0.01, "p", "g");
        Contact3D co = m.addContact3D("co", 0.5, 0.1, 0.01, "h", "a");
        Bubble3D bu = m.addBubble3D("bu", 3, 0.1, 0.01, "o1", "g");
        PlaneContact3D pl = m.addPlaneContact("pl", 0, 0.1, 0.01, 1, -1, "a");
        Attractor3D at = m.addAttractor3D("at", 0.1, 1e-4, "pi", "a");

        Mass[] masses = {a, p, l, o, o1, g, g1, h, pi};
        String[] mt = {"Mass3D", "Mass2DPlane", "Mass1D", "Osc3D", "Osc1D", "Ground3D", "Ground1D", "HapticInput3D",
            "PosInput3D"};
        for (int i = 0; i < masses.length; i++) {
            assertEquals(mt[i], masses[i].getType());
            assertEquals(m.getMatNameAt(i), masses[i].getName());
            assertSame(masses[i], m.getMass(masses[i].getName()));
            assertTrue(masses[i].isValid());
            assertEquals(mt[i] + "(\"" + masses[i].getName() + "\")", masses[i].toString());
        }
        Interaction[] links = {sp, da, sd, sd1, ro, co, bu, pl, at};
        String[] lt = {"Spring3D", "Damper3D", "SpringDamper3D", "SpringDamper1D", "Rope3D", "Contact3D", "Bubble3D",
            "PlaneContact3D", "Attractor3D"};
        for (int i = 0; i < links.length; i++) {
            assertEquals(lt[i], links[i].getType());
            assertEquals(m.getLinkTypeAt(i).name(), links[i].getType());
            assertEquals(m.getLinkNameAt(i), links[i].getName());
            assertSame(links[i], m.getInteraction(links[i].getName()));
        }
        assertSame(a, sp.getMass1());
        assertSame(g, sp.getMass2());
        assertSame(a, pl.getMass1());
        assertSame(a, pl.getMass2());
        assertSame(pi, at.getMass1());
        // the type hierarchy: inertial masses and oscillators, elastic interactions
        assertTrue(a instanceof InertialMass && p instanceof InertialMass && l instanceof InertialMass);
        assertTrue(o instanceof Oscillator && o1 instanceof Oscillator);
        assertFalse(((Mass) g) instanceof InertialMass);
        assertFalse(((Mass) h) instanceof InertialMass);
        assertTrue(sd instanceof ElasticInteraction && sd1 instanceof ElasticInteraction && ro instanceof ElasticInteraction
                && co instanceof ElasticInteraction && bu instanceof ElasticInteraction && pl instanceof ElasticInteraction);
    }

    @Test
    void massHandleGettersAndSettersAgreeWithTheNameApi() {
        PhysicalModel m = new PhysicalModel(500, 50, paramSystem.REAL_UNITS);
        Mass3D a = m.addMass3D("a", 2, v(0, 0, 0), v(1, 2, 3));
        Ground3D g = m.addGround3D("g", v(1, 0, 0));
        Osc3D o = m.addOsc3D("o", 0.5, 40, 0.2, v(0, 1, 0), v(0, 0, 0));
        m.addSpringDamper3D("s", 0.5, 30, 0.1, a, g);
        m.init();
        m.computeNSteps(3);
        assertVectSame(m.getMatPosition("a"), a.getPosition());
        assertVectSame(m.getMatVelocity("a"), a.getVelocity());
        assertVectSame(m.getMatForce("a"), a.getForce());
        Vect3D out = new Vect3D();
        assertSame(out, a.getPosition(out));
        assertVectSame(m.getMatPosition("a"), out);

        a.setMass(3.5);
        assertEquals(3.5, m.getMatMass("a"), 0.0);
        m.setMatMass("a", 4.5);
        assertEquals(4.5, a.getMass(), 0.0);

        a.setPosition(v(0.25, 0.5, 0.75));
        assertVectSame(v(0.25, 0.5, 0.75), m.getMatPosition("a"));
        assertVectSame(v(0, 0, 0), m.getMatVelocity("a"));
        a.setVelocity(v(-1, 0, 2));
        assertEquals(-1, m.getMatVelocity("a").x, 1e-12);
        assertEquals(2, m.getMatVelocity("a").z, 1e-12);
        assertVectSame(v(0.25, 0.5, 0.75), m.getMatPosition("a"));

        o.setStiffness(55);
        o.setDamping(0.3);
        assertEquals(55, m.getMatStiffness("o"), 55 * 1e-12);
        assertEquals(0.3, m.getMatDamping("o"), 0.3 * 1e-12);
        m.setMatStiffness("o", 66);
        assertEquals(66, o.getStiffness(), 66 * 1e-12);
        assertEquals(0.5, o.getMass(), 0.0);

        // applyForce acts like triggerForceImpulse: once, in newtons here (REAL_UNITS)
        PhysicalModel f = new PhysicalModel(100, 50, paramSystem.REAL_UNITS);
        Mass3D b = f.addMass3D("b", 2, v(0, 0, 0), v(0, 0, 0));
        f.init();
        b.applyForce(4, 0, 0);   // a = 2 m/s^2 over one step of 10 ms: x(1) = a dt^2 = 2e-4
        f.computeStep();
        assertEquals(2e-4, b.getPosition().x, 1e-18);
        f.computeStep();
        assertEquals(4e-4, b.getPosition().x, 1e-18);
    }

    @Test
    void interactionHandleGettersAndSettersAgreeWithTheNameApi() {
        PhysicalModel m = new PhysicalModel(1000, 50, paramSystem.REAL_UNITS);
        Mass3D a = m.addMass3D("a", 1, v(0, 0, 0), v(0, 0, 0));
        Mass3D b = m.addMass3D("b", 1, v(2, 0, 0), v(0, 0, 0));
        SpringDamper3D sd = m.addSpringDamper3D("sd", 1, 100, 0.5, a, b);
        Spring3D sp = m.addSpring3D("sp", 1.5, 200, a, b);
        Damper3D da = m.addDamper3D("da", 0.25, a, b);
        Contact3D co = m.addContact3D("co", 0.5, 300, 0.1, a, b);
        Bubble3D bu = m.addBubble3D("bu", 4, 400, 0.2, a, b);
        Rope3D ro = m.addRope3D("ro", 3, 500, 0.3, a, b);
        SpringDamper1D s1 = m.addSpringDamper1D("s1", 0.1, 600, 0.4, a, b);
        PlaneContact3D pl = m.addPlaneContact("pl", 0.05, 700, 0.6, 2, -1.25, a);
        Attractor3D at = m.addAttractor3D("at", 0.2, 0.125, a, b);

        assertEquals(100, sd.getStiffness(), 1e-10);
        assertEquals(0.5, sd.getDamping(), 1e-14);
        assertEquals(1, sd.getLength(), 0.0);
        sd.setStiffness(150);
        sd.setDamping(0.75);
        sd.setLength(1.25);
        assertEquals(150, m.getLinkStiffness("sd"), 150e-12);
        assertEquals(0.75, m.getLinkDamping("sd"), 0.75e-12);
        assertEquals(1.25, m.getLinkDRest("sd"), 0.0);
        m.setLinkParams("sd", 160, 0.8, 1.3);
        assertEquals(160, sd.getStiffness(), 160e-12);
        assertEquals(0.8, sd.getDamping(), 0.8e-12);
        assertEquals(1.3, sd.getLength(), 0.0);

        assertEquals(200, sp.getStiffness(), 200e-12);
        assertEquals(1.5, sp.getLength(), 0.0);
        sp.setLength(1.75);
        assertEquals(1.75, m.getLinkDRest("sp"), 0.0);
        assertEquals(0.25, da.getDamping(), 0.25e-12);
        da.setDamping(0.5);
        assertEquals(0.5, m.getLinkDamping("da"), 0.5e-12);
        assertEquals(0.5, co.getLength(), 0.0);
        assertEquals(300, co.getStiffness(), 300e-12);
        assertEquals(4, bu.getLength(), 0.0);
        assertEquals(0.3, ro.getDamping(), 0.3e-12);
        assertEquals(600, s1.getStiffness(), 600e-12);

        assertEquals(2, pl.getOrientation());
        assertEquals(-1.25, pl.getPlanePosition(), 0.0);
        assertEquals(0.05, pl.getLength(), 0.0);
        assertEquals(700, pl.getStiffness(), 700e-12);
        pl.setPlanePosition(-2);
        assertEquals(-2, pl.getPlanePosition(), 0.0);
        assertEquals(2.0, m.getLinkDistance("pl"), 0.0);          // a.z - plane position
        assertEquals(1.95, m.getLinkElongation("pl"), 1e-15);     // minus l0

        assertEquals(0.125, at.getAttraction(), 0.125e-12);
        assertEquals(0.2, at.getLimit(), 0.0);
        at.setAttraction(-0.5);
        at.setLimit(0.3);
        assertEquals(-0.5, at.getAttraction(), 0.5e-12);
        assertEquals(0.3, m.getLinkDRest("at"), 0.0);

        assertEquals(m.getLinkDistance("sd"), sd.getDistance(), 0.0);
        assertEquals(m.getLinkElongation("sd"), sd.getElongation(), 0.0);
        assertEquals(2.0, sd.getDistance(), 0.0);
        assertEquals(0.7, sd.getElongation(), 1e-15);

        // bad values are refused through handles as well
        assertThrows(IllegalArgumentException.class, () -> sd.setStiffness(Double.NaN));
        assertThrows(IllegalArgumentException.class, () -> sd.setLength(-1));
        assertThrows(IllegalArgumentException.class, () -> at.setAttraction(Double.POSITIVE_INFINITY));
        assertThrows(IllegalArgumentException.class, () -> at.setLimit(-0.1));
        assertThrows(IllegalArgumentException.class, () -> pl.setPlanePosition(Double.NaN));
        assertThrows(IllegalArgumentException.class, () -> a.setMass(0));
        assertEquals(160, sd.getStiffness(), 160e-12);
        assertEquals(1, a.getMass(), 0.0);
    }

    @Test
    void hapticHandleDrivesTheAvatarAndReturnsTheAccumulatedForce() {
        PhysicalModel m = new PhysicalModel(1000);
        HapticInput3D h = m.addHapticInput3D("h", v(0, 0, 0), 1);
        Ground3D g = m.addGround3D("g", v(2, 0, 0));
        m.addSpring3D("s", 1, 0.01, h, g);
        m.init();
        h.setDevicePosition(v(0.5, 0, 0));
        m.computeNSteps(4);   // smoothing 1: the avatar is at 0.5 after the first step
        assertVectSame(v(0.5, 0, 0), h.getPosition());
        // 4 interaction phases, each f = -K (1.5 - 1) along (h - g)/d = -x: +0.005 on x
        Vect3D f = h.takeForce();
        assertEquals(4 * 0.005, f.x, 1e-15);
        assertEquals(0, f.y, 0.0);
        assertVectSame(v(0, 0, 0), m.getHapticForce("h"));   // taken: reset
        m.computeStep();
        assertEquals(0.005, m.getHapticForce("h").x, 1e-15);
    }

    @Test
    void posInputHandleDrivesItsTarget() {
        PhysicalModel m = new PhysicalModel(1000);
        PosInput3D p = m.addPosInput3D("p", v(0, 0, 0), 2);
        m.init();
        p.drivePosition(v(1, 0, 0));
        m.computeStep();
        assertEquals(0.5, p.getPosition().x, 0.0);
        m.computeStep();
        assertEquals(0.75, p.getPosition().x, 0.0);
    }

    @Test
    void removedHandlesThrowIllegalStateException() {
        PhysicalModel m = new PhysicalModel(1000);
        Mass3D a = m.addMass3D("a", 1, v(0, 0, 0), v(0, 0, 0));
        Mass3D b = m.addMass3D("b", 1, v(1, 0, 0), v(0, 0, 0));
        Ground3D g = m.addGround3D("g", v(2, 0, 0));
        SpringDamper3D ab = m.addSpringDamper3D("ab", 1, 0.1, 0.01, a, b);
        SpringDamper3D bg = m.addSpringDamper3D("bg", 1, 0.1, 0.01, b, g);
        Spring3D ag = m.addSpring3D("ag", 2, 0.1, a, g);
        m.init();

        m.removeLink("ag");
        assertFalse(ag.isValid());
        assertTrue(ab.isValid());
        assertInvalid(ag::getName, ag::getType, ag::getStiffness, () -> ag.setStiffness(1), ag::getLength,
                ag::getDistance, ag::getElongation, ag::getMass1, ag::getMass2);
        assertEquals("Spring3D(removed)", ag.toString());

        m.removeMatAndConnectedLinks("a");
        assertFalse(a.isValid());
        assertFalse(ab.isValid(), "a link of a removed mass is removed too");
        assertTrue(b.isValid());
        assertTrue(bg.isValid());
        assertInvalid(a::getName, a::getType, a::getPosition, () -> a.getPosition(new Vect3D()), a::getVelocity,
                a::getForce, () -> a.setPosition(v(0, 0, 0)), () -> a.applyForce(1, 0, 0), a::getMass,
                () -> a.setMass(2), () -> a.setVelocity(v(0, 0, 0)));
        assertInvalid(ab::getDamping, () -> ab.setDamping(0.1), () -> ab.setLength(1));
        assertEquals("Mass3D(removed)", a.toString());
        // a removed handle cannot be used to build links
        assertThrows(IllegalStateException.class, () -> m.addSpring3D("x", 1, 0.1, a, g));
        assertEquals(1, m.getNumberOfLinks());
        // the name is free again, and a new module under it does not revive the old handle
        Mass3D a2 = m.addMass3D("a", 1, v(5, 0, 0), v(0, 0, 0));
        assertNotSame(a, a2);
        assertFalse(a.isValid());
        assertThrows(IllegalStateException.class, a::getPosition);
        assertEquals(5, a2.getPosition().x, 0.0);
    }

    @Test
    void changeToFixedPointReturnsAGroundKeepsLinksAndFreezesThePoint() {
        // all along x, so the motion stays radial and every spring settles at its rest length
        PhysicalModel m = new PhysicalModel(1000);
        Mass3D a = m.addMass3D("a", 1, v(0, 0, 0), v(0, 0, 0));
        Mass3D b = m.addMass3D("b", 1, v(1.5, 0, 0), v(0, 0, 0));
        Mass3D c = m.addMass3D("c", 1, v(-1.2, 0, 0), v(0, 0, 0));
        SpringDamper3D ab = m.addSpringDamper3D("ab", 1, 0.01, 0.05, a, b);
        SpringDamper3D ca = m.addSpringDamper3D("ca", 1, 0.03, 0.05, c, a);
        m.createMatSubset("sub");
        m.addMatToSubset("a", "sub");
        m.init();
        m.computeNSteps(50);   // everything moves
        Vect3D at = m.getMatPosition("a");
        assertNotEquals(0.0, at.x);
        assertNotEquals(0.0, m.getMatVelocity("a").x);

        Ground3D ga = m.changeToFixedPoint("a");
        assertFalse(a.isValid());
        assertThrows(IllegalStateException.class, a::getPosition);
        assertThrows(IllegalStateException.class, () -> a.setMass(1));
        assertTrue(ga.isValid());
        assertEquals("a", ga.getName());
        assertEquals("Ground3D", ga.getType());
        assertSame(ga, m.getMass("a"));
        assertEquals("Ground3D", m.getMatTypeAt(0).name());
        assertVectSame(at, ga.getPosition());
        assertVectSame(v(0, 0, 0), ga.getVelocity());
        assertThrows(IllegalArgumentException.class, () -> m.getMatMass("a"));
        // links stay attached, now to the fixed point
        assertTrue(ab.isValid() && ca.isValid());
        assertSame(ga, ab.getMass1());
        assertSame(ga, ca.getMass2());
        assertEquals("a", m.getLinkMatNames("ab")[0]);
        assertEquals(2, m.getNumberOfLinks());
        assertEquals(3, m.getNumberOfMats());
        // the point no longer moves, even though its links pull on it
        for (int i = 0; i < 30; i++) {
            m.computeNSteps(100);
            assertVectSame(at, ga.getPosition());
        }
        assertVectSame(v(0, 0, 0), ga.getVelocity());
        // ... and the links still act on the other masses: each settles at rest length from the fixed point
        assertEquals(1.0, ab.getDistance(), 1e-9);
        assertEquals(1.0, ca.getDistance(), 1e-9);
        assertEquals(at.x + 1, b.getPosition().x, 1e-9);
        assertEquals(at.x - 1, c.getPosition().x, 1e-9);
        assertArrayEquals2(new String[] {"a"}, m.getSubsetMembers("sub"));
    }

    @Test
    void clearModelInvalidatesEverythingAndNamesBecomeReusable() {
        PhysicalModel m = new PhysicalModel(1000);
        List<Mass> ms = new ArrayList<>();
        ms.add(m.addMass3D("a", 1, v(0, 0, 0), v(0, 0, 0)));
        ms.add(m.addGround3D("g", v(1, 0, 0)));
        ms.add(m.addHapticInput3D("h", v(0, 1, 0), 1));
        Interaction s = m.addSpringDamper3D("s", 1, 0.1, 0.01, "a", "g");
        m.init();
        m.computeNSteps(5);
        m.clearModel();
        for (Mass x : ms) {
            assertFalse(x.isValid());
            assertThrows(IllegalStateException.class, x::getPosition);
        }
        assertFalse(s.isValid());
        assertThrows(IllegalStateException.class, s::getDistance);
        assertEquals(0, m.getNumberOfMats());
        assertEquals(0, m.getNumberOfLinks());
        assertFalse(m.matExists("a"));
        assertThrows(IllegalArgumentException.class, () -> m.getMatPosition("a"));
        // names are reusable, with fresh state
        Mass3D a = m.addMass3D("a", 2, v(3, 0, 0), v(0, 0, 0));
        Ground3D g = m.addGround3D("g", v(5, 0, 0));
        SpringDamper3D s2 = m.addSpringDamper3D("s", 2, 0.1, 0.01, a, g);
        assertEquals(0, m.getMatIndex("a"));
        assertEquals(0, m.getLinkIndex("s"));
        assertEquals(2.0, s2.getDistance(), 0.0);
        m.init();
        m.computeNSteps(10);
        assertVectSame(v(3, 0, 0), a.getPosition());   // at rest length: no force, no motion
        assertFalse(ms.get(0).isValid(), "the old handle stays dead although its name is reused");
    }

    @Test
    void handleOverloadsOfAddBuildTheSameModelAsNames() {
        PhysicalModel byName = new PhysicalModel(1000);
        PhysicalModel byHandle = new PhysicalModel(1000);
        for (PhysicalModel m : new PhysicalModel[] {byName, byHandle}) {
            m.addMass3D("a", 1, v(0, 0, 0), v(0.5, 0, 0));
            m.addMass3D("b", 1, v(1.2, 0, 0), v(0, 0.3, 0));
            m.addGround3D("g", v(-1, 0, 0));
        }
        byName.addSpring3D("sp", 1, 0.01, "a", "g");
        byName.addDamper3D("da", 0.002, "a", "b");
        byName.addSpringDamper3D("sd", 1, 0.01, 0.001, "a", "b");
        byName.addSpringDamper1D("s1", 0, 0.01, 0.001, "a", "b");
        byName.addRope3D("ro", 1.5, 0.01, 0.001, "b", "g");
        byName.addContact3D("co", 0.5, 0.01, 0.001, "a", "b");
        byName.addBubble3D("bu", 2.5, 0.01, 0.001, "b", "g");
        byName.addPlaneContact("pl", 0, 0.01, 0.001, 0, -0.5, "a");
        byName.addAttractor3D("at", 0.1, 1e-6, "a", "b");
        Mass a = byHandle.getMass("a");
        Mass b = byHandle.getMass("b");
        Mass g = byHandle.getMass("g");
        byHandle.addSpring3D("sp", 1, 0.01, a, g);
        byHandle.addDamper3D("da", 0.002, a, b);
        byHandle.addSpringDamper3D("sd", 1, 0.01, 0.001, a, b);
        byHandle.addSpringDamper1D("s1", 0, 0.01, 0.001, a, b);
        byHandle.addRope3D("ro", 1.5, 0.01, 0.001, b, g);
        byHandle.addContact3D("co", 0.5, 0.01, 0.001, a, b);
        byHandle.addBubble3D("bu", 2.5, 0.01, 0.001, b, g);
        byHandle.addPlaneContact("pl", 0, 0.01, 0.001, 0, -0.5, a);
        byHandle.addAttractor3D("at", 0.1, 1e-6, a, b);
        byName.init();
        byHandle.init();
        ModelState.assertSameEvolution(byName, byHandle, 200);
    }

    @Test
    void aHandleFromAnotherModelIsRejected() {
        PhysicalModel m1 = new PhysicalModel(1000);
        PhysicalModel m2 = new PhysicalModel(1000);
        Mass3D a1 = m1.addMass3D("a", 1, v(0, 0, 0), v(0, 0, 0));
        Mass3D a2 = m2.addMass3D("a", 1, v(0, 0, 0), v(0, 0, 0));
        Ground3D g2 = m2.addGround3D("g", v(1, 0, 0));
        m1.addGround3D("g", v(1, 0, 0));
        // same names exist in m2, but the handle a1 belongs to m1
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> m2.addSpring3D("s", 1, 0.1, a1, g2));
        assertTrue(e.getMessage().contains("\"a\""), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> m2.addPlaneContact("p", 0, 0.1, 0.01, 2, 0, a1));
        assertThrows(IllegalArgumentException.class, () -> m1.addSpringDamper3D("s", 1, 0.1, 0.01, a2, a1));
        assertThrows(IllegalArgumentException.class, () -> m1.addSpring3D("s", 1, 0.1, (Mass) null, a1));
        assertEquals(0, m1.getNumberOfLinks());
        assertEquals(0, m2.getNumberOfLinks());
    }

    private static void assertInvalid(Executable... calls) {
        for (Executable c : calls) {
            assertThrows(IllegalStateException.class, c);
        }
    }

    private static void assertVectSame(Vect3D expected, Vect3D actual) {
        assertEquals(expected.x, actual.x, 0.0, "x");
        assertEquals(expected.y, actual.y, 0.0, "y");
        assertEquals(expected.z, actual.z, 0.0, "z");
    }

    private static void assertArrayEquals2(String[] expected, String[] actual) {
        org.junit.jupiter.api.Assertions.assertArrayEquals(expected, actual);
    }
}
