package tactus;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * Interaction names may repeat, as in the paper's sketches (the plucked string adds seventy Contact3Ds all called
 * "col"); a call that addresses one interaction by a shared name acts on the first live one, as the paper's engine
 * does. Mass names stay unique.
 */
class DuplicateLinkNamesTest {

    /** The paper's plucked string: a Mass2DPlane string, an avatar, and one contact "col" to every bead. */
    private static PhysicalModel pluckedString(int beads) {
        PhysicalModel m = new PhysicalModel(44100, 60, paramSystem.ALGO_UNITS);
        m.addGround3D("gL", new Vect3D(0, 0, 0));
        for (int i = 0; i < beads; i++) {
            m.addMass2DPlane("str" + i, 1, new Vect3D(i + 1, 0, 0), new Vect3D());
        }
        m.addGround3D("gR", new Vect3D(beads + 1, 0, 0));
        m.addSpringDamper3D("spring", 1, 0.1, 0.001, "gL", "str0");
        for (int i = 0; i + 1 < beads; i++) {
            m.addSpringDamper3D("spring", 1, 0.1, 0.001, "str" + i, "str" + (i + 1));
        }
        m.addSpringDamper3D("spring", 1, 0.1, 0.001, "str" + (beads - 1), "gR");
        m.addHapticInput3D("guy", new Vect3D(beads / 2.0, 1, 0), 10);
        for (int i = 0; i < beads; i++) {
            m.addContact3D("col", 0.25, 0.05, 0.001, "str" + i, "guy");
        }
        m.init();
        return m;
    }

    @Test
    void theFirstLiveMatchAnswersForASharedName() {
        PhysicalModel m = pluckedString(70);
        assertEquals(71 + 70, m.getNumberOfLinks());
        assertTrue(m.linkExists("col"));
        assertArrayEquals(new String[] {"str0", "guy"}, m.getLinkMatNames("col"));
        assertEquals(71, m.getLinkIndex("col"), "the first col comes after the 71 springs");
        m.setLinkStiffness("col", 0.02);
        assertEquals(0.02, m.getLinkStiffnessAt(71), 0.0);
        assertEquals(0.05, m.getLinkStiffnessAt(72), 0.0, "only the first match changes");
        m.removeLink("col");
        assertArrayEquals(new String[] {"str1", "guy"}, m.getLinkMatNames("col"), "the next one is now first");
        assertEquals(0.05, m.getLinkStiffness("col"), 0.0);
    }

    @Test
    void thePaperStringIsPluckedThroughItsContacts() {
        PhysicalModel m = pluckedString(70);
        Vect3D before = m.getMatPosition("str35");
        // sweep the avatar down through the string, over many steps
        for (int k = 0; k <= 200; k++) {
            m.setHapticPosition("guy", new Vect3D(36, 1 - k * 0.01, 0));
            m.computeNSteps(20);
        }
        Vect3D after = m.getMatPosition("str35");
        assertNotEquals(before.y, after.y, "the string was pushed by a contact named col");
        assertTrue(Double.isFinite(m.getTotalEnergy()));
        Vect3D f = m.getHapticForce("guy");
        assertTrue(f.isFinite());
    }

    @Test
    void linkSubsetsAndHandlesKeepEachDuplicateApart() {
        PhysicalModel m = pluckedString(5);
        m.createLinkSubset("cols");
        for (int i = 0; i < m.getNumberOfLinks(); i++) {
            if (m.getLinkNameAt(i).equals("col")) {
                m.addLinkToSubset(i, "cols");
            }
        }
        assertEquals(5, m.getSubsetMembers("cols").length);
        m.changeStiffnessParamOfSubset(0.03, "cols");
        for (int i = 0; i < m.getNumberOfLinks(); i++) {
            double expected = m.getLinkNameAt(i).equals("col") ? 0.03 : 0.1;
            assertEquals(expected, m.getLinkStiffnessAt(i), 0.0, "link " + i);
        }
        Interaction first = m.getInteraction("col");
        m.removeLink("col");
        assertFalse(first.isValid());
        assertEquals(4, m.getSubsetMembers("cols").length);
    }

    @Test
    void massNamesStayUnique() {
        PhysicalModel m = pluckedString(3);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> m.addMass3D("str1", 1, new Vect3D(), new Vect3D()));
        assertTrue(e.getMessage().contains("str1") && e.getMessage().contains("exists"), e.getMessage());
    }
}
