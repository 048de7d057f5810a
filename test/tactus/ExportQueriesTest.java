package tactus;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** The read-only queries the Faust exporter needs: an oscillator's rest point, velocity control, contact groups. */
class ExportQueriesTest {
    @Test
    void anOscillatorKeepsItsRestPointWhenMovedByHand() {
        PhysicalModel m = new PhysicalModel(1000);
        m.addOsc3D("o", 1, 0.1, 0.01, new Vect3D(1, 2, 3), new Vect3D());
        m.addMass3D("free", 1, new Vect3D(), new Vect3D());
        m.init();
        m.setMatPosition("o", new Vect3D(5, 5, 5));
        Vect3D r = m.getOscRestPosition("o");
        assertEquals(1, r.x);
        assertEquals(2, r.y);
        assertEquals(3, r.z);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> m.getOscRestPosition("free"));
        assertTrue(e.getMessage().contains("free") && e.getMessage().contains("Mass3D"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> m.getOscRestPosition("nobody"));
    }

    @Test
    void velocityControlIsVisible() {
        PhysicalModel m = new PhysicalModel(1000);
        m.addMass3D("a", 1, new Vect3D(), new Vect3D());
        m.init();
        assertFalse(m.isVelocityControlled("a"));
        m.triggerVelocityControl("a", 1, 0, 0);
        assertTrue(m.isVelocityControlled("a"));
        m.stopVelocityControl("a");
        assertFalse(m.isVelocityControlled("a"));
    }

    @Test
    void contactGroupsAreListedByTheirSubsetInCreationOrder() {
        PhysicalModel m = new PhysicalModel(1000);
        m.addMass3D("a", 1, new Vect3D(), new Vect3D());
        m.addMass3D("b", 1, new Vect3D(1, 0, 0), new Vect3D());
        m.createMatSubset("z");
        m.createMatSubset("y");
        m.addMatToSubset("a", "z");
        m.addMatToSubset("b", "y");
        assertArrayEquals(new String[0], m.getContactGroupSubsets());
        m.addContactGroup("z", 0.5, 0.1, 0);
        m.addContactGroup("y", 0.5, 0.1, 0);
        assertArrayEquals(new String[] {"z", "y"}, m.getContactGroupSubsets());
        m.removeContactGroup("z");
        assertArrayEquals(new String[] {"y"}, m.getContactGroupSubsets());
    }
}
