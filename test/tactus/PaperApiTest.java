package tactus;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import org.junit.jupiter.api.Test;
import processing.core.PVector;

/** The rest of the paper engine's PhysicalModel API (issue #11 §2), each call against its documented meaning. */
class PaperApiTest {
    private static Vect3D v(double x, double y, double z) {
        return new Vect3D(x, y, z);
    }

    /** A small scene with one module of most kinds. */
    private static PhysicalModel scene() {
        PhysicalModel m = new PhysicalModel(1000, 50);
        m.addGround3D("g", v(0, 0, 0));
        m.addMass3D("a", 2, v(1, 0, 0), v(0, 0, 0));
        m.addMass3D("b", 3, v(2, 0, 0), v(500, 0, 0));
        m.addOsc3D("o", 1, 0.1, 0.01, v(0, 1, 0), v(0, 0, 0));
        m.addMass2DPlane("p", 1, v(0, 0, 3), v(0, 0, 0));
        m.addSpringDamper3D("s1", 1, 0.1, 0.01, "g", "a");
        m.addSpringDamper3D("s2", 1, 0.1, 0.01, "a", "b");
        m.addPlaneContact("floor", 0.1, 0.2, 0.01, 1, -2.5, "b");
        m.init();
        return m;
    }

    @Test
    void linkEndsByIndexAndName() {
        PhysicalModel m = scene();
        assertEquals(0, m.getLinkMat1IdxAt(0));
        assertEquals(1, m.getLinkMat2IdxAt(0));
        assertEquals("a", m.getLinkMat1NameAt(1));
        assertEquals("b", m.getLinkMat2NameAt(1));
        Vect3D p1 = m.getLinkPos1At(1);
        Vect3D p2 = m.getLinkPos2At(1);
        assertEquals(1.0, p1.x, 0.0);
        assertEquals(2.0, p2.x, 0.0);
        // a plane contact's second end is the plane: no mass, and its foot on the plane for drawing
        assertEquals(-1, m.getLinkMat2IdxAt(2));
        assertEquals("", m.getLinkMat2NameAt(2));
        Vect3D foot = m.getLinkPos2At(2);
        assertEquals(2.0, foot.x, 0.0);
        assertEquals(-2.5, foot.y, 0.0);
        assertEquals(1, m.getPlaneOrientationAt(2));
        assertEquals(-2.5, m.getPlanePositionAt(2), 0.0);
        assertEquals(0.0, m.getPlanePositionAt(0), 0.0, "the paper's engine answered 0 for a link that is no plane");
        m.setStrict(true);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> m.getPlanePositionAt(0));
        assertTrue(e.getMessage().contains("s1"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> m.getLinkPos1At(3));
    }

    @Test
    void delayedPositionIsOneStepBehind() {
        PhysicalModel m = scene();
        m.computeNSteps(10);
        Vect3D now = m.getMatPosAt(2);
        Vect3D before = m.getMatDelayedPosAt(2);
        Vect3D vel = m.getMatVelAt(2);   // units per second = (X - X-) * fs
        assertEquals(vel.x / 1000, now.x - before.x, 1e-15);
        assertTrue(Math.abs(now.x - before.x) > 1e-3, "b is moving");
    }

    @Test
    void oscillatorDisplacementAndForceByIndex() {
        PhysicalModel m = scene();
        m.setMatPosition("o", v(0.3, 1.4, 0));
        assertEquals(0.5, m.getOsc3DDeltaPos(3), 1e-15);   // 0.3-0.4-0.5 triangle around its rest point (0, 1, 0)
        assertEquals(0.0, m.getOsc3DDeltaPos(1), 0.0, "the paper's engine answered 0 for a mass that is no oscillator");
        m.setStrict(true);
        assertThrows(IllegalArgumentException.class, () -> m.getOsc3DDeltaPos(1));
        m.setStrict(false);
        m.computeStep();
        PVector f = m.getMatForcePVector(1);
        Vect3D expected = m.getMatFrcAt(1);
        assertEquals((float) expected.x, f.x, 0f);
    }

    @Test
    void positionAndSpeedArraysPerType() {
        PhysicalModel m = scene();
        m.computeStep();
        ArrayList<PVector> pos = new ArrayList<>();
        pos.add(new PVector(9, 9, 9));   // cleared first
        m.getAllMatsOfType(pos, matModuleType.Mass3D);
        assertEquals(2, pos.size());
        assertEquals((float) m.getMatPosAt(1).x, pos.get(0).x, 0f);
        assertEquals((float) m.getMatPosAt(2).x, pos.get(1).x, 0f);
        ArrayList<PVector> p = new ArrayList<>();
        ArrayList<PVector> s = new ArrayList<>();
        m.createPosSpeedArraysForModType(p, s, matModuleType.Mass3D);
        assertEquals(2, s.size());
        assertEquals((float) (m.getMatVelAt(2).x / 1000), s.get(1).x, 1e-6f, "speed is per step");
        m.computeNSteps(5);
        m.updatePosSpeedArraysForModType(p, s, matModuleType.Mass3D);
        assertEquals(2, p.size());
        assertEquals((float) m.getMatPosAt(2).x, p.get(1).x, 0f);
        ArrayList<PVector> tooShort = new ArrayList<>();
        assertThrows(IllegalArgumentException.class,
                () -> m.updatePosSpeedArraysForModType(tooShort, tooShort, matModuleType.Mass3D));
        ArrayList<PVector> none = new ArrayList<>();
        m.getAllMatsOfType(none, matModuleType.Osc1D);
        assertTrue(none.isEmpty());
    }

    @Test
    void parametersByNamePattern() {
        PhysicalModel m = scene();
        m.setLinkParamsForName("s", 0.05, 0.002, 1.5);
        for (int i = 0; i < 2; i++) {
            assertEquals(0.05, m.getLinkStiffnessAt(i), 0.0);
            assertEquals(0.002, m.getLinkDampingAt(i), 0.0);
            assertEquals(1.5, m.getLinkDRestAt(i), 0.0);
        }
        assertEquals(0.2, m.getLinkStiffnessAt(2), 0.0, "floor does not contain \"s\"");
        m.setMatParamsForName("a", 7);
        assertEquals(7, m.getMatMass("a"), 0.0);
        assertEquals(3, m.getMatMass("b"), 0.0);
        // a rejected change leaves every match unchanged
        String before = ModelState.of(m);
        assertThrows(IllegalArgumentException.class, () -> m.setMatParamsForName("", 1));
        assertThrows(IllegalArgumentException.class, () -> m.setLinkParamsForName("s", 0.1, 0.1, -1));
        assertEquals(before, ModelState.of(m));
    }

    @Test
    void realUnitsAreConvertedByNamePatternToo() {
        PhysicalModel m = new PhysicalModel(100, 50, paramSystem.REAL_UNITS);
        m.addGround3D("g", v(0, 0, 0));
        m.addMass3D("a", 1, v(1, 0, 0), v(0, 0, 0));
        m.addSpringDamper3D("spring", 1, 10, 0.1, "g", "a");
        m.setLinkParamsForName("spr", 20, 0.2, 1);
        assertEquals(20, m.getLinkStiffness("spring"), 1e-12);
        m.setParamSystem(paramSystem.ALGO_UNITS);
        assertEquals(20.0 / (100 * 100), m.getLinkStiffness("spring"), 1e-15, "the same spring, per step");
    }

    @Test
    void setParamSystemKeepsTheModelPhysicallyTheSame() {
        PhysicalModel m = new PhysicalModel(1000, 50, paramSystem.REAL_UNITS);
        m.addMass3D("a", 1, v(0, 0, 10), v(0, 0, 0));
        m.setGravity(9.81);
        m.setFriction(0.5);
        PhysicalModel twin = new PhysicalModel(1000, 50, paramSystem.REAL_UNITS);
        twin.addMass3D("a", 1, v(0, 0, 10), v(0, 0, 0));
        twin.setGravity(9.81);
        twin.setFriction(0.5);
        m.setParamSystem(paramSystem.ALGO_UNITS);
        assertEquals(9.81 / 1e6, m.getGravity(), 1e-18);
        assertEquals(0.5 / 1000, m.getFriction(), 1e-18);
        m.computeNSteps(300);
        twin.computeNSteps(300);
        assertEquals(twin.getMatPosition("a").z, m.getMatPosition("a").z, 1e-12);
    }

    @Test
    void spacingASubsetAlongX() {
        PhysicalModel m = scene();
        m.createMatSubset("row");
        m.addMatToSubset("a", "row");
        m.addMatToSubset("b", "row");
        m.addMatToSubset("p", "row");
        m.changeDistXBetweenSubset(v(10, 2, 3), 4, "row");
        assertEquals(6, m.getMatPosition("a").x, 0.0);
        assertEquals(10, m.getMatPosition("b").x, 0.0);
        assertEquals(14, m.getMatPosition("p").x, 0.0);
        assertEquals(2, m.getMatPosition("b").y, 0.0);
        assertEquals(0, m.getMatVelocity("b").norm(), 0.0, "at rest");
    }

    @Test
    void gravityDirectionFromAPVectorAndVectorComponents() {
        PhysicalModel m = scene();
        m.setGravityDirection(new PVector(0, -2, 0));
        Vect3D d = m.getGravityDirection();
        assertEquals(-1, d.y(), 0.0);
        assertEquals(0, d.x(), 0.0);
        d.reset();
        assertEquals(0, d.z() + d.y() + d.x(), 0.0);
        assertThrows(IllegalArgumentException.class, () -> m.setGravityDirection(new PVector(0, 0, 0)));
    }

    @Test
    void aParamControllerRampsLinearlyOverItsTime() {
        PhysicalModel m = new PhysicalModel(1000, 50);
        m.addGround3D("g", v(0, 0, 0));
        m.addMass3D("a", 1, v(1, 0, 0), v(0, 0, 0));
        m.addSpringDamper3D("s", 1, 0.1, 0.01, "g", "a");
        m.createLinkSubset("springs");
        m.addLinkToSubset("s", "springs");
        m.init();
        m.addParamController("k", "springs", "stiffness", 0.1f);   // 100 steps
        ParamController pc = m.getParamController("k");
        pc.init(0.1f);
        pc.triggerRamp(0.3f);
        m.computeNSteps(50);
        assertEquals(0.2, m.getLinkStiffness("s"), 1e-6, "half-way after half the ramp");
        m.draw_physics();   // 20 more steps, through the display path too
        assertEquals(0.1 + 0.2 * 70 / 100, m.getLinkStiffness("s"), 1e-6);
        m.computeNSteps(100);
        assertEquals(0.3, m.getLinkStiffness("s"), 1e-6);
        assertFalse(pc.isRamping());
        assertNull(m.getParamController("none"));
        m.addParamController("y", "nope", "stiffness", 1); // forgiven as the paper's engine did: changes nothing
        m.getParamController("y").triggerRamp(5);
        m.computeNSteps(10);
        assertEquals(0.3, m.getLinkStiffness("s"), 1e-6);
        m.setStrict(true);
        assertThrows(IllegalArgumentException.class, () -> m.addParamController("x", "nope", "stiffness", 1));
        assertThrows(IllegalArgumentException.class, () -> m.addParamController("x", "springs", "colour", 1));
    }

    @Test
    void aMidiControllerMapsZeroTo127OntoItsRange() {
        PhysicalModel m = new PhysicalModel(1000, 50);
        m.addGround3D("g", v(0, 0, 0));
        m.addMass3D("a", 1, v(1, 0, 0), v(0, 0, 0));
        m.addSpringDamper3D("s", 1, 0.1, 0.01, "g", "a");
        m.createLinkSubset("springs");
        m.addLinkToSubset("s", "springs");
        m.init();
        MidiController mc = MidiControler.addMidiControler(m, 7, 0.01f, 0.21f, "springs", "stiffness");
        assertEquals(0.11, m.getLinkStiffness("s"), 1e-6, "the middle of the range at once");
        mc.changeParam(8, 127);   // another control number: ignored
        m.computeStep();
        assertEquals(0.11, m.getLinkStiffness("s"), 1e-6);
        mc.changeParam(7, 127);
        m.computeStep();          // a one-step ramp
        assertEquals(0.21, m.getLinkStiffness("s"), 1e-6);
        mc.changeParam(7, 0);
        m.computeStep();
        assertEquals(0.01, m.getLinkStiffness("s"), 1e-6);
    }

    @Test
    void aDistXControllerSpacesTheSubset() {
        PhysicalModel m = new PhysicalModel(1000, 50);
        for (int i = 0; i < 3; i++) {
            m.addMass3D("m" + i, 1, v(i, 5, 0), v(0, 0, 0));
        }
        m.createMatSubset("row");
        for (int i = 0; i < 3; i++) {
            m.addMatToSubset("m" + i, "row");
        }
        m.init();
        MidiController mc = MidiController.addMidiController(m, 1, 0, 4, "row", "distX", 0.01f);   // 10 steps
        assertEquals(-1, m.getMatPosition("m0").x, 1e-6, "spacing 2 around x = 1");
        mc.changeParam(127);
        m.computeNSteps(10);
        assertEquals(-3, m.getMatPosition("m0").x, 1e-6);
        assertEquals(5, m.getMatPosition("m2").x, 1e-6);
    }

    @Test
    void aSimpleMassIgnoresGravityAndFriction() {
        PhysicalModel m = new PhysicalModel(100, 50);
        m.addMass3DSimple("s", 1, v(0, 0, 0), v(100, 0, 0));   // one unit per step along x
        m.addMass3D("f", 1, v(0, 5, 0), v(100, 0, 0));
        m.setGravity(0.01);
        m.setFriction(0.1);
        m.init();
        assertEquals(matModuleType.Mass3DSimple, m.getMatTypeAt(0));
        assertEquals("Mass3DSimple", m.getMass("s").getType());
        m.computeNSteps(10);
        assertEquals(10, m.getMatPosition("s").x, 1e-12);
        assertEquals(0, m.getMatPosition("s").z, 0.0);
        assertTrue(m.getMatPosition("f").z < 0, "the Mass3D falls");
        assertTrue(m.getMatPosition("f").x < 9, "and is slowed by the friction");
        // it still feels its links: a spring pulls it back
        m.addGround3D("g", v(0, 0, 0));
        m.addSpring3D("k", 0, 0.01, "s", "g");
        double vBefore = m.getMatVelocity("s").x;
        m.computeNSteps(5);
        assertTrue(m.getMatVelocity("s").x < vBefore);
    }

    @Test
    void velocityControlMovesAMassAtExactlyItsSpeedThenLetsGo() {
        PhysicalModel m = new PhysicalModel(1000, 50);
        m.addMass3D("pick", 1, v(0, 0, 0), v(0, 0, 0));
        m.addMass3D("other", 1, v(1, 0, 0), v(0, 0, 0));
        m.addSpringDamper3D("k", 1, 0.01, 0.001, "pick", "other");
        m.setGravity(0.001);
        m.init();
        m.triggerVelocityControl("pick", 250, 0, 0);   // 0.25 per step
        assertEquals(matModuleType.Mass3D, m.getMatTypeAt(0), "it stays a Mass3D");
        m.computeNSteps(8);
        assertEquals(2.0, m.getMatPosition("pick").x, 1e-12, "exactly 8 x 0.25, whatever the spring and gravity");
        assertEquals(0.0, m.getMatPosition("pick").z, 0.0);
        assertTrue(m.getMatPosition("other").x > 1, "it pushed the other mass through the spring");
        m.triggerVelocityControl(0, 0, 500, 0);       // change of velocity, by index
        m.computeNSteps(2);
        assertEquals(1.0, m.getMatPosition("pick").y, 1e-12);
        m.stopVelocityControl("pick");
        m.computeStep();
        // released: it keeps its 0.5 per step along y, plus what the spring and gravity do in one step
        assertEquals(500, m.getMatVelocity("pick").y, 20);
        assertTrue(m.getMatPosition("pick").z < 0, "gravity acts again");
    }

    @Test
    void velocityControlRespectsConstrainedMassesAndRefusesOthers() {
        PhysicalModel m = new PhysicalModel(1000, 50);
        m.addMass2DPlane("p", 1, v(0, 0, 3), v(0, 0, 0));
        m.addMass1D("l", 1, v(5, 5, 0), v(0, 0, 0));
        m.addOsc3D("o", 1, 0.1, 0, v(0, 0, 0), v(0, 0, 0));
        m.init();
        m.triggerVelocityControl("p", 100, 100, 100);
        m.triggerVelocityControl("l", 100, 100, 100);
        m.computeNSteps(10);
        assertEquals(3, m.getMatPosition("p").z, 0.0, "the plane mass keeps its z");
        assertEquals(1, m.getMatPosition("p").x, 1e-12);
        assertEquals(5, m.getMatPosition("l").x, 0.0, "the 1D mass keeps its x");
        assertEquals(1, m.getMatPosition("l").z, 1e-12);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> m.triggerVelocityControl("o", 1, 0, 0));
        assertTrue(e.getMessage().contains("\"o\"") && e.getMessage().contains("Osc3D"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> m.triggerVelocityControl("p", Double.NaN, 0, 0));
        m.stopVelocityControl("o");   // not under control: nothing happens
    }
}
