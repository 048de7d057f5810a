package tactus;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * A contact group must produce exactly the forces of explicit Contact3D links between every pair (i, j),
 * i before j, in the enclosed-marbles scene of the paper: same trajectories bit for bit.
 */
class ContactGroupTest {
    private static final double THR = 0.2;
    private static final double K = 0.02;
    private static final double Z = 0.01;

    /** Marbles in a bubble above a plane, with gravity and friction; contacts explicit or as a group. */
    private static PhysicalModel marbles(int n, boolean group, long seed) {
        PhysicalModel m = new PhysicalModel(1000, 60);
        m.setStabilityPolicy(StabilityPolicy.OFF);
        m.setGravity(5e-5);
        m.setFriction(1e-3);
        m.addGround3D("centre", new Vect3D(0, 0, 1));
        Random r = new Random(seed);
        m.createMatSubset("marbles");
        for (int i = 0; i < n; i++) {
            String name = "m" + i;
            m.addMass3D(name, 7 + 3 * r.nextDouble(),
                    new Vect3D(2 * r.nextDouble() - 1, 2 * r.nextDouble() - 1, 2 * r.nextDouble()), new Vect3D());
            m.addMatToSubset(name, "marbles");
            m.addBubble3D("b" + i, 3, 0.1, 0.1, name, "centre");
            m.addPlaneContact("p" + i, 0, 0.01, 0.01, 2, 0, name);
        }
        if (group) {
            m.addContactGroup("marbles", THR, K, Z);
        } else {
            for (int i = 0; i < n; i++) {
                for (int j = i + 1; j < n; j++) {
                    m.addContact3D("c" + i + "_" + j, THR, K, Z, "m" + i, "m" + j);
                }
            }
        }
        m.init();
        return m;
    }

    @Test
    void groupMatchesExplicitContactsBitForBit() {
        PhysicalModel explicit = marbles(120, false, 7);
        PhysicalModel grouped = marbles(120, true, 7);
        Vect3D a = new Vect3D();
        Vect3D b = new Vect3D();
        int engagedSeen = 0;
        for (int frame = 0; frame < 40; frame++) {
            explicit.computeNSteps(250);
            grouped.computeNSteps(250);
            for (int i = 0; i < 120; i++) {
                explicit.getMatPosition("m" + i, a);
                grouped.getMatPosition("m" + i, b);
                assertEquals(a.x, b.x, 0.0, "m" + i + " x at frame " + frame);
                assertEquals(a.y, b.y, 0.0, "m" + i + " y at frame " + frame);
                assertEquals(a.z, b.z, 0.0, "m" + i + " z at frame " + frame);
            }
            for (int j = 1; j < 120; j++) {
                if (explicit.getLinkDistance("c0_" + j) < THR) {
                    engagedSeen++;
                }
            }
        }
        // the marbles must actually have touched for the comparison to mean something
        assertTrue(engagedSeen > 0, "no contact was ever engaged");
        assertEquals(explicit.getTotalEnergy(), grouped.getTotalEnergy(), 1e-12 * Math.abs(explicit.getTotalEnergy()));
    }

    /** Two piles 1,000 units apart: the bounding box is too sparse for a dense grid, so the hashed grid runs. */
    @Test
    void sparseSpreadUsesTheHashedGridWithTheSameForces() {
        PhysicalModel[] m = new PhysicalModel[2];
        for (int v = 0; v < 2; v++) {
            m[v] = new PhysicalModel(1000, 60);
            m[v].setStabilityPolicy(StabilityPolicy.OFF);
            m[v].createMatSubset("s");
            Random r = new Random(11);
            for (int i = 0; i < 40; i++) {
                double off = i < 20 ? 0 : 1000;
                m[v].addMass3D("m" + i, 1, new Vect3D(off + 0.5 * r.nextDouble(), 0.5 * r.nextDouble(),
                        0.5 * r.nextDouble()), new Vect3D(r.nextDouble() - 0.5, r.nextDouble() - 0.5, 0));
                m[v].addMatToSubset("m" + i, "s");
            }
        }
        m[0].addContactGroup("s", THR, K, Z);
        for (int i = 0; i < 40; i++) {
            for (int j = i + 1; j < 40; j++) {
                m[1].addContact3D("c" + i + "_" + j, THR, K, Z, "m" + i, "m" + j);
            }
        }
        m[0].computeNSteps(3000);
        m[1].computeNSteps(3000);
        for (int i = 0; i < 40; i++) {
            Vect3D a = m[0].getMatPosition("m" + i);
            Vect3D b = m[1].getMatPosition("m" + i);
            assertEquals(b.x, a.x, 0.0, "m" + i);
            assertEquals(b.y, a.y, 0.0, "m" + i);
            assertEquals(b.z, a.z, 0.0, "m" + i);
        }
    }

    @Test
    void groupFollowsItsSubset() {
        PhysicalModel m = marbles(60, true, 3);
        m.computeNSteps(10);
        Vect3D p0 = m.getMatPosition("m0");
        // a new member placed 0.1 away from m0 (inside the 0.2 threshold) is pushed away by the group
        m.addMass3D("late", 8, new Vect3D(p0.x + 0.1, p0.y, p0.z), new Vect3D());
        m.addMatToSubset("late", "marbles");
        m.computeStep();
        assertTrue(m.getMatForce("late").x > 0, "late joined the group: contact pushes it along +x");
        // after leaving the subset it no longer interacts
        m.setMatPosition("late", new Vect3D(p0.x + 0.1, p0.y, p0.z));
        m.removeMatFromSubset("late", "marbles");
        m.computeStep();
        assertEquals(0.0, m.getMatForce("late").x, 0.0);
        // a removed member leaves the group without breaking it
        m.removeMatAndConnectedLinks("m5");
        m.computeNSteps(5000);
        assertTrue(m.getMatPosition("m6").isFinite());
        assertTrue(!m.isDiverged());
    }

    @Test
    void badArgumentsAreRejected() {
        PhysicalModel m = marbles(4, false, 1);
        assertThrows(IllegalArgumentException.class, () -> m.addContactGroup("nope", 0.2, 1, 0));
        assertThrows(IllegalArgumentException.class, () -> m.addContactGroup("marbles", 0, 1, 0));
        assertThrows(IllegalArgumentException.class, () -> m.addContactGroup("marbles", 0.2, Double.NaN, 0));
        m.addContactGroup("marbles", 0.2, 0.01, 0);
        assertThrows(IllegalArgumentException.class, () -> m.addContactGroup("marbles", 0.2, 0.01, 0));
        assertThrows(IllegalArgumentException.class, () -> m.setContactGroupParams("x", 0.2, 0.01, 0));
    }

    @Test
    void stabilityCountsGroupContactsAsEngaged() {
        PhysicalModel m = marbles(30, true, 5);
        double calm = m.getStabilityReport().lambdaContacts();
        assertTrue(calm > 0);
        m.setContactGroupParams("marbles", THR, 2.0, 0);
        assertTrue(m.getStabilityReport().lambda() > 4, "12 engaged contacts of K = 2 on masses < 10 are unstable");
        assertTrue(m.describeStability().contains("contact group of subset \"marbles\""), m.describeStability());
    }

    /** Two masses 0.06 m apart at rest (REAL_UNITS), in contact through a group or an explicit Contact3D. */
    private static PhysicalModel penetrating(boolean group, int rate) {
        PhysicalModel m = new PhysicalModel(rate, 60, paramSystem.REAL_UNITS);
        m.addMass3D("a", 2, new Vect3D(0, 0, 0), new Vect3D());
        m.addMass3D("b", 2, new Vect3D(0.06, 0, 0), new Vect3D());
        if (group) {
            m.createMatSubset("s");
            m.addMatToSubset("a", "s");
            m.addMatToSubset("b", "s");
            m.addContactGroup("s", 0.1, 1250, 0);
        } else {
            m.addContact3D("c", 0.1, 1250, 0, "a", "b");
        }
        m.init();
        return m;
    }

    // REAL_UNITS: K = 1250 N/m, threshold 0.1 m, d = 0.06 m: |F| = K (thr - d) = 50 N at any rate. After a
    // change from 1 kHz to 4 kHz the group must still push with 50 N, like the explicit Contact3D (issue #10 §1.4:
    // it pushed with 800 N, its per-step stiffness left unscaled by the (4000/1000)^2 = 16 of the rate change).
    @Test
    void contactGroupKeepsItsForceInNewtonsAcrossARateChange() {
        double expected = 1250 * (0.1 - 0.06);
        for (boolean group : new boolean[] {false, true}) {
            PhysicalModel m = penetrating(group, 1000);
            m.computeStep();
            assertEquals(-expected, m.getMatForce("a").x, 1e-9 * expected, (group ? "group" : "explicit") + " at 1 kHz");
            m.setSimRate(4000);
            m.setMatPosition("a", new Vect3D(0, 0, 0));
            m.setMatPosition("b", new Vect3D(0.06, 0, 0));
            m.computeStep();   // the masses move a little under the pending force: use the distance they reached
            double d = m.getMatPosition("b").x - m.getMatPosition("a").x;
            double f = 1250 * (0.1 - d);
            assertEquals(expected, f, 0.01 * expected);
            assertEquals(-f, m.getMatForce("a").x, 1e-9 * f, (group ? "group" : "explicit") + " at 4 kHz");
            assertEquals(f, m.getMatForce("b").x, 1e-9 * f);
        }
        PhysicalModel g = penetrating(true, 1000);
        PhysicalModel e = penetrating(false, 1000);
        g.setSimRate(4000);
        e.setSimRate(4000);
        g.computeNSteps(200);
        e.computeNSteps(200);
        assertEquals(e.getMatPosition("a").x, g.getMatPosition("a").x, 0.0, "same trajectory at 4 kHz");
    }
}
