package tactus;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.function.Consumer;
import org.junit.jupiter.api.Test;

/**
 * The calls of the paper's API that the paper's engine (miPhysics) silently ignored: by default each does what the
 * original did, leaves the model in the state the original would have, and prints one warning per kind of problem
 * (not one per call); with {@code setStrict(true)} each throws the exception it threw before and changes nothing.
 */
class PaperLeniencyTest {

    /** A small scene: a ground, two masses, an oscillator, an avatar, springs, a damper, a plane, subsets. */
    static PhysicalModel scene() {
        PhysicalModel m = new PhysicalModel(1000, 50);
        m.addGround3D("gnd", new Vect3D(0, 0, 0));
        m.addMass3D("m1", 1, new Vect3D(1, 0, 0), new Vect3D(0, 0, 0));
        m.addMass3D("m2", 2, new Vect3D(2, 0, 0), new Vect3D(0, 0, 0));
        m.addOsc3D("o", 1, 0.01, 0.001, new Vect3D(0, 2, 0), new Vect3D(0, 0, 0));
        m.addHapticInput3D("h", new Vect3D(0, 0, 3), 1);
        m.addSpringDamper3D("s1", 1, 0.01, 0.001, "gnd", "m1");
        m.addSpring3D("s2", 1, 0.02, "m1", "m2");
        m.addDamper3D("d", 0.003, "m2", "gnd");
        m.addPlaneContact("p", 0, 0.1, 0.01, 2, -1, "m1");
        m.createMatSubset("all");
        for (String n : new String[] {"gnd", "m1", "m2", "o"}) {
            m.addMatToSubset(n, "all");
        }
        m.createLinkSubset("links");
        for (String n : new String[] {"s1", "s2", "d"}) {
            m.addLinkToSubset(n, "links");
        }
        m.init();
        m.computeNSteps(5);
        return m;
    }

    /** Runs {@code call} on a forgiving scene, returns what it printed to standard error. */
    private static String forgiving(PhysicalModel m, Consumer<PhysicalModel> call) {
        PrintStream old = System.err;
        ByteArrayOutputStream buf = new ByteArrayOutputStream();
        System.setErr(new PrintStream(buf, true, StandardCharsets.UTF_8));
        try {
            call.accept(m);
        } finally {
            System.setErr(old);
        }
        return buf.toString(StandardCharsets.UTF_8);
    }

    private static int warnings(String err) {
        return err.split("Tactus: ", -1).length - 1;
    }

    /** In strict mode the call throws a message naming {@code element}, and the model is exactly as before. */
    private static void strictThrows(Consumer<PhysicalModel> call, String element) {
        PhysicalModel m = scene();
        m.setStrict(true);
        String before = ModelState.of(m, "all", "links");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> call.accept(m));
        assertTrue(e.getMessage().contains(element), e.getMessage());
        assertEquals(before, ModelState.of(m, "all", "links"), "strict: the model is unchanged");
        assertEquals(0, m.core.lenient.forgivenCount());
    }

    @Test
    void forgivingIsTheDefaultAndStrictIsASwitch() {
        PhysicalModel m = new PhysicalModel(100);
        assertFalse(m.isStrict());
        m.setStrict(true);
        assertTrue(m.isStrict());
        m.setStrict(false);
        assertFalse(m.isStrict());
    }

    @Test
    void aLinkFromAMassToItselfIsNotAddedAndWarnedOnce() {
        PhysicalModel m = scene();
        int links = m.getNumberOfLinks();
        String before = ModelState.of(m, "all", "links");
        String err = forgiving(m, x -> {
            // the paper's loop over every module, which includes the one it links to
            for (int i = 0; i < x.getNumberOfMats(); i++) {
                x.addBubble3D("bub" + i, 3, 0.1, 0.1, "gnd", x.getMatNameAt(i));
            }
            assertNull(x.addContact3D("col", 0.5, 0.1, 0.1, "m1", "m1"));
            assertNull(x.addSpring3D("self", 1, 0.1, "o", "o"));
            assertNull(x.addAttractor3D("att", 0.1, 1, "m2", "m2"));
        });
        assertEquals(links + m.getNumberOfMats() - 1, m.getNumberOfLinks(), "every bubble but gnd-gnd was added");
        assertFalse(m.linkExists("bub0"));
        assertTrue(m.linkExists("bub1"));
        assertFalse(m.linkExists("col") || m.linkExists("self") || m.linkExists("att"));
        assertEquals(1, warnings(err), err);
        assertTrue(err.contains("addBubble3D(\"bub0\"): cannot link mass \"gnd\" to itself"), err);
        assertTrue(err.contains("not added"), err);
        assertEquals(4, m.core.lenient.forgivenCount());
        // nothing else changed: removing the bubbles gives back the scene as it was
        for (int i = 1; i < m.getNumberOfMats(); i++) {
            m.removeLink("bub" + i);
        }
        assertEquals(before, ModelState.of(m, "all", "links"));
        strictThrows(x -> x.addBubble3D("b", 3, 0.1, 0.1, "gnd", "gnd"), "gnd");
        strictThrows(x -> x.addContact3D("c", 3, 0.1, 0.1, "m1", "m1"), "m1");
    }

    @Test
    void handleCallsStayStrict() {
        PhysicalModel m = scene();
        Mass a = m.getMass("m1");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> m.addContact3D("c", 1, 0.1, 0.1, a, a));
        assertTrue(e.getMessage().contains("itself"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> m.getMatMass("gnd"));
        assertThrows(IllegalArgumentException.class, () -> m.addContactGroup("nope", 1, 0.1, 0.1));
        assertThrows(IllegalArgumentException.class, () -> m.getHapticForce("m1", new Vect3D()));
        assertEquals(0, m.core.lenient.forgivenCount());
    }

    @Test
    void aSubsetNeverCreatedChangesNothing() {
        PhysicalModel m = scene();
        String before = ModelState.of(m, "all", "links");
        String err = forgiving(m, x -> {
            for (int frame = 0; frame < 100; frame++) { // as a sketch's draw() would
                x.changeDampingParamOfSubset(0.5, "stretchingFactor");
                x.changeStiffnessParamOfSubset(0.5, "stretchingFactor");
                x.changeParamOfSubset(0.5f, "nope", "stiffness");
                x.changeDistXBetweenSubset(new Vect3D(), 1, "nope");
            }
            assertEquals(-1, x.getParamValueOfSubset("nope", "stiffness"), 0);
        });
        assertEquals(before, ModelState.of(m, "all", "links"));
        assertEquals(1, warnings(err), err);
        assertTrue(err.contains("changeDampingParamOfSubset(\"stretchingFactor\"): no such subset"), err);
        assertEquals(401, m.core.lenient.forgivenCount());
        strictThrows(x -> x.changeDampingParamOfSubset(0.5, "stretchingFactor"), "stretchingFactor");
        strictThrows(x -> x.changeDistXBetweenSubset(new Vect3D(), 1, "nope"), "nope");
        strictThrows(x -> x.getParamValueOfSubset("nope", "mass"), "nope");
    }

    @Test
    void massAndDistOfASubsetNeverCreatedStillThrowAsTheyCrashedTheOriginal() {
        PhysicalModel m = scene();
        assertThrows(IllegalArgumentException.class, () -> m.changeMassParamOfSubset(2, "nope"));
        assertThrows(IllegalArgumentException.class, () -> m.changeDistParamOfSubset(2, "nope"));
        assertThrows(IllegalArgumentException.class, () -> m.getBarycenterOfSubset("nope"));
        assertEquals(0, m.core.lenient.forgivenCount());
    }

    @Test
    void aMidiControllerOnASubsetNeverCreatedChangesNothing() {
        PhysicalModel m = scene();
        String err = forgiving(m, x -> {
            MidiController k = MidiController.addMidiController(x, 4, 0.1f, 0.4f, "col", "stiffness");
            MidiController z = MidiController.addMidiController(x, 5, 0.0001f, 0.1f, "col", "damping");
            k.changeParam(4, 100);
            z.changeParam(5, 10);
            x.computeNSteps(10);
        });
        PhysicalModel twin = scene();
        twin.computeNSteps(10);
        assertEquals(ModelState.of(twin, "all", "links"), ModelState.of(m, "all", "links"));
        assertEquals(1, warnings(err), err);
        assertTrue(err.contains("\"col\"): no such subset"), err);
        PhysicalModel s = scene();
        s.setStrict(true);
        assertThrows(IllegalArgumentException.class,
                () -> MidiController.addMidiController(s, 4, 0.1f, 0.4f, "col", "stiffness"));
    }

    @Test
    void aMassChangeLeavesTheGroundsOfTheSubsetAlone() {
        PhysicalModel a = scene();
        String err2 = forgiving(a, x -> x.changeMassParamOfSubset(3, "all"));
        assertEquals(3.0, a.getMatMass("m1"), 0);
        assertEquals(3.0, a.getMatMass("m2"), 0);
        assertEquals(3.0, a.getMatMass("o"), 0);
        assertEquals(1.0, a.getMatMassAt(0), 0, "the ground keeps its nominal mass 1");
        assertEquals(matModuleType.Ground3D, a.getMatTypeAt(0));
        Vect3D g = a.getMatPosition("gnd");
        a.computeNSteps(100);
        assertEquals(0.0, a.getMatPosition("gnd").dist(g), 0.0, "the ground stays fixed");
        assertEquals(1, warnings(err2), err2);
        assertTrue(err2.contains("changeMassParamOfSubset(\"gnd\"): a Ground3D has no mass parameter"), err2);
        strictThrows(x -> x.changeMassParamOfSubset(3, "all"), "gnd");
    }

    @Test
    void setMatParamsForNameLeavesGroundsAlone() {
        PhysicalModel m = scene();
        m.addGround3D("mfix", new Vect3D(0, 0, -1));
        String err = forgiving(m, x -> x.setMatParamsForName("m", 4)); // m1, m2 and the ground mfix
        assertEquals(4.0, m.getMatMass("m1"), 0);
        assertEquals(4.0, m.getMatMass("m2"), 0);
        assertEquals(1.0, m.getMatMassAt(m.getMatIndex("mfix")), 0);
        assertEquals(1, warnings(err), err);
        assertTrue(err.contains("setMatParamsForName(\"mfix\"): a Ground3D has no mass parameter"), err);
        m.setStrict(true);
        assertThrows(IllegalArgumentException.class, () -> m.setMatParamsForName("m", 5));
        assertEquals(4.0, m.getMatMass("m1"), 0, "strict: nothing changed");
    }

    @Test
    void massParameterOfAGroundIsOneAndSettingItDoesNothing() {
        PhysicalModel m = scene();
        String before = ModelState.of(m, "all", "links");
        String err = forgiving(m, x -> {
            for (int i = 0; i < x.getNumberOfMats(); i++) {
                x.getMatMassAt(i); // the paper's DynamicParameterMods prints every mass
            }
            assertEquals(1.0, x.getMatMassAt(0), 0);
            assertEquals(1.0, x.getMatMassAt(4), 0, "an avatar too");
            x.setMatMassAt(0, 5);
            x.setMatMass("gnd", 5);
            x.setMatMass("h", 5);
        });
        assertEquals(before, ModelState.of(m, "all", "links"));
        assertEquals(1, warnings(err), err);
        assertTrue(err.contains("getMatMassAt(\"gnd\"): a Ground3D has no mass parameter; 1 was returned"), err);
        assertEquals(1.0, m.getMatMassAt(0), 0);
        strictThrows(x -> x.getMatMassAt(0), "gnd");
        strictThrows(x -> x.setMatMassAt(0, 5), "gnd");
        strictThrows(x -> x.setMatMass("h", 5), "h");
    }

    @Test
    void stiffnessOrDampingOfMembersWithoutItAreSkipped() {
        PhysicalModel m = scene();
        String err = forgiving(m, x -> {
            x.changeStiffnessParamOfSubset(0.05, "links"); // d is a Damper3D: no stiffness
            x.changeDampingParamOfSubset(0.004, "links"); // s2 is a Spring3D: no damping
            x.changeStiffnessParamOfSubset(0.02, "all"); // only o is an oscillator
            x.changeParamOfSubset(1f, "links", "colour");
        });
        assertEquals(0.05, m.getLinkStiffness("s1"), 1e-15);
        assertEquals(0.05, m.getLinkStiffness("s2"), 1e-15);
        assertEquals(0.004, m.getLinkDamping("s1"), 1e-15);
        assertEquals(0.004, m.getLinkDamping("d"), 1e-15);
        assertEquals(0.02, m.getMatStiffness("o"), 1e-15);
        assertEquals(2, warnings(err), err); // one for the missing parameters, one for the unknown name
        assertTrue(err.contains("changeStiffnessParamOfSubset(\"d\"): a Damper3D has no stiffness parameter"), err);
        assertTrue(err.contains("\"colour\""), err);
        strictThrows(x -> x.changeStiffnessParamOfSubset(0.05, "links"), "\"d\"");
        strictThrows(x -> x.changeParamOfSubset(1f, "links", "colour"), "colour");
    }

    @Test
    void indexQueriesOfParametersAModuleLacksAnswerZero() {
        PhysicalModel m = scene();
        String before = ModelState.of(m, "all", "links");
        String err = forgiving(m, x -> {
            assertEquals(0, x.getMatStiffnessAt(1), 0);
            assertEquals(0, x.getMatDampingAt(1), 0);
            x.setMatStiffnessAt(1, 0.5);
            x.setMatDampingAt(2, 0.5);
            assertEquals(0, x.getOsc3DDeltaPos(1), 0);
            assertEquals(0, x.getPlaneOrientationAt(0));
            assertEquals(0, x.getPlanePositionAt(0), 0);
        });
        assertEquals(before, ModelState.of(m, "all", "links"));
        assertEquals(1, warnings(err), err);
        assertEquals(7, m.core.lenient.forgivenCount());
        strictThrows(x -> x.getMatStiffnessAt(1), "m1");
        strictThrows(x -> x.setMatDampingAt(2, 0.5), "m2");
        strictThrows(x -> x.getPlanePositionAt(0), "s1");
    }

    @Test
    void hapticCallsOnAMassThatIsNoInputDoNothing() {
        PhysicalModel m = scene();
        String before = ModelState.of(m, "all", "links");
        String err = forgiving(m, x -> {
            x.setHapticPosition("m1", new Vect3D(5, 5, 5));
            Vect3D f = x.getHapticForce("m2");
            assertEquals(0, f.norm(), 0);
        });
        assertEquals(before, ModelState.of(m, "all", "links"));
        assertEquals(1, warnings(err), err);
        strictThrows(x -> x.setHapticPosition("m1", new Vect3D(5, 5, 5)), "m1");
        strictThrows(x -> x.getHapticForce("m2"), "m2");
    }

    @Test
    void subsetsCreatedTwiceOrFedUnknownModulesAreKeptAsTheyAre() {
        PhysicalModel m = scene();
        String err = forgiving(m, x -> {
            x.createMatSubset("all");
            x.createLinkSubset("links");
            x.addMatToSubset("ghost", "all");
            x.addMatToSubset(x.getMatIndex("ghost"), "all");
            x.addLinkToSubset("ghost", "links");
            x.addLinkToSubset(x.getLinkIndex("ghost"), "links");
        });
        assertArrayEquals(new String[] {"gnd", "m1", "m2", "o"}, m.getSubsetMembers("all"));
        assertArrayEquals(new String[] {"s1", "s2", "d"}, m.getSubsetMembers("links"));
        assertEquals(2, warnings(err), err); // one for the duplicate, one for the unknown modules
        strictThrows(x -> x.createMatSubset("all"), "all");
        strictThrows(x -> x.addMatToSubset("ghost", "all"), "ghost");
        strictThrows(x -> x.addLinkToSubset(-1, "links"), "-1");
    }

    @Test
    void indexGettersPastTheEndAnswerTheOriginalsDefaults() {
        PhysicalModel m = scene();
        int nm = m.getNumberOfMats();
        int nl = m.getNumberOfLinks();
        String before = ModelState.of(m, "all", "links");
        String err = forgiving(m, x -> {
            for (int i = 0; i <= nm; i++) { // the paper's off-by-one loop
                x.getMatPosAt(i);
            }
            assertEquals("None", x.getMatNameAt(nm));
            assertEquals(matModuleType.UNDEFINED, x.getMatTypeAt(nm));
            assertEquals(0, x.getMatPosAt(nm).norm(), 0);
            assertEquals(0, x.getMatVelAt(nm).norm(), 0);
            assertEquals(0, x.getMatFrcAt(nm).norm(), 0);
            assertEquals(0, x.getMatDelayedPosAt(nm + 3).norm(), 0);
            assertEquals(0, x.getMatMassAt(nm), 0);
            assertEquals(0, x.getMatStiffnessAt(nm), 0);
            assertEquals(0, x.getMatDampingAt(nm), 0);
            x.setMatStiffnessAt(nm, 1);
            x.setMatDampingAt(nm, 1);
            assertEquals("None", x.getLinkNameAt(nl));
            assertEquals(linkModuleType.UNDEFINED, x.getLinkTypeAt(nl));
            assertEquals(0, x.getLinkPos1At(nl).norm(), 0);
            assertEquals(0, x.getLinkPos2At(nl).norm(), 0);
            assertEquals(-1, x.getLinkMat1IdxAt(nl));
            assertEquals(-1, x.getLinkMat2IdxAt(nl));
            assertEquals("", x.getLinkMat1NameAt(nl));
            assertEquals("", x.getLinkMat2NameAt(nl));
            assertEquals(0, x.getLinkStiffnessAt(nl), 0);
            assertEquals(0, x.getLinkDampingAt(nl), 0);
            assertEquals(0, x.getLinkDistanceAt(nl), 0);
            assertEquals(0, x.getLinkElongationAt(nl), 0);
            assertEquals(0, x.getLinkDRestAt(nl), 0);
            assertEquals(0, x.getPlaneOrientationAt(nl));
            assertEquals(0, x.getPlanePositionAt(nl), 0);
        });
        assertEquals(before, ModelState.of(m, "all", "links"));
        assertEquals(1, warnings(err), err);
        assertTrue(err.contains("getMatPosAt(" + nm + "): mass index out of range 0.." + (nm - 1)), err);
        // a negative index crashed the original: it stays an error, and setters past the end too
        assertThrows(IllegalArgumentException.class, () -> m.getMatPosAt(-1));
        assertThrows(IllegalArgumentException.class, () -> m.setMatMassAt(nm, 2));
        assertThrows(IllegalArgumentException.class, () -> m.setLinkStiffnessAt(nl, 2));
        strictThrows(x -> x.getMatNameAt(x.getNumberOfMats()), "out of range");
        strictThrows(x -> x.getLinkStiffnessAt(x.getNumberOfLinks()), "out of range");
    }

    @Test
    void getParamValueOfSubsetAnswersAsTheOriginal() {
        PhysicalModel m = scene();
        m.createLinkSubset("empty");
        String err = forgiving(m, x -> {
            assertEquals(-1, x.getParamValueOfSubset("empty", "stiffness"), 0);
            assertEquals(1, x.getParamValueOfSubset("all", "mass"), 0, "the first member is the ground");
            assertEquals(-1, x.getParamValueOfSubset("all", "stiffness"), 0);
            assertEquals(0, x.getParamValueOfSubset("links", "dist") - 1, 0, "s1's rest length");
            assertEquals(-1, x.getParamValueOfSubset("links", "mass"), 0);
        });
        assertEquals(2, warnings(err), err); // an empty subset; parameters the first member lacks
        strictThrows(x -> x.getParamValueOfSubset("all", "mass"), "gnd");
    }

    @Test
    void twoTopoGeneratorsFillingOneSubsetWarnNothing() {
        PhysicalModel m = new PhysicalModel(1000, 50);
        String err = forgiving(m, x -> {
            for (String prefix : new String[] {"a", "b"}) {
                TopoGenerator q = new TopoGenerator(x, prefix, "l");
                q.setDim(2, 1, 1, 1);
                q.setParams(1, 0.01, 0.001);
                q.setGeometry(1, 1);
                q.setTranslation(0, "a".equals(prefix) ? 0 : 5, 0);
                q.setMatSubsetName("shared");
                q.setLinkSubsetName("sharedLinks");
                q.generate();
            }
        });
        assertEquals("", err);
        assertEquals(4, m.getSubsetMembers("shared").length);
        assertEquals(2, m.getSubsetMembers("sharedLinks").length);
        assertEquals(0, m.core.lenient.forgivenCount());
    }

    @Test
    void aRampOnARealtimeModelSkipsTheGroundsToo() throws Exception {
        PhysicalModel m = scene();
        m.addParamController("ramp", "all", "mass", 0.01f);
        String init = forgiving(m, x -> x.getParamController("ramp").init(1)); // warns here, on this thread
        assertEquals(1, warnings(init), init);
        m.beginRealtimeStepping();
        Thread owner = new Thread(() -> m.computeNSteps(1));
        owner.start();
        owner.join(10_000);
        String err = forgiving(m, x -> x.getParamController("ramp").triggerRamp(2));
        Thread stepper = new Thread(() -> m.computeNSteps(50));
        stepper.start();
        stepper.join(10_000);
        m.endRealtimeStepping();
        assertEquals(2.0, m.getMatMass("m1"), 1e-6);
        assertEquals(2.0, m.getMatMass("o"), 1e-6);
        assertEquals(matModuleType.Ground3D, m.getMatTypeAt(0));
        assertEquals(0, warnings(err), "already warned: " + err);
        assertTrue(m.core.lenient.forgivenCount() >= 2, "the ground was skipped at init and at the trigger");
    }
}
