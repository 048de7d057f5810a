package tactus;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.HashMap;
import java.util.HashSet;
import java.util.Map;
import java.util.Set;
import org.junit.jupiter.api.Test;

/**
 * TopoGenerator: mass and link counts against closed forms, neighbourhoods pair by pair, the paper's
 * names, subsets, boundary conditions, transforms, sphere carving and argument validation.
 */
class TopoGeneratorTest {
    static final double DIST = 2.0;
    static final double L0 = 3.0;

    static PhysicalModel generate(int nx, int ny, int nz, int span, Bound... bounds) {
        PhysicalModel m = new PhysicalModel(1000, 50);
        TopoGenerator q = new TopoGenerator(m, "mass", "spring");
        q.setDim(nx, ny, nz, span);
        q.setParams(1, 0.01, 0.001);
        q.setGeometry(DIST, L0);
        for (Bound b : bounds) {
            q.addBoundaryCondition(b);
        }
        q.generate();
        return m;
    }

    /** Number of unordered pairs at Chebyshev distance 1..s in an n1 x n2 x n3 grid: (prod_a S_a - N) / 2, S_a = sum_{|o|<=s} max(0, n_a - |o|). */
    static int pairs(int nx, int ny, int nz, int s) {
        long prod = 1;
        for (int n : new int[] {nx, ny, nz}) {
            long sum = 0;
            for (int o = -s; o <= s; o++) {
                sum += Math.max(0, n - Math.abs(o));
            }
            prod *= sum;
        }
        return (int) ((prod - (long) nx * ny * nz) / 2);
    }

    /** The two mass names of link i, by index (link names repeat in the paper's naming). */
    static String[] ends(PhysicalModel m, int i) {
        return tactus.io.LinkEnds.of(m, i);
    }

    static int[] coords(String name) {
        String[] p = name.split("_");
        return new int[] {Integer.parseInt(p[1]), Integer.parseInt(p[2]), Integer.parseInt(p[3])};
    }

    static int groundCount(PhysicalModel m) {
        int n = 0;
        for (int i = 0; i < m.getNumberOfMats(); i++) {
            if (String.valueOf(m.getMatTypeAt(i)).equals("Ground3D")) {
                n++;
            }
        }
        return n;
    }

    @Test
    void stringHasNMinusOneLinksAndTwoNMinusThreeWithSpanTwo() {
        int n = 9;
        PhysicalModel a = generate(n, 1, 1, 1);
        assertEquals(n, a.getNumberOfMats());
        assertEquals(n - 1, a.getNumberOfLinks());
        PhysicalModel b = generate(n, 1, 1, 2);
        assertEquals((n - 1) + (n - 2), b.getNumberOfLinks());
        assertEquals(0, generate(n, 1, 1, 0).getNumberOfLinks());
    }

    @Test
    void meshLinksCountAxesAndBothCellDiagonals() {
        int nx = 5, ny = 4;
        PhysicalModel m = generate(nx, ny, 1, 1);
        assertEquals(nx * ny, m.getNumberOfMats());
        int axes = (nx - 1) * ny + nx * (ny - 1);
        int diagonals = 2 * (nx - 1) * (ny - 1);
        assertEquals(axes + diagonals, m.getNumberOfLinks());
        assertEquals(pairs(nx, ny, 1, 1), m.getNumberOfLinks());
    }

    @Test
    void volumeLinksCountAxesFaceAndBodyDiagonals() {
        int nx = 4, ny = 3, nz = 2;
        PhysicalModel m = generate(nx, ny, nz, 1);
        assertEquals(nx * ny * nz, m.getNumberOfMats());
        int axes = (nx - 1) * ny * nz + nx * (ny - 1) * nz + nx * ny * (nz - 1);
        int faces = 2 * ((nx - 1) * (ny - 1) * nz + (nx - 1) * ny * (nz - 1) + nx * (ny - 1) * (nz - 1));
        int body = 4 * (nx - 1) * (ny - 1) * (nz - 1);
        assertEquals(axes + faces + body, m.getNumberOfLinks());
    }

    @Test
    void widerSpansMatchTheClosedForm() {
        for (int[] c : new int[][] {{6, 1, 1, 3}, {4, 4, 1, 2}, {3, 3, 3, 2}, {5, 2, 3, 3}, {2, 2, 2, 5}}) {
            PhysicalModel m = generate(c[0], c[1], c[2], c[3]);
            assertEquals(pairs(c[0], c[1], c[2], c[3]), m.getNumberOfLinks(), Arrays.toString(c));
        }
    }

    @Test
    void everyPairWithinTheSpanIsLinkedOnceWithTheGridRestLength() {
        for (int span : new int[] {1, 2}) {
            int nx = 4, ny = 3, nz = 3;
            PhysicalModel m = generate(nx, ny, nz, span);
            Set<String> seen = new HashSet<>();
            for (int i = 0; i < m.getNumberOfLinks(); i++) {
                String[] e = ends(m, i);
                int[] a = coords(e[0]);
                int[] b = coords(e[1]);
                int dx = b[0] - a[0], dy = b[1] - a[1], dz = b[2] - a[2];
                int cheb = Math.max(Math.abs(dx), Math.max(Math.abs(dy), Math.abs(dz)));
                assertTrue(cheb >= 1 && cheb <= span, "link " + i + " spans " + cheb);
                String key = e[0].compareTo(e[1]) < 0 ? e[0] + "|" + e[1] : e[1] + "|" + e[0];
                assertTrue(seen.add(key), "pair linked twice: " + key);
                assertEquals(Math.sqrt(dx * dx + dy * dy + dz * dz) * L0, m.getLinkDRestAt(i), 1e-12);
                assertEquals(0.01, m.getLinkStiffnessAt(i), 0.0);
                assertEquals(0.001, m.getLinkDampingAt(i), 0.0);
            }
            assertEquals(pairs(nx, ny, nz, span), seen.size());
        }
    }

    @Test
    void massesAreNamedByGridPointAndPlacedOnTheGrid() {
        PhysicalModel m = generate(3, 2, 2, 1);
        int idx = 0;
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 2; j++) {
                for (int k = 0; k < 2; k++) {
                    String n = "mass_" + i + "_" + j + "_" + k;
                    assertEquals(n, m.getMatNameAt(idx++));
                    Vect3D p = m.getMatPosition(n);
                    assertEquals(i * DIST, p.x, 0.0);
                    assertEquals(j * DIST, p.y, 0.0);
                    assertEquals(k * DIST, p.z, 0.0);
                    assertEquals("Mass3D", String.valueOf(m.getMatTypeAt(m.getMatIndex(n))));
                }
            }
        }
    }

    @Test
    void linksCarryThePapersNameOfTheirFirstMass() {
        PhysicalModel m = generate(3, 2, 1, 1);
        // Every link starting at mass (i, j, k) is named mass1_ijk; the first of them holds the plain name.
        Map<String, Integer> firstIndex = new HashMap<>();
        for (int i = 0; i < m.getNumberOfLinks(); i++) {
            int[] a = coords(ends(m, i)[0]);
            String base = "mass1_" + a[0] + a[1] + a[2];
            String name = m.getLinkNameAt(i);
            assertTrue(name.equals(base) || name.startsWith(base + "~"), name + " vs " + base);
            firstIndex.putIfAbsent(base, i);
        }
        for (Map.Entry<String, Integer> e : firstIndex.entrySet()) {
            assertEquals((int) e.getValue(), m.getLinkIndex(e.getKey()));
        }
        // Mass (0,0,0) of a 3x2 mesh links to (0,1,0), (1,0,0) and (1,1,0) in the paper's order.
        assertEquals("mass1_000", m.getLinkNameAt(0));
        assertEquals("mass_0_1_0", ends(m, 0)[1]);
        assertEquals("mass_1_0_0", ends(m, 1)[1]);
        assertEquals("mass_1_1_0", ends(m, 2)[1]);
    }

    @Test
    void subsetsHoldEveryGeneratedModule() {
        PhysicalModel m = new PhysicalModel(1000, 50);
        m.addMass3D("outsider", 1, new Vect3D(-5, 0, 0), new Vect3D());
        TopoGenerator q = new TopoGenerator(m, "b", "s");
        q.setDim(3, 2, 2, 1);
        q.setParams(2, 0.1, 0.01);
        q.setGeometry(1, 1);
        q.setMatSubsetName("beamMats");
        q.setLinkSubsetName("beamLinks");
        q.generate();
        assertEquals(12, m.getSubsetMembers("beamMats").length);
        assertEquals(m.getNumberOfLinks(), m.getSubsetMembers("beamLinks").length);
        assertFalse(Arrays.asList(m.getSubsetMembers("beamMats")).contains("outsider"));
        m.changeMassParamOfSubset(5, "beamMats");
        assertEquals(5, m.getMatMass("b_2_1_1"), 0.0);
        assertEquals(1, m.getMatMass("outsider"), 0.0);
    }

    @Test
    void eachBoundFixesItsFaceAndKeepsTheLinks() {
        int nx = 4, ny = 3, nz = 2;
        int links = generate(nx, ny, nz, 1).getNumberOfLinks();
        Object[][] cases = {
            {Bound.X_LEFT, ny * nz, 0}, {Bound.X_RIGHT, ny * nz, nx - 1},
            {Bound.Y_LEFT, nx * nz, 0}, {Bound.Y_RIGHT, nx * nz, ny - 1},
            {Bound.Z_LEFT, nx * ny, 0}, {Bound.Z_RIGHT, nx * ny, nz - 1},
        };
        for (int axis = 0; axis < cases.length; axis++) {
            Bound b = (Bound) cases[axis][0];
            PhysicalModel m = generate(nx, ny, nz, 1, b);
            assertEquals((int) cases[axis][1], groundCount(m), b.name());
            assertEquals(links, m.getNumberOfLinks(), b.name());
            for (int i = 0; i < m.getNumberOfMats(); i++) {
                int[] c = coords(m.getMatNameAt(i));
                boolean onFace = c[axis / 2] == (int) cases[axis][2];
                assertEquals(onFace, String.valueOf(m.getMatTypeAt(i)).equals("Ground3D"), b + " " + m.getMatNameAt(i));
            }
        }
        // Two faces share an edge: inclusion-exclusion.
        assertEquals(ny * nz + nx * nz - nz, groundCount(generate(nx, ny, nz, 1, Bound.X_LEFT, Bound.Y_LEFT)));
        // Both ends of a string.
        assertEquals(2, groundCount(generate(7, 1, 1, 1, Bound.X_LEFT, Bound.X_RIGHT)));
    }

    @Test
    void cornersAndCentre() {
        assertEquals(8, groundCount(generate(4, 3, 2, 1, Bound.FIXED_CORNERS)));
        assertEquals(4, groundCount(generate(4, 3, 1, 1, Bound.FIXED_CORNERS)));
        assertEquals(2, groundCount(generate(6, 1, 1, 1, Bound.FIXED_CORNERS)));
        PhysicalModel m = generate(5, 3, 2, 1, Bound.FIXED_CENTRE);
        assertEquals(1, groundCount(m));
        assertEquals("Ground3D", String.valueOf(m.getMatTypeAt(m.getMatIndex("mass_2_1_1"))));
        PhysicalModel both = generate(4, 3, 2, 1, Bound.FIXED_CORNERS, Bound.X_LEFT);
        assertEquals(3 * 2 + 4, groundCount(both));
    }

    @Test
    void planeOptionMakesMass2DPlanes() {
        PhysicalModel m = new PhysicalModel(1000, 50);
        TopoGenerator q = new TopoGenerator(m, "s", "l");
        q.setDim(4, 1, 1, 1);
        q.setParams(1, 0.1, 0.01);
        q.setGeometry(1, 1);
        q.set2DPlane(true);
        q.generate();
        for (int i = 0; i < 4; i++) {
            assertEquals("Mass2DPlane", String.valueOf(m.getMatTypeAt(i)));
        }
    }

    @Test
    void rotationThenTranslationIsRigid() {
        PhysicalModel m = new PhysicalModel(1000, 50);
        TopoGenerator q = new TopoGenerator(m, "r", "l");
        q.setDim(3, 2, 2, 1);
        q.setParams(1, 0.1, 0.01);
        q.setGeometry(1.5, 1.5);
        q.setRotation(0, 0, (float) (Math.PI / 2));
        q.setTranslation(10, 20, 30);
        q.generate();
        // A quarter turn about z sends (x, y, z) to (-y, x, z).
        Vect3D p = m.getMatPosition("r_2_1_1");
        assertEquals(-1.5 + 10, p.x, 1e-6);
        assertEquals(3.0 + 20, p.y, 1e-6);
        assertEquals(1.5 + 30, p.z, 1e-6);
        // Every link starts at its rest length: the transform keeps distances.
        for (int i = 0; i < m.getNumberOfLinks(); i++) {
            String[] e = ends(m, i);
            assertEquals(m.getLinkDRestAt(i), m.getMatPosition(e[0]).dist(m.getMatPosition(e[1])), 1e-9);
        }
        PhysicalModel tilted = new PhysicalModel(1000, 50);
        TopoGenerator t = new TopoGenerator(tilted, "t", "l");
        t.setDim(2, 2, 2, 1);
        t.setParams(1, 0.1, 0.01);
        t.setGeometry(1, 1);
        t.setRotation(0.3f, -0.7f, 1.1f);
        t.generate();
        for (int i = 0; i < tilted.getNumberOfLinks(); i++) {
            String[] e = ends(tilted, i);
            assertEquals(tilted.getLinkDRestAt(i), tilted.getMatPosition(e[0]).dist(tilted.getMatPosition(e[1])), 1e-12);
        }
    }

    @Test
    void sphereCarvingKeepsTheBallOrTheShellOfThisBlockOnly() {
        // 5x5x5 grid of spacing 1 centred on (2,2,2): points with squared distance 0, 1 or 2 lie within 1.5.
        int inside = 1 + 6 + 12;
        PhysicalModel m = new PhysicalModel(1000, 50);
        m.addMass3D("bystander", 1, new Vect3D(100, 100, 100), new Vect3D());
        TopoGenerator q = new TopoGenerator(m, "p", "s");
        q.setDim(5, 5, 5, 1);
        q.setParams(1, 0.1, 0.01);
        q.setGeometry(1, 1);
        q.setTranslation(7, -3, 2);
        q.generate();
        q.conditionAlongSphere(1.5, true);
        assertEquals(inside + 1, m.getNumberOfMats());
        assertTrue(m.matExists("bystander"));
        // The links left are exactly the span-1 pairs among the surviving grid points:
        int expected = 0;
        String[] names = new String[m.getNumberOfMats()];
        for (int i = 0; i < names.length; i++) {
            names[i] = m.getMatNameAt(i);
        }
        for (int a = 0; a < names.length; a++) {
            for (int b = a + 1; b < names.length; b++) {
                if (names[a].startsWith("p_") && names[b].startsWith("p_")) {
                    int[] u = coords(names[a]), v = coords(names[b]);
                    int cheb = Math.max(Math.abs(u[0] - v[0]), Math.max(Math.abs(u[1] - v[1]), Math.abs(u[2] - v[2])));
                    if (cheb == 1) {
                        expected++;
                    }
                }
            }
        }
        assertEquals(expected, m.getNumberOfLinks());
        q.conditionAlongSphere(0.5, false);
        assertEquals(inside, m.getNumberOfMats());
        assertFalse(m.matExists("p_2_2_2"));
    }

    @Test
    void badArgumentsAreRejectedWithTheirValue() {
        PhysicalModel m = new PhysicalModel(1000, 50);
        assertThrows(IllegalArgumentException.class, () -> new TopoGenerator(null, "a", "b"));
        assertThrows(IllegalArgumentException.class, () -> new TopoGenerator(m, "", "b"));
        TopoGenerator q = new TopoGenerator(m, "a", "b");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> q.setDim(0, 1, 1, 1));
        assertTrue(e.getMessage().contains("0 x 1 x 1"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> q.setDim(2, 2, 2, -1));
        e = assertThrows(IllegalArgumentException.class, () -> q.setParams(0, 1, 1));
        assertTrue(e.getMessage().contains("mass"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> q.setParams(1, Double.NaN, 1));
        assertThrows(IllegalArgumentException.class, () -> q.setParams(1, 1, Double.POSITIVE_INFINITY));
        assertThrows(IllegalArgumentException.class, () -> q.setGeometry(-1, 1));
        assertThrows(IllegalArgumentException.class, () -> q.setGeometry(1, Double.NaN));
        assertThrows(IllegalArgumentException.class, () -> q.setRotation(Float.NaN, 0, 0));
        assertThrows(IllegalArgumentException.class, () -> q.setTranslation(0, Float.POSITIVE_INFINITY, 0));
        assertThrows(IllegalArgumentException.class, () -> q.addBoundaryCondition(null));
        assertThrows(IllegalArgumentException.class, () -> q.conditionAlongSphere(Double.NaN, true));
        e = assertThrows(IllegalArgumentException.class, q::generate);
        assertTrue(e.getMessage().contains("setParams"), e.getMessage());
        assertEquals(0, m.getNumberOfMats());
    }

    @Test
    void aRejectedGenerationLeavesTheModelUnchanged() {
        PhysicalModel m = new PhysicalModel(1000, 50);
        m.addMass3D("a_1_0_0", 1, new Vect3D(), new Vect3D());
        TopoGenerator q = new TopoGenerator(m, "a", "b");
        q.setDim(3, 1, 1, 1);
        q.setParams(1, 0.1, 0.01);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, q::generate);
        assertTrue(e.getMessage().contains("a_1_0_0"), e.getMessage());
        assertEquals(1, m.getNumberOfMats());
        assertEquals(0, m.getNumberOfLinks());

        TopoGenerator same = new TopoGenerator(m, "c", "d");
        same.setDim(2, 1, 1, 1);
        same.setParams(1, 0.1, 0.01);
        same.setMatSubsetName("x");
        same.setLinkSubsetName("x");
        assertThrows(IllegalArgumentException.class, same::generate);
        assertEquals(1, m.getNumberOfMats());

        // A mass subset name that is already a link subset: the first addition fails and is rolled back.
        m.createLinkSubset("taken");
        TopoGenerator clash = new TopoGenerator(m, "e", "f");
        clash.setDim(3, 2, 1, 1);
        clash.setParams(1, 0.1, 0.01);
        clash.setMatSubsetName("taken");
        assertThrows(IllegalArgumentException.class, clash::generate);
        assertEquals(1, m.getNumberOfMats());
        assertEquals(0, m.getNumberOfLinks());
    }

    @Test
    void twoGeneratorsShareAModelAndASubset() {
        PhysicalModel m = new PhysicalModel(1000, 50);
        for (String p : new String[] {"str0", "str1"}) {
            TopoGenerator q = new TopoGenerator(m, p, "spring");
            q.setDim(5, 1, 1, 1);
            q.setParams(1, 0.1, 0.01);
            q.setGeometry(1, 1);
            q.setMatSubsetName("strings");
            q.addBoundaryCondition(Bound.X_LEFT);
            q.generate();
        }
        assertEquals(10, m.getNumberOfMats());
        assertEquals(8, m.getNumberOfLinks());
        assertEquals(10, m.getSubsetMembers("strings").length);
        assertEquals(2, groundCount(m));
        m.init();
        m.computeNSteps(10);
    }
}
