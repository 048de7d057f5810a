package tactus.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static tactus.render.Canvas.WHITE;
import static tactus.render.Canvas.hex;
import static tactus.render.Canvas.rgb;

import org.junit.jupiter.api.Test;

import processing.core.PApplet;
import processing.core.PGraphics;
import tactus.ModelRenderer;
import tactus.ModelSnapshot;
import tactus.PhysicalModel;
import tactus.Vect3D;
import tactus.linkModuleType;
import tactus.matModuleType;

/**
 * Pixel tests of the generic renderer in an off-screen JAVA2D target (headless): where masses and links land,
 * in which colour, and what the view settings do to them. Expected positions and colours come from the documented
 * mapping (drawing point = scale × zoom ⊙ model point, radius = scale × (size + scaling × mass), colour blend
 * linear in strain), never from a previous run.
 */
class ModelDrawerTest {
    private static final int MASS3D = rgb(180, 100, 0);
    private static final int GREEN = rgb(0, 220, 130);    // Ground3D, Mass2DPlane, Osc3D
    private static final int AVATAR = rgb(255, 50, 50);
    private static final int GREY = rgb(125, 125, 125);   // the types the paper's engine could not style
    private static final int SPRING = rgb(30, 100, 100);
    private static final int SPRING_DAMPER = rgb(30, 250, 250);

    private static Vect3D v(double x, double y, double z) {
        return new Vect3D(x, y, z);
    }

    private static ModelRenderer rendererFor(PGraphics g) {
        PApplet app = new PApplet();
        app.g = g;
        return new ModelRenderer(app);
    }

    /** Draws the model once with the renderer into a fresh centred 240 × 240 canvas. */
    private static Canvas draw(PhysicalModel m, ModelRenderer r) {
        Canvas c = new Canvas(240, 240);
        PGraphics g = c.begin();
        r.renderModel(m, g);
        c.end();
        return c;
    }

    private static void assertPixel(int expected, Canvas c, double x, double y, String what) {
        assertEquals(hex(expected), hex(c.at(x, y)), what + " at (" + x + ", " + y + ")");
    }

    @Test
    void everyMassTypeIsADiscOfItsTypeColourAtItsXyPosition() {
        PhysicalModel m = new PhysicalModel(1000, 50);
        m.addMass3D("mass", 1, v(-80, -80, 7), v(0, 0, 0));
        m.addGround3D("ground", v(0, -80, -3));
        m.addMass2DPlane("plane", 1, v(80, -80, 0), v(0, 0, 0));
        m.addOsc3D("osc", 1, 0.01, 0.001, v(-80, 0, 0), v(0, 0, 0));
        m.addHapticInput3D("avatar", v(0, 0, 50), 1);
        m.addMass1D("m1d", 1, v(80, 0, 0), v(0, 0, 0));
        m.addGround1D("g1d", v(-80, 80, 0));
        m.addOsc1D("o1d", 1, 0.01, 0.001, v(0, 80, 0), v(0, 0, 0));
        m.addPosInput3D("driver", v(80, 80, 0), 1);
        m.init();
        Canvas c = draw(m, new ModelRenderer(new PApplet()));
        int[] colours = {MASS3D, GREEN, GREEN, GREEN, AVATAR, GREY, GREY, GREY, GREY};
        double[] radius = {10, 10, 10, 10, 10, 5, 5, 5, 5};
        ModelSnapshot s = m.getSnapshot();
        for (int i = 0; i < colours.length; i++) {
            double x = s.x(i);
            double y = s.y(i);
            String name = m.getMatNameAt(i);
            assertPixel(colours[i], c, x, y, name + " centre");
            assertPixel(colours[i], c, x + radius[i] - 1.5, y, name + " inside its radius");
            assertPixel(colours[i], c, x, y - radius[i] + 1.5, name + " inside its radius");
            assertPixel(WHITE, c, x + radius[i] + 1.5, y, name + " outside its radius");
            assertPixel(WHITE, c, x, y + radius[i] + 1.5, name + " outside its radius");
        }
    }
}
