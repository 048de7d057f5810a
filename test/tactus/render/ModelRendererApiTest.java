package tactus.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.reflect.Constructor;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;

import org.junit.jupiter.api.Test;

import processing.core.PApplet;
import processing.core.PConstants;
import tactus.ModelRenderer;
import tactus.PhysicalModel;
import tactus.linkModuleType;
import tactus.matModuleType;

/** The paper-compatible surface of {@link ModelRenderer}: names, argument and return types, defaults, checks. */
class ModelRendererApiTest {

    private static void assertMethod(Class<?> returns, String name, Class<?>... args) throws Exception {
        Method m = ModelRenderer.class.getMethod(name, args);
        assertTrue(Modifier.isPublic(m.getModifiers()), name);
        assertEquals(returns, m.getReturnType(), name + " returns");
    }

    @Test
    void theSignaturesAreThePaperEngines() throws Exception {
        assertTrue(Modifier.isPublic(ModelRenderer.class.getModifiers()));
        assertTrue(PConstants.class.isAssignableFrom(ModelRenderer.class));
        Constructor<ModelRenderer> c = ModelRenderer.class.getConstructor(PApplet.class);
        assertTrue(Modifier.isPublic(c.getModifiers()));
        Class<?> i = int.class;
        Class<?> f = float.class;
        assertMethod(boolean.class, "setColor", matModuleType.class, i, i, i);
        assertMethod(boolean.class, "setSize", matModuleType.class, f);
        assertMethod(boolean.class, "setScaling", matModuleType.class, f);
        assertMethod(void.class, "setZoomVector", f, f, f);
        assertMethod(boolean.class, "setSize", linkModuleType.class, i);
        assertMethod(boolean.class, "setColor", linkModuleType.class, i, i, i, i);
        assertMethod(boolean.class, "setStrainGradient", linkModuleType.class, boolean.class, f);
        assertMethod(boolean.class, "setStrainColor", linkModuleType.class, i, i, i, i);
        assertMethod(void.class, "setScale", f);
        assertMethod(float.class, "getScale");
        assertMethod(void.class, "displayMats", boolean.class);
        assertMethod(void.class, "renderModel", PhysicalModel.class);
    }

    @Test
    void everyRealTypeCanBeStyledAndUndefinedCannot() {
        ModelRenderer r = new ModelRenderer(new PApplet());
        for (matModuleType t : matModuleType.values()) {
            boolean real = t != matModuleType.UNDEFINED;
            assertEquals(real, r.setColor(t, 1, 2, 3), t.name());
            assertEquals(real, r.setSize(t, 4), t.name());
            assertEquals(real, r.setScaling(t, 0.5f), t.name());
            if (real) {
                MassStyle s = r.getDrawer().style().mass(t);
                assertEquals(0xFF010203, s.argb(), t.name());
                assertEquals(4 + 0.5f * 6, s.radius(6), 1e-6, t.name());
            }
        }
        for (linkModuleType t : linkModuleType.values()) {
            boolean real = t != linkModuleType.UNDEFINED;
            assertEquals(real, r.setColor(t, 1, 2, 3, 4), t.name());
            assertEquals(real, r.setSize(t, 5), t.name());
            assertEquals(real, r.setStrainGradient(t, true, 3), t.name());
            assertEquals(real, r.setStrainColor(t, 6, 7, 8, 9), t.name());
            if (real) {
                LinkStyle s = r.getDrawer().style().link(t);
                assertEquals(0x04010203, s.argb(), t.name());
                assertEquals(0x09060708, s.strainArgb(), t.name());
                assertEquals(5f, s.getWeight(), t.name());
                assertTrue(s.hasStrainGradient());
                assertEquals(3f, s.getStrainMax());
            }
        }
    }

    @Test
    void theDefaultsAreThePaperEngines() {
        RenderStyle s = new RenderStyle();
        assertEquals(0xFFB46400, s.mass(matModuleType.Mass3D).argb());
        assertEquals(10f, s.mass(matModuleType.Mass3D).getSize());
        assertEquals(0f, s.mass(matModuleType.Mass3D).getScaling());
        for (matModuleType t : new matModuleType[] {matModuleType.Ground3D, matModuleType.Mass2DPlane,
                matModuleType.Osc3D}) {
            assertEquals(0xFF00DC82, s.mass(t).argb(), t.name());
            assertEquals(10f, s.mass(t).getSize(), t.name());
        }
        assertEquals(0xFFFF3232, s.mass(matModuleType.HapticInput3D).argb());
        for (matModuleType t : new matModuleType[] {matModuleType.Mass1D, matModuleType.Ground1D,
                matModuleType.Osc1D, matModuleType.Mass3DSimple, matModuleType.PosInput3D}) {
            assertEquals(0xFF7D7D7D, s.mass(t).argb(), t.name());
            assertEquals(5f, s.mass(t).getSize(), t.name());
        }
        assertEquals(0xFF1E6464, s.link(linkModuleType.Spring3D).argb());
        assertEquals(0xFF1E6464, s.link(linkModuleType.Damper3D).argb());
        assertEquals(0xFF1EFAFA, s.link(linkModuleType.SpringDamper3D).argb());
        assertEquals(0xFF32FFFA, s.link(linkModuleType.SpringDamper1D).argb());
        assertEquals(0xFF00FF64, s.link(linkModuleType.Rope3D).argb());
        for (linkModuleType t : new linkModuleType[] {linkModuleType.Contact3D, linkModuleType.Bubble3D,
                linkModuleType.PlaneContact3D, linkModuleType.Attractor3D}) {
            assertFalse(s.link(t).isVisible(), t.name() + " hidden");
        }
        for (linkModuleType t : linkModuleType.values()) {
            assertEquals(2f, s.link(t).getWeight(), t.name());
            assertFalse(s.link(t).hasStrainGradient(), t.name());
            assertEquals(2f, s.link(t).getStrainMax(), t.name());
            assertEquals(0, s.link(t).strainArgb(), t.name());
        }
        ModelRenderer r = new ModelRenderer(new PApplet());
        assertEquals(1f, r.getScale());
        assertTrue(r.getDrawer().getShowMasses());
        assertEquals(1f, r.getDrawer().getZoomX());
        r.displayMats(false);
        assertFalse(r.getDrawer().getShowMasses());
    }

    @Test
    void badArgumentsAreRejectedWithTheirValueAndLeaveTheStyleUnchanged() {
        ModelRenderer r = new ModelRenderer(new PApplet());
        MassStyle mass = r.getDrawer().style().mass(matModuleType.Mass3D);
        int colour = mass.argb();
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> r.setColor(matModuleType.Mass3D, 10, 256, 0));
        assertTrue(e.getMessage().contains("green") && e.getMessage().contains("256"), e.getMessage());
        assertEquals(colour, mass.argb());
        e = assertThrows(IllegalArgumentException.class, () -> r.setSize(matModuleType.Mass3D, -1));
        assertTrue(e.getMessage().contains("-1"), e.getMessage());
        assertEquals(10f, mass.getSize());
        assertThrows(IllegalArgumentException.class, () -> r.setSize(matModuleType.Mass3D, Float.NaN));
        assertThrows(IllegalArgumentException.class, () -> r.setScaling(matModuleType.Mass3D, Float.POSITIVE_INFINITY));
        assertThrows(IllegalArgumentException.class, () -> r.setSize(linkModuleType.Spring3D, -2));
        e = assertThrows(IllegalArgumentException.class,
                () -> r.setStrainGradient(linkModuleType.Spring3D, true, 0));
        assertTrue(e.getMessage().contains("max"), e.getMessage());
        assertFalse(r.getDrawer().style().link(linkModuleType.Spring3D).hasStrainGradient());
        assertThrows(IllegalArgumentException.class, () -> r.setStrainColor(linkModuleType.Spring3D, 0, 0, -1, 0));
        assertThrows(IllegalArgumentException.class, () -> r.setScale(0));
        assertThrows(IllegalArgumentException.class, () -> r.setZoomVector(1, Float.NaN, 1));
        assertEquals(1f, r.getScale());
        assertThrows(IllegalArgumentException.class, () -> r.setColor((matModuleType) null, 0, 0, 0));
        assertThrows(IllegalArgumentException.class, () -> r.renderModel(null));
        assertThrows(IllegalArgumentException.class, () -> new ModelRenderer(null));
    }
}
