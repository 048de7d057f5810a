package tactus;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

/**
 * Named subsets of masses and links: grouped parameter changes (checked through getters and through
 * the physics), read-back, barycentre, and that subsets keep designating the right modules after
 * removals, which the original engine's index-based subsets did not.
 */
class SubsetTest {
    /**
     * Four identical 1D-like oscillators along x: mass "mi" at (1.1, 3i, 0) tied to ground "gi" at
     * (0, 3i, 0) by spring-damper "si" of rest length 1. ALGO units.
     */
    static PhysicalModel fourOscillators(double K, double Z) {
        PhysicalModel m = new PhysicalModel(1000, 50);
        for (int i = 0; i < 4; i++) {
            m.addGround3D("g" + i, new Vect3D(0, 3 * i, 0));
            m.addMass3D("m" + i, 1, new Vect3D(1.1, 3 * i, 0), new Vect3D(0, 0, 0));
            m.addSpringDamper3D("s" + i, 1, K, Z, "m" + i, "g" + i);
        }
        m.init();
        return m;
    }

    /**
     * Discrete angular frequency of x(n+1) = 2x(n) - x(n-1) - (K/M) x(n): cos w = 1 - K/(2M).
     *
     * @return the period in steps
     */
    static double discretePeriod(double K, double M) {
        return 2 * Math.PI / Math.acos(1 - K / (2 * M));
    }

    /** Measures the mean period (in steps) of x - 1 for each mass "m0".."m3" from upward zero crossings. */
    static double[] measurePeriods(PhysicalModel m, int steps) {
        double[] prev = new double[4];
        double[] first = new double[4];
        double[] last = new double[4];
        int[] count = new int[4];
        for (int i = 0; i < 4; i++) {
            prev[i] = m.getMatPosition("m" + i).x - 1;
            first[i] = -1;
        }
        for (int n = 1; n <= steps; n++) {
            m.computeStep();
            for (int i = 0; i < 4; i++) {
                double x = m.getMatPosition("m" + i).x - 1;
                if (prev[i] < 0 && x >= 0) {
                    double t = n - 1 + (-prev[i]) / (x - prev[i]);   // linear interpolation of the crossing
                    if (first[i] < 0) {
                        first[i] = t;
                    } else {
                        count[i]++;
                    }
                    last[i] = t;
                }
                prev[i] = x;
            }
        }
        double[] periods = new double[4];
        for (int i = 0; i < 4; i++) {
            periods[i] = count[i] == 0 ? Double.NaN : (last[i] - first[i]) / count[i];
        }
        return periods;
    }

    @Test
    void groupedStiffnessChangeChangesGettersAndPeriodOfMembersOnly() {
        double K = 0.01;
        PhysicalModel m = fourOscillators(K, 0);
        m.createLinkSubset("springs");
        m.addLinkToSubset("s1", "springs");
        m.addLinkToSubset("s3", "springs");
        m.changeStiffnessParamOfSubset(4 * K, "springs");
        assertEquals(K, m.getLinkStiffness("s0"), 0.0);
        assertEquals(4 * K, m.getLinkStiffness("s1"), 0.0);
        assertEquals(K, m.getLinkStiffness("s2"), 0.0);
        assertEquals(4 * K, m.getLinkStiffness("s3"), 0.0);
        assertEquals(4 * K, m.getParamValueOfSubset("springs", "stiffness"), 0.0);

        double[] p = measurePeriods(m, 3000);
        assertEquals(discretePeriod(K, 1), p[0], 0.01);
        assertEquals(discretePeriod(4 * K, 1), p[1], 0.01);
        assertEquals(discretePeriod(K, 1), p[2], 0.01);
        assertEquals(discretePeriod(4 * K, 1), p[3], 0.01);
        // 4x stiffer is about 2x faster (exactly so only in the continuous limit)
        assertEquals(2.0, p[0] / p[1], 0.01);
    }

    @Test
    void groupedMassChangeChangesGettersAndPeriodOfMembersOnly() {
        double K = 0.01;
        PhysicalModel m = fourOscillators(K, 0);
        m.createMatSubset("heavy");
        m.addMatToSubset("m0", "heavy");
        m.addMatToSubset(m.getMatIndex("m2"), "heavy");
        m.changeMassParamOfSubset(9, "heavy");
        assertEquals(9, m.getMatMass("m0"), 0.0);
        assertEquals(1, m.getMatMass("m1"), 0.0);
        assertEquals(9, m.getMatMass("m2"), 0.0);
        assertEquals(1, m.getMatMass("m3"), 0.0);
        assertEquals(9, m.getParamValueOfSubset("heavy", "mass"), 0.0);
        double[] p = measurePeriods(m, 4000);
        assertEquals(discretePeriod(K, 9), p[0], 0.02);
        assertEquals(discretePeriod(K, 1), p[1], 0.02);
        assertEquals(discretePeriod(K, 9), p[2], 0.02);
        assertEquals(3.0, p[0] / p[1], 0.01);
    }

    @Test
    void groupedDampingChangeMakesMembersDecayAtTheExpectedRate() {
        double K = 0.01;
        PhysicalModel m = fourOscillators(K, 0);
        m.createLinkSubset("damped");
        m.addLinkToSubset("s0", "damped");
        m.addLinkToSubset("s2", "damped");
        m.changeDampingParamOfSubset(0.004, "damped");
        assertEquals(0.004, m.getLinkDamping("s0"), 0.0);
        assertEquals(0.0, m.getLinkDamping("s1"), 0.0);
        assertEquals(0.004, m.getLinkDamping("s2"), 0.0);
        assertEquals(0.004, m.getParamValueOfSubset("damped", "damping"), 0.0);
        // amplitude envelope: exp(-Z/(2M) n) for the damped ones, constant for the others
        int n = 1000;
        double[] peak = new double[4];
        for (int s = 1; s <= n + 200; s++) {
            m.computeStep();
            if (s > n) {
                for (int i = 0; i < 4; i++) {
                    peak[i] = Math.max(peak[i], Math.abs(m.getMatPosition("m" + i).x - 1));
                }
            }
        }
        double decay = Math.exp(-0.004 / 2 * n);
        assertEquals(0.1 * decay, peak[0], 0.1 * decay * 0.25);
        assertEquals(0.1 * decay, peak[2], 0.1 * decay * 0.25);
        assertEquals(0.1, peak[1], 0.002);
        assertEquals(0.1, peak[3], 0.002);
    }

    @Test
    void groupedRestLengthChangeMovesTheEquilibriumOfMembersOnly() {
        PhysicalModel m = fourOscillators(0.05, 0.05);
        m.createLinkSubset("long");
        m.addLinkToSubset("s1", "long");
        m.addLinkToSubset("s2", "long");
        m.changeDistParamOfSubset(1.5, "long");
        assertEquals(1.0, m.getLinkDRest("s0"), 0.0);
        assertEquals(1.5, m.getLinkDRest("s1"), 0.0);
        assertEquals(1.5, m.getLinkDRest("s2"), 0.0);
        assertEquals(1.0, m.getLinkDRest("s3"), 0.0);
        assertEquals(1.5, m.getParamValueOfSubset("long", "dist"), 0.0);
        m.computeNSteps(3000);
        assertEquals(1.0, m.getMatPosition("m0").x, 1e-6);
        assertEquals(1.5, m.getMatPosition("m1").x, 1e-6);
        assertEquals(1.5, m.getMatPosition("m2").x, 1e-6);
        assertEquals(1.0, m.getMatPosition("m3").x, 1e-6);
    }

    @Test
    void changeParamOfSubsetByNameIsTheSameAsTheNamedShortcuts() {
        PhysicalModel m = fourOscillators(0.01, 0.001);
        m.createLinkSubset("all");
        for (int i = 0; i < 4; i++) {
            m.addLinkToSubset("s" + i, "all");
        }
        m.changeParamOfSubset(0.02f, "all", "stiffness");
        m.changeParamOfSubset(0.003, "all", "damping");
        m.changeParamOfSubset(0.75, "all", "dist");
        for (int i = 0; i < 4; i++) {
            assertEquals((double) 0.02f, m.getLinkStiffness("s" + i), 0.0);
            assertEquals(0.003, m.getLinkDamping("s" + i), 0.0);
            assertEquals(0.75, m.getLinkDRest("s" + i), 0.0);
        }
        m.createMatSubset("masses");
        m.addMatToSubset("m3", "masses");
        m.changeParamOfSubset(2.5, "masses", "mass");
        assertEquals(2.5, m.getMatMass("m3"), 0.0);
        assertEquals(1.0, m.getMatMass("m0"), 0.0);
    }

    @Test
    void oscillatorSubsetsTakeStiffnessAndDampingAndTheyActAtOnce() {
        PhysicalModel m = new PhysicalModel(1000, 50);
        m.addOsc3D("o1", 1, 0.01, 0, new Vect3D(0, 0, 0), new Vect3D(0, 0, 0));
        m.addOsc3D("o2", 1, 0.01, 0, new Vect3D(5, 0, 0), new Vect3D(0, 0, 0));
        m.createMatSubset("oscs");
        m.addMatToSubset("o1", "oscs");
        m.init();
        m.changeStiffnessParamOfSubset(0.04, "oscs");
        m.changeDampingParamOfSubset(0.002, "oscs");
        assertEquals(0.04, m.getMatStiffness("o1"), 0.0);
        assertEquals(0.002, m.getMatDamping("o1"), 0.0);
        assertEquals(0.01, m.getMatStiffness("o2"), 0.0);
        assertEquals(0.04, m.getParamValueOfSubset("oscs", "stiffness"), 0.0);
        assertEquals(0.002, m.getParamValueOfSubset("oscs", "damping"), 0.0);
        // the new stiffness acts from the next step on (an oscillator launched from its anchor)
        PhysicalModel q = new PhysicalModel(1000, 50);
        q.addOsc3D("o1", 1, 0.01, 0, new Vect3D(0, 0, 0), new Vect3D(100, 0, 0));
        q.createMatSubset("oscs");
        q.addMatToSubset("o1", "oscs");
        q.init();
        q.changeStiffnessParamOfSubset(0.04, "oscs");
        q.computeStep();   // x(1) = 0 + 0.1 - 0.04 * 0 = 0.1
        assertEquals(0.1, q.getMatPosition("o1").x, 1e-15);
        q.computeStep();   // x(2) = 0.1 + (0.1 - 0) - 0.04 * 0.1 = 0.196
        assertEquals(0.196, q.getMatPosition("o1").x, 1e-14);
    }

    @Test
    void barycenterIsTheMeanPositionOfTheMembers() {
        PhysicalModel m = new PhysicalModel(1000);
        m.addMass3D("a", 1, new Vect3D(1, 2, 3), new Vect3D(0, 0, 0));
        m.addMass3D("b", 5, new Vect3D(-1, 4, 0), new Vect3D(0, 0, 0));
        m.addGround3D("c", new Vect3D(3, 0, 6));
        m.addMass3D("d", 1, new Vect3D(100, 100, 100), new Vect3D(0, 0, 0));
        m.createMatSubset("s");
        m.addMatToSubset("a", "s");
        m.addMatToSubset("b", "s");
        m.addMatToSubset("c", "s");
        Vect3D c = m.getBarycenterOfSubset("s");
        assertEquals(1.0, c.x, 1e-15);
        assertEquals(2.0, c.y, 1e-15);
        assertEquals(3.0, c.z, 1e-15);
        m.createMatSubset("empty");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> m.getBarycenterOfSubset("empty"));
        assertEquals(true, e.getMessage().contains("empty"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> m.getParamValueOfSubset("empty", "mass"));
        // adding a member twice does not weigh it twice
        m.addMatToSubset("a", "s");
        assertArrayEquals(new String[] {"a", "b", "c"}, m.getSubsetMembers("s"));
        assertEquals(1.0, m.getBarycenterOfSubset("s").x, 1e-15);
    }

    @Test
    void removingANonMemberThatShiftsIndicesKeepsMassSubsetsExact() {
        PhysicalModel m = new PhysicalModel(1000);
        String[] names = {"a", "b", "c", "d", "e"};
        for (int i = 0; i < names.length; i++) {
            m.addMass3D(names[i], 1 + i, new Vect3D(i, 0, 0), new Vect3D(0, 0, 0));
        }
        m.createMatSubset("sub");
        m.addMatToSubset("c", "sub");
        m.addMatToSubset("e", "sub");
        // "b" is not a member, sits before both members: its removal shifts their indices down
        m.removeMatAndConnectedLinks("b");
        assertEquals(2, m.getMatIndex("d"));
        assertEquals(1, m.getMatIndex("c"));
        assertArrayEquals(new String[] {"c", "e"}, m.getSubsetMembers("sub"));
        assertEquals(3.0, m.getParamValueOfSubset("sub", "mass"), 0.0);
        assertEquals(3.0, m.getBarycenterOfSubset("sub").x, 0.0);   // (2 + 4) / 2
        m.changeMassParamOfSubset(42, "sub");
        assertEquals(1.0, m.getMatMass("a"), 0.0);
        assertEquals(42.0, m.getMatMass("c"), 0.0);
        assertEquals(4.0, m.getMatMass("d"), 0.0);
        assertEquals(42.0, m.getMatMass("e"), 0.0);
        // removing a member: the subset designates exactly the remaining one
        m.removeMatAndConnectedLinks(m.getMatIndex("c"));
        assertArrayEquals(new String[] {"e"}, m.getSubsetMembers("sub"));
        assertEquals(4.0, m.getBarycenterOfSubset("sub").x, 0.0);
        m.changeMassParamOfSubset(7, "sub");
        assertEquals(1.0, m.getMatMass("a"), 0.0);
        assertEquals(4.0, m.getMatMass("d"), 0.0);
        assertEquals(7.0, m.getMatMass("e"), 0.0);
        // a new mass that takes a removed member's name is NOT a member
        m.addMass3D("c", 3, new Vect3D(9, 9, 9), new Vect3D(0, 0, 0));
        assertArrayEquals(new String[] {"e"}, m.getSubsetMembers("sub"));
        m.changeMassParamOfSubset(8, "sub");
        assertEquals(3.0, m.getMatMass("c"), 0.0);
        assertEquals(8.0, m.getMatMass("e"), 0.0);
        // removing the last member leaves an empty, still existing subset
        m.removeMatAndConnectedLinks("e");
        assertArrayEquals(new String[0], m.getSubsetMembers("sub"));
        m.changeMassParamOfSubset(5, "sub");   // no member: no effect, no error
        assertEquals(3.0, m.getMatMass("c"), 0.0);
        assertEquals(1.0, m.getMatMass("a"), 0.0);
        assertEquals(4.0, m.getMatMass("d"), 0.0);
    }

    @Test
    void removalsKeepLinkSubsetsExact() {
        PhysicalModel m = new PhysicalModel(1000);
        m.addGround3D("g", new Vect3D(0, 0, 0));
        for (int i = 0; i < 5; i++) {
            m.addMass3D("m" + i, 1, new Vect3D(1, i, 0), new Vect3D(0, 0, 0));
            m.addSpringDamper3D("s" + i, 1, 0.01 * (i + 1), 0.05 * (i + 1), "m" + i, "g");
        }
        m.addDamper3D("dd", 0.5, "m1", "m4");
        m.init();
        m.createLinkSubset("ls");
        m.addLinkToSubset("s2", "ls");
        m.addLinkToSubset("s4", "ls");
        m.addLinkToSubset("dd", "ls");
        // remove a non-member link with a lower index: indices shift, the subset does not
        m.removeLink("s0");
        assertEquals(0, m.getLinkIndex("s1"));
        assertArrayEquals(new String[] {"s2", "s4", "dd"}, m.getSubsetMembers("ls"));
        m.changeDampingParamOfSubset(0.25, "ls");
        assertEquals(0.05 * 2, m.getLinkDamping("s1"), 0.0);
        assertEquals(0.25, m.getLinkDamping("s2"), 0.0);
        assertEquals(0.05 * 4, m.getLinkDamping("s3"), 0.0);
        assertEquals(0.25, m.getLinkDamping("s4"), 0.0);
        assertEquals(0.25, m.getLinkDamping("dd"), 0.0);
        // remove the mass of member "s4" (and with it "dd", also a member): only "s2" is left
        m.removeMatAndConnectedLinks("m4");
        assertEquals(false, m.linkExists("dd"));
        assertArrayEquals(new String[] {"s2"}, m.getSubsetMembers("ls"));
        assertEquals(0.01 * 3, m.getParamValueOfSubset("ls", "stiffness"), 0.0);
        m.changeStiffnessParamOfSubset(0.5, "ls");
        assertEquals(0.01 * 2, m.getLinkStiffness("s1"), 0.0);
        assertEquals(0.5, m.getLinkStiffness("s2"), 0.0);
        assertEquals(0.01 * 4, m.getLinkStiffness("s3"), 0.0);
        // remove a non-member mass with a lower index (takes "s1" with it)
        m.removeMatAndConnectedLinks("m1");
        assertArrayEquals(new String[] {"s2"}, m.getSubsetMembers("ls"));
        m.changeDistParamOfSubset(0.5, "ls");
        assertEquals(0.5, m.getLinkDRest("s2"), 0.0);
        assertEquals(1.0, m.getLinkDRest("s3"), 0.0);
        // the grouped change acts on the physics of the right link: m2 settles at 0.5 from g, m3 stays at 1
        m.computeNSteps(4000);
        assertEquals(0.5, m.getLinkDistance("s2"), 1e-6);
        assertEquals(1.0, m.getLinkDistance("s3"), 1e-6);
    }

    @Test
    void removeFromSubsetAndSubsetMembershipAreExplicit() {
        PhysicalModel m = fourOscillators(0.01, 0);
        m.createMatSubset("ms");
        m.addMatToSubset("m0", "ms");
        m.addMatToSubset("m1", "ms");
        m.removeMatFromSubset("m0", "ms");
        assertArrayEquals(new String[] {"m1"}, m.getSubsetMembers("ms"));
        m.createLinkSubset("ls");
        m.addLinkToSubset(m.getLinkIndex("s3"), "ls");
        m.addLinkToSubset("s2", "ls");
        m.removeLinkFromSubset("s3", "ls");
        assertArrayEquals(new String[] {"s2"}, m.getSubsetMembers("ls"));
        // a module can belong to several subsets
        m.createLinkSubset("ls2");
        m.addLinkToSubset("s2", "ls2");
        m.removeLink("s2");
        assertArrayEquals(new String[0], m.getSubsetMembers("ls"));
        assertArrayEquals(new String[0], m.getSubsetMembers("ls2"));
    }

    @Test
    void changeToFixedPointKeepsSubsetMembershipByName() {
        PhysicalModel m = fourOscillators(0.01, 0);
        m.createMatSubset("ms");
        m.addMatToSubset("m1", "ms");
        m.addMatToSubset("m2", "ms");
        m.changeToFixedPoint("m1");
        assertArrayEquals(new String[] {"m1", "m2"}, m.getSubsetMembers("ms"));
        // m1 is a Ground3D now: by default a mass change leaves it alone and changes m2, as the paper's engine did
        m.changeMassParamOfSubset(3, "ms");
        assertEquals(3.0, m.getMatMass("m2"), 0.0);
        assertEquals(matModuleType.Ground3D, m.getMatTypeAt(m.getMatIndex("m1")));
        // strict: refused as a whole
        m.setStrict(true);
        assertThrows(IllegalArgumentException.class, () -> m.changeMassParamOfSubset(5, "ms"));
        assertEquals(3.0, m.getMatMass("m2"), 0.0);
    }

    @Test
    void clearModelRemovesSubsets() {
        PhysicalModel m = fourOscillators(0.01, 0);
        m.createMatSubset("ms");
        m.addMatToSubset("m1", "ms");
        m.createLinkSubset("ls");
        m.clearModel();
        assertThrows(IllegalArgumentException.class, () -> m.getSubsetMembers("ms"));
        m.setStrict(true); // by default the paper's call forgives a subset that does not exist (PaperLeniencyTest)
        assertThrows(IllegalArgumentException.class, () -> m.changeStiffnessParamOfSubset(1, "ls"));
        m.createMatSubset("ms");
        m.createLinkSubset("ls");
        assertArrayEquals(new String[0], m.getSubsetMembers("ms"));
    }

    @Test
    void realUnitSubsetChangesRoundTripExactly() {
        PhysicalModel m = new PhysicalModel(44100, 60, paramSystem.REAL_UNITS);
        m.addGround3D("g", new Vect3D(0, 0, 0));
        m.addMass3D("a", 0.01, new Vect3D(0.1, 0, 0), new Vect3D(0, 0, 0));
        m.addOsc3D("o", 0.02, 1000, 0.5, new Vect3D(0, 1, 0), new Vect3D(0, 0, 0));
        m.addSpringDamper3D("s", 0.1, 500, 0.3, "a", "g");
        m.createLinkSubset("ls");
        m.addLinkToSubset("s", "ls");
        m.createMatSubset("os");
        m.addMatToSubset("o", "os");
        m.changeStiffnessParamOfSubset(1234.5, "ls");
        m.changeDampingParamOfSubset(0.75, "ls");   // v1 divided by fs^2 here instead of fs
        m.changeStiffnessParamOfSubset(2222, "os");
        m.changeDampingParamOfSubset(0.125, "os");
        assertEquals(1234.5, m.getLinkStiffness("s"), 1234.5 * 1e-12);
        assertEquals(0.75, m.getLinkDamping("s"), 0.75 * 1e-12);
        assertEquals(1234.5, m.getParamValueOfSubset("ls", "stiffness"), 1234.5 * 1e-12);
        assertEquals(0.75, m.getParamValueOfSubset("ls", "damping"), 0.75 * 1e-12);
        assertEquals(2222, m.getMatStiffness("o"), 2222 * 1e-12);
        assertEquals(0.125, m.getMatDamping("o"), 0.125 * 1e-12);
        assertEquals(2222, m.getParamValueOfSubset("os", "stiffness"), 2222 * 1e-12);
        assertEquals(0.125, m.getParamValueOfSubset("os", "damping"), 0.125 * 1e-12);
    }
}
