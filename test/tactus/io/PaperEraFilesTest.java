package tactus.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.InputStreamReader;
import java.io.Reader;
import java.io.StringReader;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;
import tactus.PhysicalModel;
import tactus.PlaneContact3D;
import tactus.Vect3D;

/**
 * Model files as the paper-era engine writes them (v1.1.1 up to the paper's commit: velocities in
 * {@code initVel.*}, every group written, alphabetical attributes, a plane contact's {@code m2} empty, a
 * damper with {@code drest} and {@code stiffness} too, a haptic input with its position only), and as its first
 * loader wrote them ({@code posR.*}). Both fixtures hold one module of every type, with the same numbers; each
 * must load with its counts, positions and velocities, checked through the API and by one step: with no
 * gravity, no friction and no force yet, every simulated mass moves by its velocity / fs in the first step.
 */
class PaperEraFilesTest {
    static final String PAPER_ERA = "paper-era-every-type.xml";
    static final String EARLY = "early-posr-every-type.xml";
    static final int FS = 1000;

    /** name, type, initial position, initial velocity (units per second), as written in both fixtures. */
    static final Object[][] MASSES = {
        {"anchor", "Ground3D", v(-70, 0, 0), v(0, 0, 0)},
        {"g1d", "Ground1D", v(0, 5, 0), v(0, 0, 0)},
        {"m1d", "Mass1D", v(0, 5, 2.5), v(0, 0, -750)},
        {"m2d", "Mass2DPlane", v(10, -4, 1), v(500, -250, 0)},
        {"ball", "Mass3D", v(20, 0, 0), v(-2000, 500, 125)},
        {"simple", "Mass3DSimple", v(0, 20, 0), v(0, 250, -500)},
        {"o1d", "Osc1D", v(0, -5, 0), v(0, 0, 500)},
        {"o3d", "Osc3D", v(30, 0, 0), v(0, 125, -250)},
        {"hand", "HapticInput3D", v(0, 0, 30), v(0, 0, 0)},
    };

    static final String[][] LINKS = {
        {"sd3d", "SpringDamper3D"}, {"damp", "Damper3D"}, {"spring", "Spring3D"}, {"col", "Contact3D"},
        {"floor", "PlaneContact3D"}, {"rope", "Rope3D"}, {"sd1d", "SpringDamper1D"}, {"bubble", "Bubble3D"},
    };

    static Vect3D v(double x, double y, double z) {
        return new Vect3D(x, y, z);
    }

    static PhysicalModel load(String fixture) {
        PhysicalModel m = new PhysicalModel(FS, 50);
        try (Reader in = new InputStreamReader(PaperEraFilesTest.class.getResourceAsStream(fixture),
                StandardCharsets.UTF_8)) {
            ModelXml.read(in, fixture, m);
        } catch (java.io.IOException e) {
            throw new AssertionError(e);
        }
        return m;
    }

    @Test
    void aPaperEraFileLoadsEveryTypeWithItsVelocities() {
        checkEveryType(load(PAPER_ERA), PAPER_ERA);
    }

    @Test
    void aFileOfTheFirstLoaderWithPosRLoadsTheSame() {
        checkEveryType(load(EARLY), EARLY);
    }

    private static void checkEveryType(PhysicalModel m, String what) {
        assertEquals(MASSES.length, m.getNumberOfMats(), what + ": masses");
        assertEquals(LINKS.length, m.getNumberOfLinks(), what + ": interactions");
        for (int i = 0; i < MASSES.length; i++) {
            String name = (String) MASSES[i][0];
            assertEquals(name, m.getMatNameAt(i), what + ": the index attributes give the order");
            assertEquals(MASSES[i][1], String.valueOf(m.getMatTypeAt(i)), what + ": type of " + name);
            assertEquals(((Vect3D) MASSES[i][2]).toString(), m.getMatPosAt(i).toString(), what + ": position of " + name);
        }
        for (int i = 0; i < LINKS.length; i++) {
            assertEquals(LINKS[i][0], m.getLinkNameAt(i), what);
            assertEquals(LINKS[i][1], String.valueOf(m.getLinkTypeAt(i)), what + ": type of " + LINKS[i][0]);
        }
        assertEquals(0.003, m.getLinkDamping("damp"), 0.0, what);
        assertEquals(0.004, m.getLinkStiffness("spring"), 0.0, what);
        assertEquals(25.0, m.getLinkDRest("spring"), 0.0, what);
        PlaneContact3D floor = (PlaneContact3D) m.getInteraction("floor");
        assertEquals(2, floor.getOrientation(), what);
        assertEquals(-10.0, floor.getPlanePosition(), 0.0, what);
        assertEquals("ball,ball", String.join(",", m.getLinkMatNames("floor")), what + ": the empty m2 of a plane");

        // Velocities through the API (the axes a mass moves along; a Mass1D moves along z, a Mass2DPlane in x-y).
        for (Object[] row : MASSES) {
            String name = (String) row[0];
            Vect3D expected = (Vect3D) row[3];
            Vect3D got = m.getMatVelocity(name);
            assertTrue(got.dist(expected) < 1e-9, what + ": velocity of " + name + " is " + got + ", the file says "
                    + expected);
        }

        // One step: no gravity, no friction and no force yet, so each mass moves by its velocity / fs.
        Vect3D[] before = new Vect3D[MASSES.length];
        for (int i = 0; i < MASSES.length; i++) {
            before[i] = m.getMatPosAt(i);
        }
        m.computeStep();
        for (int i = 0; i < MASSES.length; i++) {
            Vect3D moved = m.getMatPosAt(i).sub(before[i]);
            Vect3D expected = new Vect3D((Vect3D) MASSES[i][3]).div(FS);
            assertTrue(moved.dist(expected) < 1e-12, what + ": " + MASSES[i][0] + " moved by " + moved
                    + " in the first step, expected " + expected);
        }
    }

    @Test
    void theVelocityOfAPaperEraFileIsNotLostThroughASaveAndALoad() {
        PhysicalModel first = load(PAPER_ERA);
        StringWriter w = new StringWriter();
        ModelXml.write(first, w, "again");
        assertTrue(w.toString().contains("initVel.x=\"-2000.0\""), "Tactus writes the paper-era attribute:\n" + w);
        assertTrue(!w.toString().contains("posR."), "and not the first loader's");
        PhysicalModel second = new PhysicalModel(FS, 50);
        ModelXml.read(new StringReader(w.toString()), "again", second);
        for (Object[] row : MASSES) {
            String name = (String) row[0];
            assertEquals(first.getMatVelocity(name).toString(), second.getMatVelocity(name).toString(), name);
        }
    }

    @Test
    void twoDifferentVelocitiesInOneElementAreRefusedWithTheirNames() {
        String one = "<?xml version=\"1.0\"?>\n<m>\n  <global>\n    <gravity gravity=\"0.0\"/>\n"
                + "    <friction friction=\"0.0\"/>\n    <vector pos.x=\"0.0\" pos.y=\"0.0\" pos.z=\"1.0\"/>\n"
                + "  </global>\n  <MAT>\n    <Mass3D>\n      <mass_0 index=\"0\" initPos.x=\"0\" initPos.y=\"0\""
                + " initPos.z=\"0\" initVel.x=\"%s\" mass=\"1\" name=\"a\" posR.x=\"%s\"/>\n    </Mass3D>\n"
                + "  </MAT>\n  <Link/>\n</m>\n";
        PhysicalModel agree = new PhysicalModel(FS, 50);
        ModelXml.read(new StringReader(String.format(one, "3.0", "3.0")), "agree", agree);
        assertEquals(3.0, agree.getMatVelocity("a").x, 1e-9);

        PhysicalModel m = new PhysicalModel(FS, 50);
        ModelFileException e = assertThrows(ModelFileException.class,
                () -> ModelXml.read(new StringReader(String.format(one, "3.0", "4.0")), "both", m));
        assertTrue(e.getMessage().contains("initVel.x") && e.getMessage().contains("posR.x")
                && e.getMessage().contains("mass_0"), e.getMessage());
        assertEquals(0, m.getNumberOfMats(), "the model is unchanged");
    }
}
