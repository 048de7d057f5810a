package tactus;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import processing.core.PVector;

/** Vect3D arithmetic and the PVector bridge used by sketches. */
class Vect3DTest {
    static void assertVect(double x, double y, double z, Vect3D v) {
        assertEquals(x, v.x, 0.0, "x");
        assertEquals(y, v.y, 0.0, "y");
        assertEquals(z, v.z, 0.0, "z");
    }

    @Test
    void constructionAndCopies() {
        assertVect(0, 0, 0, new Vect3D());
        Vect3D a = new Vect3D(1, -2, 3.5);
        assertVect(1, -2, 3.5, a);
        Vect3D b = new Vect3D(a);
        assertNotSame(a, b);
        a.x = 10;
        assertVect(1, -2, 3.5, b);
        assertSame(b, b.set(4, 5, 6));
        assertVect(4, 5, 6, b);
        assertSame(b, b.set(a));
        assertVect(10, -2, 3.5, b);
    }

    @Test
    void arithmeticMutatesAndChains() {
        Vect3D a = new Vect3D(1, 2, 3);
        Vect3D r = a.add(new Vect3D(0.5, -1, 2)).mult(2).sub(new Vect3D(1, 1, 1)).div(4);
        assertSame(a, r);
        assertVect(0.5, 0.25, 2.25, a);
        Vect3D b = new Vect3D(1, 1, 1);
        b.add(b);
        assertVect(2, 2, 2, b);
    }

    @Test
    void normsAndDistances() {
        Vect3D a = new Vect3D(3, 4, 12);
        assertEquals(13, a.norm(), 0.0);
        assertEquals(169, a.sqNorm(), 0.0);
        Vect3D p = new Vect3D(1, 1, 1);
        Vect3D q = new Vect3D(3, 4, 7);
        assertEquals(7, p.dist(q), 0.0);
        assertEquals(7, q.dist(p), 0.0);
        assertEquals(49, p.sqDist(q), 0.0);
        assertEquals(0, p.dist(new Vect3D(p)), 0.0);
    }

    @Test
    void finiteness() {
        assertTrue(new Vect3D(1, 2, 3).isFinite());
        assertFalse(new Vect3D(Double.NaN, 0, 0).isFinite());
        assertFalse(new Vect3D(0, Double.POSITIVE_INFINITY, 0).isFinite());
        assertFalse(new Vect3D(0, 0, Double.NEGATIVE_INFINITY).isFinite());
        assertTrue(new Vect3D(Double.MAX_VALUE, -Double.MAX_VALUE, Double.MIN_VALUE).isFinite());
    }

    @Test
    void toStringShowsTheComponents() {
        assertEquals("(1.0, -2.5, 3.0E-7)", new Vect3D(1, -2.5, 3e-7).toString());
    }

    @Test
    void toPVectorHasFloatComponents() {
        Vect3D a = new Vect3D(0.1, 1.0 / 3, -1e10);
        PVector p = a.toPVector();
        assertEquals((float) 0.1, p.x, 0.0f);
        assertEquals((float) (1.0 / 3), p.y, 0.0f);
        assertEquals((float) -1e10, p.z, 0.0f);
        p.x = 5;
        assertEquals(0.1, a.x, 0.0, "the PVector is a copy");
    }

    @Test
    void modelReturnsPositionsAsFloatPVectorsAndCopies() {
        PhysicalModel m = new PhysicalModel(300, 60);
        m.addMass3D("a", 1, new Vect3D(0.1, 0.2, 1.0 / 3), new Vect3D(0, 0, 1));
        m.init();
        m.computeNSteps(7);
        Vect3D pos = m.getMatPosition("a");
        PVector pv = m.getMatPVector("a");
        assertEquals((float) pos.x, pv.x, 0.0f);
        assertEquals((float) pos.y, pv.y, 0.0f);
        assertEquals((float) pos.z, pv.z, 0.0f);
        assertEquals(PVector.class, pv.getClass());
        assertEquals(float.class, fieldType("x"));
        // returned vectors are copies: changing them does not move the mass
        pos.x = 100;
        pv.y = 100;
        assertEquals(0.1, m.getMatPosition("a").x, 0.0);
        assertEquals(0.2, m.getMatPosition("a").y, 0.0);
        // the allocation-free variant writes into the given vector
        Vect3D out = new Vect3D();
        assertSame(out, m.getMatPosition("a", out));
        assertEquals(m.getMatPosition("a").z, out.z, 0.0);
        // the force vector is a float PVector as well
        PVector f = m.getMatForcePVector("a");
        assertEquals(0f, f.x, 0f);
    }

    private static Class<?> fieldType(String name) {
        try {
            return PVector.class.getField(name).getType();
        } catch (NoSuchFieldException e) {
            throw new AssertionError(e);
        }
    }
}
