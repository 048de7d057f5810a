package tactus.io;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.io.InputStreamReader;
import java.io.Reader;
import java.io.StringReader;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import tactus.Attractor3D;
import tactus.PhysicalModel;
import tactus.PlaneContact3D;
import tactus.Vect3D;
import tactus.paramSystem;

/**
 * ModelXml: a file written by hand in the paper's engine's format loads with every parameter; a saved
 * model has the structure the paper's loader walks; save then load reproduces trajectories bit for
 * bit; and every kind of bad file is refused with its line and element, leaving the model unchanged.
 */
class ModelXmlTest {
    static final String FIXTURE = "paper-format-all-types.xml";

    static PhysicalModel loadFixture() {
        PhysicalModel m = new PhysicalModel(1000, 50);
        try (Reader in = new InputStreamReader(ModelXmlTest.class.getResourceAsStream(FIXTURE), StandardCharsets.UTF_8)) {
            ModelXml.read(in, FIXTURE, m);
        } catch (java.io.IOException e) {
            throw new AssertionError(e);
        }
        return m;
    }

    /** A complete textual state of a model (names, types, positions, velocities, parameters, globals). */
    static String state(PhysicalModel m) {
        StringWriter w = new StringWriter();
        ModelXml.write(m, w, "state");
        return m.getNumberOfMats() + " " + m.getNumberOfLinks() + "\n" + w;
    }

    static String type(PhysicalModel m, int i) {
        return String.valueOf(m.getMatTypeAt(i));
    }

    @Test
    void aHandWrittenPaperFileLoadsEveryParameter() {
        PhysicalModel m = loadFixture();
        assertEquals(0.0010000000474974513, m.getGravity(), 0.0);
        assertEquals(1.0E-4, m.getFriction(), 0.0);
        // Masses come back in the order of their index attributes, not grouped by type.
        String[][] mats = {
            {"anchor", "Ground3D"}, {"g1d", "Ground1D"}, {"m1d", "Mass1D"}, {"m2d", "Mass2DPlane"}, {"mass", "Mass3D"},
            {"ball", "Mass3D"}, {"o1d", "Osc1D"}, {"o3d", "Osc3D"}, {"hapticMass", "HapticInput3D"},
        };
        assertEquals(mats.length, m.getNumberOfMats());
        for (int i = 0; i < mats.length; i++) {
            assertEquals(mats[i][0], m.getMatNameAt(i));
            assertEquals(mats[i][1], type(m, i));
        }
        assertPos(m, "anchor", -70, 0, 0);
        assertPos(m, "m2d", 10, -4, 1);
        assertPos(m, "hapticMass", 0, 0, 30);
        assertVel(m, "m1d", 0, 0, -0.75);
        assertVel(m, "m2d", 3, -1.25, 0);
        assertVel(m, "mass", 0, 0, 1);
        assertVel(m, "ball", -2, 0.5, 0);
        assertVel(m, "o3d", 0, 0.1, 0);
        assertEquals(2.0, m.getMatMass("m1d"), 0.0);
        assertEquals(1.5, m.getMatMass("m2d"), 0.0);
        assertEquals(0.5, m.getMatMass("ball"), 0.0);
        assertEquals(0.01, m.getMatStiffness("o1d"), 0.0);
        assertEquals(0.001, m.getMatDamping("o1d"), 0.0);
        assertEquals(0.05000000074505806, m.getMatStiffness("o3d"), 0.0);
        assertEquals(0.0020000000949949026, m.getMatDamping("o3d"), 0.0);

        // name, type, m1, m2, K, Z, length
        Object[][] links = {
            {"spring1", "SpringDamper3D", "mass", "anchor", 9.000000427477062E-4, 0.009999999776482582, 70.0},
            {"damp", "Damper3D", "mass", "ball", 0.0, 0.003, 0.0},
            {"spring", "Spring3D", "m2d", "anchor", 0.004, 0.0, 25.0},
            {"col", "Contact3D", "hapticMass", "mass", 0.05, 0.005, 4.0},
            {"floor", "PlaneContact3D", "ball", "ball", 0.1, 0.005, 0.5},
            {"rope", "Rope3D", "o3d", "ball", 0.03, 0.002, 15.0},
            {"sd1d", "SpringDamper1D", "m1d", "g1d", 0.02, 0.004, 2.5},
            {"bubble", "Bubble3D", "ball", "anchor", 0.02, 0.01, 100.0},
            {"spring2", "SpringDamper3D", "mass", "ball", 0.001, 0.01, 30.0},
        };
        assertEquals(links.length, m.getNumberOfLinks());
        for (int i = 0; i < links.length; i++) {
            Object[] l = links[i];
            assertEquals(l[0], m.getLinkNameAt(i));
            assertEquals(l[1], String.valueOf(m.getLinkTypeAt(i)));
            assertArrayEquals(new String[] {(String) l[2], (String) l[3]}, m.getLinkMatNames((String) l[0]));
            if (((Double) l[4]) != 0) {
                assertEquals((double) l[4], m.getLinkStiffnessAt(i), 0.0, (String) l[0]);
            }
            if (((Double) l[5]) != 0) {
                assertEquals((double) l[5], m.getLinkDampingAt(i), 0.0, (String) l[0]);
            }
            assertEquals((double) l[6], m.getLinkDRestAt(i), 0.0, (String) l[0]);
        }
        PlaneContact3D floor = (PlaneContact3D) m.getInteraction("floor");
        assertEquals(2, floor.getOrientation());
        assertEquals(-10.0, floor.getPlanePosition(), 0.0);
        m.computeNSteps(100);
    }

    static void assertPos(PhysicalModel m, String name, double x, double y, double z) {
        Vect3D p = m.getMatPosition(name);
        assertEquals(x, p.x, 0.0, name);
        assertEquals(y, p.y, 0.0, name);
        assertEquals(z, p.z, 0.0, name);
    }

    static void assertVel(PhysicalModel m, String name, double x, double y, double z) {
        // The model keeps X and X - v/fs; reading (X - XR) * fs back loses up to about ulp(X) * fs.
        Vect3D v = m.getMatVelocity(name);
        double tol = 4 * Math.ulp(Math.max(1, m.getMatPosition(name).norm())) * m.getSimRate();
        assertEquals(x, v.x, tol, name);
        assertEquals(y, v.y, tol, name);
        assertEquals(z, v.z, tol, name);
    }

    @Test
    void aLoadedFileSavesBackToTheSameModules() {
        PhysicalModel a = loadFixture();
        StringWriter w = new StringWriter();
        ModelXml.write(a, w, "again");
        PhysicalModel b = new PhysicalModel(1000, 50);
        ModelXml.read(new StringReader(w.toString()), "again", b);
        assertEquals(state(a), state(b));
    }

    /** Every module kind Tactus has, with velocities that make a naive velocity round trip lose bits. */
    static PhysicalModel everyKind(int rate, paramSystem units, long seed) {
        Random r = new Random(seed);
        PhysicalModel m = new PhysicalModel(rate, 50, units);
        double s = units == paramSystem.REAL_UNITS ? (double) rate * rate : 1;   // scale coefficients to stay stable
        m.setGravity(units == paramSystem.REAL_UNITS ? 9.81 : 1e-5);
        m.setGravityDirection(new Vect3D(0, -1, 0));
        m.setFriction(units == paramSystem.REAL_UNITS ? 1e-3 * rate : 1e-6);
        m.addGround3D("g3", new Vect3D(0, 0, 0));
        m.addGround1D("g1", new Vect3D(0, 5, 0));
        m.addMass3D("a", 1.3, new Vect3D(1e-3, 0, 2), hard(r, 1e-3, rate));
        m.addMass3D("b", 0.7, new Vect3D(3, 1, -2.0 / 3), vel(r, rate));
        m.addMass2DPlane("p", 1.1, new Vect3D(-1e-3, 0.1, 1), hard(r, -1e-3, rate));
        m.addMass1D("l", 2.0, new Vect3D(0, 5, 1.0 / 3), vel(r, rate));
        m.addOsc3D("o3", 1.0, 0.02 * s, 0.001 * Math.sqrt(s), new Vect3D(0.1, 0.2, 0.3), vel(r, rate));
        m.addOsc1D("o1", 1.0, 0.03 * s, 0.001 * Math.sqrt(s), new Vect3D(0, -1, 0), vel(r, rate));
        m.addHapticInput3D("h", new Vect3D(0, 0, 4), 3);
        m.addPosInput3D("d", new Vect3D(-1, 0, 4), 2);
        m.addSpring3D("s", 1.5, 0.01 * s, "a", "g3");
        m.addDamper3D("z", 0.001 * Math.sqrt(s), "a", "b");
        m.addSpringDamper3D("sd", 2.0, 0.01 * s, 0.002 * Math.sqrt(s), "b", "p");
        m.addSpringDamper1D("sd1", 0.5, 0.02 * s, 0.001 * Math.sqrt(s), "l", "g1");
        m.addRope3D("r", 3.0, 0.01 * s, 0.001 * Math.sqrt(s), "o3", "b");
        m.addContact3D("c", 1.0, 0.05 * s, 0.001 * Math.sqrt(s), "h", "a");
        m.addBubble3D("bu", 6.0, 0.01 * s, 0.001 * Math.sqrt(s), "b", "g3");
        m.addPlaneContact("pl", 0.1, 0.05 * s, 0.001 * Math.sqrt(s), 2, -3, "p");
        m.addAttractor3D("at", 0.5, 1e-4 * s, "d", "a");
        m.addSpringDamper3D("pd", 1.0, 0.01 * s, 0.001 * Math.sqrt(s), "d", "b");
        return m;
    }

    /** A random velocity (units per second) whose per-step displacement is large against small coordinates. */
    static Vect3D vel(Random r, int rate) {
        return new Vect3D((r.nextDouble() - 0.5) * 0.3 * rate, (r.nextDouble() - 0.5) * 0.3 * rate,
                (r.nextDouble() - 0.5) * 0.3 * rate);
    }

    /**
     * A velocity whose x component a naive save (write (X - XR) * fs, load XR = X - v / fs) would not
     * bring back to the same delayed position for a mass at x: the case the velocity codec exists for.
     */
    static Vect3D hard(Random r, double x, int rate) {
        for (int tries = 0; tries < 10_000_000; tries++) {
            Vect3D v = vel(r, rate);
            double xr = x - v.x / rate;
            if (x - ((x - xr) * rate) / rate != xr) {
                return v;
            }
        }
        throw new AssertionError("no hard velocity found for x = " + x + " at " + rate + " Hz");
    }

    @Test
    void saveThenLoadReproducesTrajectoriesBitForBit(@TempDir Path dir) {
        int[] rates = {1000, 1050, 44100};
        for (int t = 0; t < rates.length; t++) {
            PhysicalModel original = everyKind(rates[t], paramSystem.ALGO_UNITS, 17 + t);
            File file = dir.resolve("every-kind-" + t + ".xml").toFile();
            ModelXml.save(original, file);
            PhysicalModel loaded = new PhysicalModel(rates[t], 50, paramSystem.ALGO_UNITS);
            ModelXml.load(file, loaded);
            original.init();
            assertEquals(original.getNumberOfMats(), loaded.getNumberOfMats());
            assertEquals(original.getNumberOfLinks(), loaded.getNumberOfLinks());
            compareTrajectories(original, loaded, 3000);
        }
    }

    @Test
    void aGeneratedBeamRoundTripsWithItsRepeatedLinkNames(@TempDir Path dir) {
        PhysicalModel original = new PhysicalModel(1000, 50);
        tactus.TopoGenerator q = new tactus.TopoGenerator(original, "mass", "spring");
        q.setDim(4, 2, 3, 1);
        q.setParams(1, 0.01, 0.001);
        q.setGeometry(2, 2);
        q.addBoundaryCondition(tactus.Bound.Z_LEFT);
        q.generate();
        original.triggerForceImpulse("mass_3_1_2", 0.5, 0, 0);
        File file = dir.resolve("beam.xml").toFile();
        ModelXml.save(original, file);
        PhysicalModel loaded = new PhysicalModel(1000, 50);
        ModelXml.load(file, loaded);
        assertEquals(original.getNumberOfLinks(), loaded.getNumberOfLinks());
        for (int i = 0; i < original.getNumberOfLinks(); i++) {
            assertEquals(original.getLinkNameAt(i), loaded.getLinkNameAt(i));
            assertArrayEquals(LinkEnds.of(original, i), LinkEnds.of(loaded, i), "link " + i);
            assertEquals(original.getLinkDRestAt(i), loaded.getLinkDRestAt(i), 0.0, "link " + i);
        }
        original.init();
        loaded.triggerForceImpulse("mass_3_1_2", 0.5, 0, 0);
        compareTrajectories(original, loaded, 400);
    }

    /**
     * In REAL_UNITS the saved numbers went through the unit conversion (K / fs^2 in, K_algo * fs^2 out) and go
     * through it again on loading. Dividing, multiplying and dividing again by the same factor gives back the
     * same double for every value we tried (also a million random ones per rate, outside this suite), but this
     * is observed, not proven: the page promises agreement to within rounding.
     */
    @Test
    void realUnitsRoundTripMatchesThisModelBitForBit(@TempDir Path dir) {
        PhysicalModel original = everyKind(2000, paramSystem.REAL_UNITS, 5);
        File file = dir.resolve("real.xml").toFile();
        ModelXml.save(original, file);
        PhysicalModel loaded = new PhysicalModel(2000, 50, paramSystem.REAL_UNITS);
        ModelXml.load(file, loaded);
        original.init();
        compareTrajectories(original, loaded, 500);
        // A REAL_UNITS file refuses to load into an ALGO_UNITS model: the numbers would mean something else.
        PhysicalModel algo = new PhysicalModel(2000, 50);
        ModelFileException e = assertThrows(ModelFileException.class, () -> ModelXml.load(file, algo));
        assertTrue(e.getMessage().contains("REAL_UNITS"), e.getMessage());
        assertEquals(7, e.getLine(), e.getMessage());
        assertEquals("units", e.getElement());
        assertEquals(0, algo.getNumberOfMats());
    }

    /** Steps both models and asserts every mass position is bit-identical at every step. */
    static void compareTrajectories(PhysicalModel a, PhysicalModel b, int steps) {
        int n = a.getNumberOfMats();
        Vect3D p = new Vect3D(), q = new Vect3D();
        for (int step = 0; step < steps; step++) {
            for (int i = 0; i < n; i++) {
                String name = a.getMatNameAt(i);
                a.getMatPosition(name, p);
                b.getMatPosition(name, q);
                String where = name + " at step " + step;
                assertEquals(Double.doubleToRawLongBits(p.x), Double.doubleToRawLongBits(q.x), where);
                assertEquals(Double.doubleToRawLongBits(p.y), Double.doubleToRawLongBits(q.y), where);
                assertEquals(Double.doubleToRawLongBits(p.z), Double.doubleToRawLongBits(q.z), where);
            }
            a.computeStep();
            b.computeStep();
        }
    }

    @Test
    void theVelocityCodecRebuildsTheDelayedPositionWhereTheNaiveValueDoesNot() {
        Random r = new Random(11);
        int naiveMisses = 0;
        for (double fs : new double[] {1000, 1050, 44100, 48000}) {
            for (int i = 0; i < 200000; i++) {
                double x = r.nextInt(3) == 0 ? 0 : (r.nextDouble() - 0.5) * Math.pow(10, r.nextInt(10) - 5);
                double v = (r.nextDouble() - 0.5) * Math.pow(10, r.nextInt(10) - 3);
                double xr = x - v / fs;                 // what the model stores
                double reported = (x - xr) * fs;        // what getMatVelAt reports
                if (x - reported / fs != xr) {
                    naiveMisses++;
                }
                double written = VelocityCodec.encode(x, reported, fs);
                assertEquals(xr, x - written / fs, 0.0, "x=" + x + " v=" + v + " fs=" + fs);
                assertEquals(xr, x - VelocityCodec.fromDelayed(x, xr, fs) / fs, 0.0, "x=" + x + " v=" + v + " fs=" + fs);
            }
        }
        assertTrue(naiveMisses > 0, "the sample must contain cases the naive round trip gets wrong");
    }

    @Test
    void linksMayReferToMassesAlreadyInTheModel() {
        PhysicalModel m = new PhysicalModel(1000, 50);
        m.addGround3D("wall", new Vect3D(5, 0, 0));
        String xml = "<x>\n  <global>\n    <gravity gravity=\"0\"/>\n    <friction friction=\"0\"/>\n"
                + "    <vector pos.x=\"0\" pos.y=\"0\" pos.z=\"1\"/>\n  </global>\n  <MAT>\n    <Mass3D>\n"
                + "      <mass_0 initPos.x=\"1\" initPos.y=\"0\" initPos.z=\"0\" mass=\"1\" name=\"bob\"/>\n"
                + "    </Mass3D>\n  </MAT>\n  <Link>\n    <SpringDamper3D>\n"
                + "      <interaction_0 damping=\"0.1\" drest=\"4\" m1=\"bob\" m2=\"wall\" name=\"tie\" stiffness=\"0.1\"/>\n"
                + "    </SpringDamper3D>\n  </Link>\n</x>\n";
        ModelXml.read(new StringReader(xml), "inline", m);
        assertEquals(2, m.getNumberOfMats());
        assertArrayEquals(new String[] {"bob", "wall"}, m.getLinkMatNames("tie"));
        assertEquals(0, m.getMatVelocity("bob").norm(), 0.0);   // posR is optional: at rest
    }

    // ------------------------------------------------------------------ refused files

    static final String GOOD_HEAD = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<bad.xml>\n  <global>\n"
            + "    <gravity gravity=\"0.0\"/>\n    <friction friction=\"0.0\"/>\n"
            + "    <vector pos.x=\"0.0\" pos.y=\"0.0\" pos.z=\"1.0\"/>\n  </global>\n";

    static String file(String mat, String link) {
        return GOOD_HEAD + "  <MAT>\n" + mat + "  </MAT>\n  <Link>\n" + link + "  </Link>\n</bad.xml>\n";
    }

    static final String TWO_MASSES = "    <Mass3D>\n"
            + "      <mass_0 index=\"0\" initPos.x=\"0.0\" initPos.y=\"0.0\" initPos.z=\"0.0\" mass=\"1.0\" name=\"a\"/>\n"
            + "      <mass_1 index=\"1\" initPos.x=\"1.0\" initPos.y=\"0.0\" initPos.z=\"0.0\" mass=\"1.0\" name=\"b\"/>\n"
            + "    </Mass3D>\n";

    /** Loads {@code xml} into a model that already holds modules and asserts a refusal naming line and element. */
    static ModelFileException refused(String xml, int line, String element, String... words) {
        PhysicalModel m = new PhysicalModel(1000, 50);
        m.setGravity(0.5);
        m.setFriction(0.01);
        m.addMass3D("keep", 1, new Vect3D(0, 0, 9), new Vect3D(1, 2, 3));
        m.addGround3D("pin", new Vect3D());
        m.addSpringDamper3D("keepLink", 1, 0.1, 0.01, "keep", "pin");
        String before = state(m);
        ModelFileException e = assertThrows(ModelFileException.class, () -> ModelXml.read(new StringReader(xml), "bad.xml", m));
        assertEquals(line, e.getLine(), e.getMessage());
        assertEquals(element, e.getElement(), e.getMessage());
        assertTrue(e.getMessage().startsWith("bad.xml"), e.getMessage());
        for (String w : words) {
            assertTrue(e.getMessage().contains(w), "\"" + w + "\" not in: " + e.getMessage());
        }
        assertEquals(before, state(m), "the model must be unchanged");
        return e;
    }

    @Test
    void malformedXmlNamesTheLine() {
        String xml = file(TWO_MASSES, "    <Spring3D>\n      <interaction_0 drest=\"1\"\n    </Spring3D>\n");
        ModelFileException e = assertThrows(ModelFileException.class,
                () -> ModelXml.read(new StringReader(xml), "bad.xml", new PhysicalModel(1000, 50)));
        assertTrue(e.getLine() >= 16 && e.getLine() <= 17, e.getMessage());
        assertTrue(e.getMessage().contains("malformed XML"), e.getMessage());
        refused("<a><b></a>", 1, "b", "malformed XML");
    }

    @Test
    void unknownModuleTypesAreRefused() {
        refused(file(TWO_MASSES + "    <Mass4D>\n      <mass_2 name=\"c\"/>\n    </Mass4D>\n", ""), 13, "Mass4D", "unknown mass type");
        refused(file(TWO_MASSES, "    <Spring9D/>\n"), 15, "Spring9D", "unknown interaction type");
    }

    @Test
    void missingSectionsAndAttributesAreRefused() {
        refused("<x>\n  <MAT/>\n  <Link/>\n</x>", 1, "x", "<global>");
        refused(GOOD_HEAD + "  <Link/>\n</bad.xml>\n", 2, "bad.xml", "<MAT>");
        refused(file("    <Mass3D>\n      <mass_0 initPos.x=\"0\" initPos.y=\"0\" initPos.z=\"0\" name=\"a\"/>\n    </Mass3D>\n", ""),
                10, "mass_0", "\"mass\"");
        refused(file("    <Osc3D>\n      <mass_0 initPos.x=\"0\" initPos.y=\"0\" initPos.z=\"0\" mass=\"1\" name=\"o\" damping=\"0.1\"/>\n    </Osc3D>\n", ""),
                10, "mass_0", "\"stiffness\"");
        refused(file(TWO_MASSES, "    <Spring3D>\n      <interaction_0 drest=\"1\" m1=\"a\" m2=\"b\" name=\"s\" stiffness=\"soft\"/>\n    </Spring3D>\n"),
                16, "interaction_0", "\"stiffness\"", "soft");
        refused(file(TWO_MASSES, "    <PlaneContact3D>\n      <interaction_0 damping=\"0\" drest=\"0\" m1=\"a\" m2=\"a\" name=\"p\" position=\"0\" stiffness=\"1\"/>\n    </PlaneContact3D>\n"),
                16, "interaction_0", "\"orientation\"");
    }

    @Test
    void danglingReferencesAreRefused() {
        refused(file(TWO_MASSES, "    <SpringDamper3D>\n      <interaction_0 damping=\"0.1\" drest=\"1\" m1=\"a\" m2=\"nobody\" name=\"s\" stiffness=\"0.1\"/>\n    </SpringDamper3D>\n"),
                16, "interaction_0", "\"nobody\"", "\"s\"");
    }

    @Test
    void clashingNamesAndIndicesAreRefused() {
        String dup = "    <Mass3D>\n      <mass_0 initPos.x=\"0\" initPos.y=\"0\" initPos.z=\"0\" mass=\"1\" name=\"a\"/>\n"
                + "      <mass_1 initPos.x=\"0\" initPos.y=\"0\" initPos.z=\"0\" mass=\"1\" name=\"a\"/>\n    </Mass3D>\n";
        refused(file(dup, ""), 11, "mass_1", "used twice");
        String taken = "    <Ground3D>\n      <mass_0 initPos.x=\"0\" initPos.y=\"0\" initPos.z=\"0\" name=\"keep\"/>\n    </Ground3D>\n";
        refused(file(taken, ""), 10, "mass_0", "already has a mass named \"keep\"");
        String sameIndex = TWO_MASSES.replace("index=\"1\"", "index=\"0\"");
        refused(file(sameIndex, ""), 11, "mass_1", "index 0");
        String someIndex = TWO_MASSES.replace("index=\"1\" ", "");
        refused(file(someIndex, ""), 11, "mass_1", "index attribute is missing");
    }

    @Test
    void theModelsOwnChecksAreReportedWithTheLine() {
        String negative = TWO_MASSES.replace("mass=\"1.0\" name=\"b\"", "mass=\"-1.0\" name=\"b\"");
        refused(file(negative, ""), 11, "mass_1", "mass must be");
        // A failure on the last link undoes the masses and links added before it.
        String links = "    <SpringDamper3D>\n"
                + "      <interaction_0 damping=\"0.1\" drest=\"1\" index=\"0\" m1=\"a\" m2=\"b\" name=\"s1\" stiffness=\"0.1\"/>\n"
                + "      <interaction_1 damping=\"0.1\" drest=\"1\" index=\"1\" m1=\"a\" m2=\"nobody\" name=\"s2\" stiffness=\"0.1\"/>\n"
                + "    </SpringDamper3D>\n";
        refused(file(TWO_MASSES, links), 17, "interaction_1", "nobody");
        // a link from a mass to itself is skipped with one warning, as the paper's engine and PhysicalModel do
        PhysicalModel m = new PhysicalModel(1000, 50);
        ModelXml.read(new StringReader(file(TWO_MASSES, links.replace("nobody", "a"))), "self.xml", m);
        assertEquals(1, m.getNumberOfLinks());
        assertTrue(m.linkExists("s1"));
        refused(file(TWO_MASSES, "    <Damper3D>\n      <interaction_0 damping=\"NaN\" m1=\"a\" m2=\"b\" name=\"z\"/>\n    </Damper3D>\n"),
                16, "interaction_0", "Z");
    }

    @Test
    void badGlobalsNameTheGlobalElement() {
        String xml = file(TWO_MASSES, "").replace("<friction friction=\"0.0\"/>", "<friction friction=\"Infinity\"/>");
        refused(xml, 3, "global", "friction");
    }

    @Test
    void aMass3DSimpleLoadsAndRoundTrips() {
        String simple = "    <Mass3DSimple>\n      <mass_0 initPos.x=\"0.5\" initPos.y=\"0\" initPos.z=\"0\" mass=\"2\" name=\"s\"/>\n"
                + "    </Mass3DSimple>\n";
        PhysicalModel m = new PhysicalModel(1000, 50);
        ModelXml.read(new StringReader(file(simple, "")), "simple.xml", m);
        assertEquals("Mass3DSimple", String.valueOf(m.getMatTypeAt(m.getMatIndex("s"))));
        assertEquals(2.0, m.getMatMass("s"), 0.0);
        StringWriter w = new StringWriter();
        ModelXml.write(m, w, "simple.xml");
        assertTrue(w.toString().contains("<Mass3DSimple>"), w.toString());
    }

    @Test
    void attractorsAndPositionInputsUseTactusGroups() {
        PhysicalModel m = everyKind(1000, paramSystem.ALGO_UNITS, 3);
        StringWriter w = new StringWriter();
        ModelXml.write(m, w, "kinds.xml");
        String xml = w.toString();
        assertTrue(xml.contains("<Attractor3D>"), xml);
        assertTrue(xml.contains("attrFactor=\"1.0E-4\""), xml);
        assertTrue(xml.contains("<PosInput3D>"), xml);
        assertTrue(xml.startsWith("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<kinds.xml>\n  <global>\n"), xml);
        PhysicalModel back = new PhysicalModel(1000, 50);
        ModelXml.read(new StringReader(xml), "kinds.xml", back);
        assertEquals(1e-4, ((Attractor3D) back.getInteraction("at")).getAttraction(), 0.0);
        assertEquals(0.5, back.getLinkDRest("at"), 0.0);
        assertEquals("PosInput3D", String.valueOf(back.getMatTypeAt(back.getMatIndex("d"))));
    }

    @Test
    void rootNamesAreValidXml() {
        assertEquals("HelloMass.xml", ModelXml.rootNameFor("HelloMass.xml"));
        assertEquals("model", ModelXml.rootNameFor("2strings.xml"));
        assertEquals("model", ModelXml.rootNameFor("my model.xml"));
        assertEquals("model", ModelXml.rootNameFor(null));
        assertNotNull(ModelXml.rootNameFor("xmlish"));
    }

    @Test
    void aMissingFileIsAnIoError(@TempDir Path dir) throws Exception {
        File f = dir.resolve("absent.xml").toFile();
        java.io.UncheckedIOException e = assertThrows(java.io.UncheckedIOException.class,
                () -> ModelXml.load(f, new PhysicalModel(1000, 50)));
        assertTrue(e.getMessage().contains("absent.xml"), e.getMessage());
        assertTrue(Files.notExists(f.toPath()));
    }

    /** File errors show the full path tried, and why, also for a relative name. */
    @Test
    void fileErrorsShowTheFullPathTried(@TempDir Path dir) throws Exception {
        File relative = new File("no-such-folder-" + System.nanoTime(), "absent.xml");
        java.io.UncheckedIOException e = assertThrows(java.io.UncheckedIOException.class,
                () -> ModelXml.load(relative, new PhysicalModel(1000, 50)));
        assertEquals("cannot read the model file " + relative.getAbsolutePath() + ": there is no such file (a relative"
                + " name is taken from the working directory, " + new File("").getAbsolutePath() + ", or in a sketch"
                + " from the sketch folder)", e.getMessage());
        File bad = dir.resolve("bad.xml").toFile();
        Files.write(bad.toPath(), "<model><mass></model>".getBytes(java.nio.charset.StandardCharsets.UTF_8));
        ModelFileException malformed = assertThrows(ModelFileException.class,
                () -> ModelXml.load(bad, new PhysicalModel(1000, 50)));
        assertTrue(malformed.getMessage().startsWith(bad.getAbsolutePath()), malformed.getMessage());
        File blocker = dir.resolve("a-file").toFile();
        Files.write(blocker.toPath(), new byte[0]);
        File unwritable = new File(blocker, "model.xml");
        java.io.UncheckedIOException w = assertThrows(java.io.UncheckedIOException.class,
                () -> ModelXml.save(new PhysicalModel(1000, 50), unwritable));
        assertTrue(w.getMessage().startsWith("cannot write the model file " + unwritable.getAbsolutePath() + ": "),
                w.getMessage());
    }
}
