package tactus;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.io.StringReader;
import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;
import tactus.io.ModelXml;

/**
 * 1D masses feel gravity in Tactus and not in the paper's engine: the physics stays, and a note is printed once per
 * model when gravity first pulls along z in a model with a Mass1D or Osc1D (gravity set, its direction set, or a 1D
 * mass added), never otherwise.
 */
class GravityNoteTest {
    static final String NOTE = "1D masses feel gravity in Tactus";

    static String stderrOf(Runnable r) {
        PrintStream err = System.err;
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        System.setErr(new PrintStream(out, true));
        try {
            r.run();
        } finally {
            System.setErr(err);
        }
        return new String(out.toByteArray(), StandardCharsets.UTF_8);
    }

    static int notes(String printed) {
        return printed.split(NOTE, -1).length - 1;
    }

    static Vect3D v(double x, double y, double z) {
        return new Vect3D(x, y, z);
    }

    @Test
    void turningGravityOnInAModelWithA1DMassPrintsTheNoteOnce() {
        PhysicalModel m = new PhysicalModel(1000, 50);
        String printed = stderrOf(() -> {
            m.addGround1D("g", v(0, 0, 0));
            m.addMass1D("plate", 1, v(0, 0, 1), v(0, 0, 0));
            m.addSpringDamper1D("s", 1, 0.01, 0.001, "plate", "g");
            m.init();
            m.setGravity(0);   // off: nothing to say
        });
        assertEquals(0, notes(printed), printed);
        printed = stderrOf(() -> {
            m.setGravity(0.001);
            m.setGravity(0.002);
            m.addMass1D("plate2", 1, v(1, 0, 1), v(0, 0, 0));
            m.setGravity(0);
            m.setGravity(0.001);
            m.computeNSteps(10);
        });
        assertEquals(1, notes(printed), printed);
        assertTrue(printed.contains("\"plate\"") && printed.contains("keep gravity at 0")
                && printed.contains("once per model"), printed);
        Vect3D before = m.getMatPosition("plate2");
        m.computeNSteps(200);
        assertTrue(m.getMatPosition("plate2").z < before.z, "the physics stays: the 1D mass falls along z");
    }

    @Test
    void adding1DMassesToAModelWithGravityPrintsItOnceAndOtherMassesNever() {
        PhysicalModel m = new PhysicalModel(1000, 50);
        String printed = stderrOf(() -> {
            m.setGravity(0.001);
            m.addMass3D("ball", 1, v(0, 0, 0), v(0, 0, 0));
            m.addMass2DPlane("puck", 1, v(1, 0, 0), v(0, 0, 0));
            m.addOsc3D("o3", 1, 0.01, 0.001, v(2, 0, 0), v(0, 0, 0));
        });
        assertEquals(0, notes(printed), printed);
        printed = stderrOf(() -> {
            m.addOsc1D("bar", 1, 0.01, 0.001, v(3, 0, 0), v(0, 0, 0));
            m.addMass1D("bead", 1, v(4, 0, 0), v(0, 0, 0));
        });
        assertEquals(1, notes(printed), printed);
        assertTrue(printed.contains("\"bar\""), printed);
    }

    @Test
    void gravityWithoutAZComponentNeedsNoNoteUntilItsDirectionGetsOne() {
        PhysicalModel m = new PhysicalModel(1000, 50);
        String printed = stderrOf(() -> {
            m.setGravityDirection(v(1, 0, 0));
            m.setGravity(0.001);
            m.addMass1D("bead", 1, v(0, 0, 0), v(0, 0, 0));
        });
        assertEquals(0, notes(printed), printed);
        printed = stderrOf(() -> m.setGravityDirection(v(1, 0, 1)));
        assertEquals(1, notes(printed), printed);
    }

    @Test
    void aLoadedFileWith1DMassesAndGravityPrintsItOnce() {
        PhysicalModel source = new PhysicalModel(1000, 50);
        stderrOf(() -> {
            source.setGravity(0.001);
            source.addGround1D("g", v(0, 0, 0));
            source.addMass1D("plate", 1, v(0, 0, 1), v(0, 0, 0));
            source.addSpringDamper1D("s", 1, 0.01, 0.001, "plate", "g");
        });
        java.io.StringWriter w = new java.io.StringWriter();
        ModelXml.write(source, w, "plate");
        PhysicalModel m = new PhysicalModel(1000, 50);
        String printed = stderrOf(() -> ModelXml.read(new StringReader(w.toString()), "plate", m));
        assertEquals(1, notes(printed), "the file is built into a scratch model first; one note all the same:\n"
                + printed);
        assertEquals(0.001, m.getGravity(), 0.0);
    }
}
