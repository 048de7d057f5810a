package tactus.export;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

import tactus.PhysicalModel;
import tactus.Vect3D;

/**
 * What cannot export is refused with an exception that names the module (or option) and says why, and an export
 * leaves the model as it was. Needs no Faust.
 */
class FaustExportRefusalTest {
    static PhysicalModel pair() {
        PhysicalModel m = new PhysicalModel(44100);
        m.addMass3D("a", 1, new Vect3D(0, 0, 0), new Vect3D());
        m.addMass3D("b", 1, new Vect3D(1, 0, 0), new Vect3D());
        m.addSpringDamper3D("s", 1, 0.1, 0.001, "a", "b");
        return m;
    }

    static FaustExportException refused(PhysicalModel m, FaustExportOptions o) {
        return assertThrows(FaustExportException.class, () -> FaustExporter.toDsp(m, o));
    }

    @Test
    void aContactGroupIsRefusedByItsSubset() {
        PhysicalModel m = pair();
        m.createMatSubset("marbles");
        m.addMatToSubset("a", "marbles");
        m.addMatToSubset("b", "marbles");
        m.addContactGroup("marbles", 0.5, 0.1, 0.001);
        m.init();
        FaustExportException e = refused(m, new FaustExportOptions().listen("a", 0));
        assertTrue(e.getModule().contains("marbles") && e.getMessage().contains("contact group"), e.getMessage());
    }

    @Test
    void theHapticAvatarAndPositionDriversAreRefusedByName() {
        PhysicalModel m = pair();
        m.addHapticInput3D("avatar", new Vect3D(2, 0, 0), 10);
        m.init();
        FaustExportException e = refused(m, new FaustExportOptions().listen("a", 0));
        assertTrue(e.getMessage().contains("HapticInput3D \"avatar\""), e.getMessage());
        PhysicalModel p = pair();
        p.addPosInput3D("driver", new Vect3D(2, 0, 0), 10);
        p.init();
        e = refused(p, new FaustExportOptions().listen("a", 0));
        assertTrue(e.getMessage().contains("PosInput3D \"driver\""), e.getMessage());
    }

    @Test
    void aMassUnderVelocityControlIsRefused() {
        PhysicalModel m = pair();
        m.init();
        m.triggerVelocityControl("b", 0, 1, 0);
        FaustExportException e = refused(m, new FaustExportOptions().listen("a", 0));
        assertTrue(e.getMessage().contains("\"b\"") && e.getMessage().contains("velocity control"), e.getMessage());
        m.stopVelocityControl("b");
        assertTrue(FaustExporter.toDsp(m, new FaustExportOptions().listen("a", 0)).contains("springDamper("));
    }

    @Test
    void optionsNameWhatIsWrong() {
        PhysicalModel m = pair();
        m.init();
        assertTrue(refused(m, new FaustExportOptions()).getMessage().contains("nothing to listen to"));
        assertTrue(refused(m, new FaustExportOptions().listen("nobody", 2)).getMessage().contains("nobody"));
        assertTrue(refused(m, new FaustExportOptions().listen("a", 0).forceInput("ghost", 1)).getMessage()
                .contains("ghost"));
        FaustExportException e = refused(m, new FaustExportOptions().listen("a", 0)
                .slider("k", FaustExportOptions.STIFFNESS, "nothing"));
        assertTrue(e.getMessage().contains("slider \"k\"") && e.getMessage().contains("nothing"), e.getMessage());
        m.addDamper3D("d", 0.01, "a", "b");
        e = refused(m, new FaustExportOptions().listen("a", 0).slider("k", FaustExportOptions.STIFFNESS, "s", "d"));
        assertTrue(e.getMessage().contains("Damper3D has no stiffness"), e.getMessage());
        m.addSpringDamper3D("s2", 1, 0.2, 0.001, "a", "b");
        e = refused(m, new FaustExportOptions().listen("a", 0).slider("k", FaustExportOptions.STIFFNESS, "s", "s2"));
        assertTrue(e.getMessage().contains("one value for all"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> new FaustExportOptions().listen("a", 3));
        assertThrows(IllegalArgumentException.class, () -> new FaustExportOptions().slider("k", "colour", "s"));
        assertThrows(IllegalArgumentException.class, () -> new FaustExportOptions().slider("k", "mass", 2, 1, "a"));
    }

    @Test
    void anExportLeavesTheModelAsItWas() {
        PhysicalModel m = pair();
        m.init();
        m.triggerForceImpulse("a", 0.1, 0.2, 0.3);
        m.computeNSteps(10);
        Vect3D before = m.getMatPosition("b");
        Vect3D force = m.getMatForce("b");
        long steps = m.getStepCount();
        FaustExporter.toDsp(m, new FaustExportOptions().listen("b", 1).forceInput("a", 0)
                .slider("stiffness", FaustExportOptions.STIFFNESS, "s"));
        assertEquals(steps, m.getStepCount());
        assertEquals(before.x, m.getMatPosition("b").x);
        assertEquals(before.y, m.getMatPosition("b").y);
        assertEquals(force.x, m.getMatForce("b").x);
        assertEquals(0.1, m.getLinkStiffness("s"));
    }

    @Test
    void numbersAreFaustLiterals() {
        assertEquals("(-1.5e-5)", FaustNumbers.lit(-1.5e-5));
        assertEquals("0.0", FaustNumbers.lit(-0.0));
        assertEquals("0.15", FaustNumbers.lit(0.15));
        assertThrows(IllegalStateException.class, () -> FaustNumbers.lit(Double.NaN));
    }

    @Test
    void aOneDimensionalModelUsesMiLibUnlessAModuleHasNoMiLibForm() {
        PhysicalModel m = new PhysicalModel(44100);
        m.addMass1D("a", 1, new Vect3D(0, 0, 0), new Vect3D());
        m.addMass1D("b", 1, new Vect3D(0, 0, 1), new Vect3D());
        m.addContact3D("c", 0.5, 0.1, 0.001, "a", "b");
        String dsp = FaustExporter.toDsp(m, new FaustExportOptions().listen("a", 2));
        assertTrue(dsp.contains("mi.collision(") && !dsp.contains("coord("), dsp);
        m.setMatPosition("b", new Vect3D(0.2, 0, 1));   // no longer on a's line: the contact is a 3-D distance
        dsp = FaustExporter.toDsp(m, new FaustExportOptions().listen("a", 2));
        assertTrue(dsp.contains("contact(") && dsp.contains("Contact3D \"c\" has no mi.lib form"), dsp);
    }
}
