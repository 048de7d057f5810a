package tactus.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import processing.data.XML;
import tactus.PhysicalModel;
import tactus.PlaneContact3D;
import tactus.Vect3D;

/**
 * A file saved by Tactus, read the way the paper's engine's loader reads it: with Processing's own
 * {@code processing.data.XML}, taking the section elements by name, stepping over the children two by
 * two (it expects a whitespace text node before each element) and reading attributes by name. The
 * modules it finds, rebuilt with the calls that loader makes, must equal the saved model.
 */
class PaperLoaderCompatTest {
    /** Every module type the paper's loader knows (it has no Attractor3D, PosInput3D or HapticInput3D loading). */
    static PhysicalModel paperKinds() {
        PhysicalModel m = new PhysicalModel(1050, 50);
        m.setGravity(0.001);
        m.setFriction(1e-4);
        m.addGround3D("g3", new Vect3D(0, 0, 0));
        m.addGround1D("g1", new Vect3D(0, 5, 0));
        m.addMass3D("a", 1.3, new Vect3D(0.5, 0, 2), new Vect3D(1, 2, 3));
        m.addMass3D("b", 0.7, new Vect3D(3, 1, -2.0 / 3), new Vect3D(-4, 0, 0.25));
        m.addMass2DPlane("p", 1.1, new Vect3D(-3, 0.1, 1), new Vect3D(0.5, -0.5, 0));
        m.addMass1D("l", 2.0, new Vect3D(0, 5, 1.0 / 3), new Vect3D(0, 0, 7));
        m.addOsc3D("o3", 1.0, 0.02, 0.001, new Vect3D(0.1, 0.2, 0.3), new Vect3D(0, 0, 1));
        m.addSpring3D("s", 1.5, 0.01, "a", "g3");
        m.addDamper3D("z", 0.001, "a", "b");
        m.addSpringDamper3D("sd", 2.0, 0.01, 0.002, "b", "p");
        m.addSpringDamper1D("sd1", 0.5, 0.02, 0.001, "l", "g1");
        m.addRope3D("r", 3.0, 0.01, 0.001, "o3", "b");
        m.addContact3D("c", 1.0, 0.05, 0.001, "p", "a");
        m.addBubble3D("bu", 6.0, 0.01, 0.001, "b", "g3");
        m.addPlaneContact("pl", 0.1, 0.05, 0.001, 2, -3, "p");
        return m;
    }

    @Test
    void aSavedModelReadsBackThroughThePapersLoaderWalk(@TempDir Path dir) throws Exception {
        PhysicalModel original = paperKinds();
        File file = dir.resolve("Compat.xml").toFile();
        ModelXml.save(original, file);

        XML xml = new XML(file);
        XML link = xml.getChild("Link");
        XML mat = xml.getChild("MAT");
        XML glo = xml.getChild("global");
        assertNotNull(link);
        assertNotNull(mat);
        assertNotNull(glo);

        PhysicalModel rebuilt = new PhysicalModel(1050, 50);
        rebuilt.setGravity(glo.getChild("gravity").getDouble("gravity"));
        rebuilt.setFriction(glo.getChild("friction").getDouble("friction"));
        XML v = glo.getChild("vector");
        rebuilt.setGravityDirection(new Vect3D(v.getFloat("pos.x"), v.getFloat("pos.y"), v.getFloat("pos.z")));

        for (XML e : walk(mat)) {
            Vect3D pos = new Vect3D(e.getDouble("initPos.x"), e.getDouble("initPos.y"), e.getDouble("initPos.z"));
            Vect3D vel = new Vect3D(e.getDouble("initVel.x"), e.getDouble("initVel.y"), e.getDouble("initVel.z"));
            String name = e.getString("name");
            switch (e.getParent().getName()) {
                case "Ground3D":
                    rebuilt.addGround3D(name, pos);
                    break;
                case "Ground1D":
                    rebuilt.addGround1D(name, pos);
                    break;
                case "Mass1D":
                    rebuilt.addMass1D(name, e.getDouble("mass"), pos, vel);
                    break;
                case "Mass2DPlane":
                    rebuilt.addMass2DPlane(name, e.getDouble("mass"), pos, vel);
                    break;
                case "Mass3D":
                    rebuilt.addMass3D(name, e.getDouble("mass"), pos, vel);
                    break;
                case "Osc3D":
                    rebuilt.addOsc3D(name, e.getDouble("mass"), e.getDouble("stiffness"), e.getDouble("damping"), pos, vel);
                    break;
                default:
                    throw new AssertionError("unexpected mass group " + e.getParent().getName());
            }
        }
        for (XML e : walk(link)) {
            String n = e.getString("name"), m1 = e.getString("m1"), m2 = e.getString("m2");
            double d = e.getDouble("drest"), k = e.getDouble("stiffness"), z = e.getDouble("damping");
            switch (e.getParent().getName()) {
                case "Bubble3D":
                    rebuilt.addBubble3D(n, d, k, z, m1, m2);
                    break;
                case "Contact3D":
                    rebuilt.addContact3D(n, d, k, z, m1, m2);
                    break;
                case "Rope3D":
                    rebuilt.addRope3D(n, d, k, z, m1, m2);
                    break;
                case "SpringDamper1D":
                    rebuilt.addSpringDamper1D(n, d, k, z, m1, m2);
                    break;
                case "SpringDamper3D":
                    rebuilt.addSpringDamper3D(n, d, k, z, m1, m2);
                    break;
                case "Spring3D":
                    rebuilt.addSpring3D(n, d, k, m1, m2);
                    break;
                case "Damper3D":
                    rebuilt.addDamper3D(n, z, m1, m2);
                    break;
                case "PlaneContact3D":
                    rebuilt.addPlaneContact(n, d, k, z, e.getInt("orientation"), e.getDouble("position"), m1);
                    break;
                default:
                    throw new AssertionError("unexpected link group " + e.getParent().getName());
            }
        }

        assertEquals(original.getNumberOfMats(), rebuilt.getNumberOfMats());
        assertEquals(original.getNumberOfLinks(), rebuilt.getNumberOfLinks());
        assertEquals(original.getGravity(), rebuilt.getGravity(), 0.0);
        assertEquals(original.getFriction(), rebuilt.getFriction(), 0.0);
        for (int i = 0; i < original.getNumberOfMats(); i++) {
            String n = original.getMatNameAt(i);
            int j = rebuilt.getMatIndex(n);
            assertTrue(j >= 0, n);
            assertEquals(String.valueOf(original.getMatTypeAt(i)), String.valueOf(rebuilt.getMatTypeAt(j)), n);
            assertEquals(original.getMatPosAt(i).toString(), rebuilt.getMatPosAt(j).toString(), n);
            Vect3D va = original.getMatVelAt(i), vb = rebuilt.getMatVelAt(j);
            assertTrue(va.dist(vb) <= 1e-9, n + ": " + va + " vs " + vb);
        }
        for (int i = 0; i < original.getNumberOfLinks(); i++) {
            String n = original.getLinkNameAt(i);
            assertEquals(String.valueOf(original.getLinkTypeAt(i)), String.valueOf(rebuilt.getLinkTypeAt(rebuilt.getLinkIndex(n))), n);
            assertEquals(String.join(",", original.getLinkMatNames(n)), String.join(",", rebuilt.getLinkMatNames(n)), n);
            assertEquals(original.getLinkStiffness(n), rebuilt.getLinkStiffness(n), 0.0, n);
            assertEquals(original.getLinkDamping(n), rebuilt.getLinkDamping(n), 0.0, n);
            assertEquals(original.getLinkDRest(n), rebuilt.getLinkDRest(n), 0.0, n);
        }
        PlaneContact3D pl = (PlaneContact3D) rebuilt.getInteraction("pl");
        assertEquals(2, pl.getOrientation());
        assertEquals(-3, pl.getPlanePosition(), 0.0);
    }

    /**
     * The paper's loader walk: for children 1, 3, 5, ... of a section (skipping the whitespace text
     * before each), and for the children 1, 3, 5, ... of each group that has children.
     */
    static List<XML> walk(XML section) {
        List<XML> out = new ArrayList<>();
        XML[] groups = section.getChildren();
        for (int i = 1; i < groups.length; i += 2) {
            XML type = section.getChild(i);
            assertTrue(isElement(type), "child " + i + " of <" + section.getName() + "> must be an element");
            assertTrue(!isElement(section.getChild(i - 1)), "child " + (i - 1) + " of <" + section.getName() + "> must be whitespace");
            if (type.hasChildren()) {
                XML[] members = type.getChildren();
                for (int p = 1; p < members.length; p += 2) {
                    XML e = type.getChild(p);
                    assertTrue(isElement(e), "child " + p + " of <" + type.getName() + "> must be an element");
                    out.add(e);
                }
            }
        }
        return out;
    }

    static boolean isElement(XML x) {
        return x != null && x.getName() != null && !x.getName().startsWith("#");
    }
}
