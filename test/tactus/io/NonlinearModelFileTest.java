package tactus.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringReader;
import java.io.StringWriter;
import org.junit.jupiter.api.Test;
import tactus.Interaction;
import tactus.PhysicalModel;
import tactus.Vect3D;
import tactus.linkModuleType;
import tactus.paramSystem;

/** Every nonlinear kind saves to a model file with its extra parameters by name, and loads back the same. */
class NonlinearModelFileTest {
    static PhysicalModel everyNonlinearKind() {
        PhysicalModel m = new PhysicalModel(1000, paramSystem.REAL_UNITS);
        m.addMass3D("a", 1, new Vect3D(0, 0, 0), new Vect3D());
        m.addMass3D("b", 1, new Vect3D(0.5, 0, 0), new Vect3D());
        m.addMass1D("c", 1, new Vect3D(0, 0, 0), new Vect3D());
        m.addGround1D("g", new Vect3D(0, 0, 1));
        m.addQuadraticSpringDamper3D("q3", 0.4, 100, 0.1, 2000, "a", "b");
        m.addQuadraticSpringDamper1D("q1", 0.1, 110, 0.2, 2100, "c", "g");
        m.addCubicSpringDamper3D("c3", 0.4, 120, 0.3, 3e4, "a", "b");
        m.addCubicSpringDamper1D("c1", 0.1, 130, 0.4, 3.1e4, "c", "g");
        m.addClippedSpringDamper3D("k3", 0.4, 140, 0.5, 5e4, 900, "a", "b");
        m.addClippedSpringDamper1D("k1", 0.1, 150, 0.6, 5.1e4, 910, "c", "g");
        m.addPluck3D("p3", 0.4, 160, 0.7, 0.05, "a", "b");
        m.addPluck1D("p1", 0.1, 170, 0.8, 0.06, "c", "g");
        m.addBow3D("b3", 1.5, 0.3, 1, "a", "b");
        m.addBow1D("b1", 1.6, 0.4, 0, "c", "g");
        m.addClippedContact3D("x3", 0.6, 180, 0.9, 6e4, 920, "a", "b");
        m.addClippedContact1D("x1", 0.2, 190, 1.0, 6.1e4, 930, "c", "g");
        return m;
    }

    @Test
    void everyKindSavesAndLoadsWithItsExtraParameters() {
        PhysicalModel m = everyNonlinearKind();
        StringWriter out = new StringWriter();
        ModelXml.write(m, out, "model");
        String xml = out.toString();
        assertTrue(xml.contains("Kmax=") && xml.contains("profile=") && xml.contains("scale="), xml);
        PhysicalModel back = new PhysicalModel(1000, paramSystem.REAL_UNITS);
        ModelXml.read(new StringReader(xml), "memory", back);
        assertEquals(m.getNumberOfLinks(), back.getNumberOfLinks());
        int nonlinear = 0;
        for (int i = 0; i < m.getNumberOfLinks(); i++) {
            linkModuleType t = m.getLinkTypeAt(i);
            assertEquals(t, back.getLinkTypeAt(i));
            String name = m.getLinkNameAt(i);
            assertEquals(name, back.getLinkNameAt(i));
            assertEquals(m.getLinkStiffnessAt(i), back.getLinkStiffnessAt(i), 1e-9, name);
            assertEquals(m.getLinkDampingAt(i), back.getLinkDampingAt(i), 1e-12, name);
            assertEquals(m.getLinkDRestAt(i), back.getLinkDRestAt(i), 1e-15, name);
            Interaction a = m.getInteractionAt(i), b = back.getInteractionAt(i);
            for (String p : t.extraParameterNames()) {
                assertEquals(a.getExtraParameter(p), b.getExtraParameter(p),
                        1e-12 * Math.abs(a.getExtraParameter(p)), name + "." + p);
            }
            nonlinear += t.isNonlinear() ? 1 : 0;
        }
        assertEquals(12, nonlinear);
    }
}
