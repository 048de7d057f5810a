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

    @Test
    void scalingGrowsTheRadiusWithInertia() {
        PhysicalModel m = new PhysicalModel(1000, 50);
        m.addMass3D("light", 1, v(-50, 0, 0), v(0, 0, 0));
        m.addMass3D("heavy", 4, v(50, 0, 0), v(0, 0, 0));
        m.init();
        ModelRenderer r = new ModelRenderer(new PApplet());
        assertTrue(r.setSize(matModuleType.Mass3D, 6));
        assertTrue(r.setScaling(matModuleType.Mass3D, 5));
        Canvas c = draw(m, r);
        // radius = 6 + 5 * mass: 11 for the light one, 26 for the heavy one
        assertPixel(MASS3D, c, -50 + 9.5, 0, "light, inside 11");
        assertPixel(WHITE, c, -50 + 12.5, 0, "light, outside 11");
        assertPixel(MASS3D, c, 50 + 24.5, 0, "heavy, inside 26");
        assertPixel(WHITE, c, 50 + 27.5, 0, "heavy, outside 26");
    }

    @Test
    void aLinkIsALineOfItsTypeColourBetweenItsMasses() {
        PhysicalModel m = new PhysicalModel(1000, 50);
        m.addGround3D("a", v(-100, -40, 0));
        m.addGround3D("b", v(100, -40, 0));
        m.addGround3D("c", v(-60, 0, 0));
        m.addGround3D("d", v(60, 100, 0));
        m.addSpring3D("horizontal", 200, 0.1, "a", "b");
        m.addSpringDamper3D("diagonal", 0, 0.1, 0.01, "c", "d");
        m.init();
        ModelRenderer r = new ModelRenderer(new PApplet());
        r.displayMats(false);
        Canvas c = draw(m, r);
        for (int x = -95; x <= 95; x += 5) {
            assertPixel(SPRING, c, x + 0.5, -40 + 0.5, "horizontal spring");
            assertPixel(WHITE, c, x + 0.5, -40 + 4.5, "beside the horizontal spring");
        }
        for (int k = 1; k < 20; k++) {
            double t = k / 20.0;
            double x = -60 + 120 * t;
            double y = 100 * t;
            assertPixel(SPRING_DAMPER, c, x, y, "diagonal spring-damper");
        }
        assertPixel(WHITE, c, 0, 20, "off the diagonal");
        // masses hidden: no disc where the ground points are (away from the lines)
        assertPixel(WHITE, c, -60, 5, "hidden mass");
    }

    @Test
    void theStrainGradientGoesFromTheBaseColourAtRestToTheStrainColourAtMax() {
        PhysicalModel m = new PhysicalModel(1000, 50);
        // three springs of length parameter 20: at rest (distance 20), strain 1 (distance 40), strain 5 (120)
        m.addGround3D("a0", v(-60, -60, 0));
        m.addGround3D("b0", v(-40, -60, 0));
        m.addGround3D("a1", v(-60, 0, 0));
        m.addGround3D("b1", v(-20, 0, 0));
        m.addGround3D("a2", v(-60, 60, 0));
        m.addGround3D("b2", v(60, 60, 0));
        m.addSpring3D("rest", 20, 0.1, "a0", "b0");
        m.addSpring3D("half", 20, 0.1, "a1", "b1");
        m.addSpring3D("full", 20, 0.1, "a2", "b2");
        m.init();
        ModelRenderer r = new ModelRenderer(new PApplet());
        r.displayMats(false);
        assertTrue(r.setColor(linkModuleType.Spring3D, 0, 0, 255, 255));
        assertTrue(r.setStrainColor(linkModuleType.Spring3D, 255, 0, 0, 255));
        assertTrue(r.setStrainGradient(linkModuleType.Spring3D, true, 2));
        Canvas c = draw(m, r);
        assertPixel(rgb(0, 0, 255), c, -50, -60, "spring at rest");
        assertPixel(rgb(255, 0, 0), c, 0, 60, "spring beyond the maximum strain");
        // strain 1 of max 2: half way, channel by channel
        int half = c.at(-40, 0);
        assertEquals(127.5, (half >> 16) & 0xFF, 0.5, "red half way: " + hex(half));
        assertEquals(0, (half >> 8) & 0xFF, "green: " + hex(half));
        assertEquals(127.5, half & 0xFF, 0.5, "blue half way: " + hex(half));

        // the boolean is honoured: gradient off gives the base colour, however strained
        assertTrue(r.setStrainGradient(linkModuleType.Spring3D, false, 2));
        Canvas off = draw(m, r);
        assertPixel(rgb(0, 0, 255), off, 0, 60, "strained spring without gradient");
        assertPixel(rgb(0, 0, 255), off, -40, 0, "strained spring without gradient");
    }

    @Test
    void aZeroLengthSpringIsColouredWithoutNaN() {
        PhysicalModel m = new PhysicalModel(1000, 50);
        m.addGround3D("a", v(-60, -30, 0));
        m.addGround3D("b", v(60, -30, 0));
        m.addGround3D("c", v(-60, 30, 0));
        m.addSpring3D("stretched", 0, 0.1, "a", "b");
        m.addGround3D("c2", v(-60, 30, 0));
        m.addSpring3D("collapsed", 0, 0.1, "c", "c2");
        m.init();
        ModelRenderer r = new ModelRenderer(new PApplet());
        r.displayMats(false);
        r.setColor(linkModuleType.Spring3D, 0, 0, 255, 255);
        r.setStrainColor(linkModuleType.Spring3D, 255, 0, 0, 255);
        r.setStrainGradient(linkModuleType.Spring3D, true, 2);
        Canvas c = draw(m, r);
        assertPixel(rgb(255, 0, 0), c, 0, -30, "stretched zero-length spring: infinite strain");
        int dot = c.at(-60, 30);
        assertTrue(dot == WHITE || dot == rgb(0, 0, 255), "a zero-length spring at rest has the base colour: "
                + hex(dot));
        assertEquals(0.0, LinkStyle.strain(0, 0), "no stretch of a zero-length link is no strain");
        assertEquals(Double.POSITIVE_INFINITY, LinkStyle.strain(3, 0));
        assertEquals(0.0, LinkStyle.strain(-3, 0));
        assertEquals(0.0, LinkStyle.strain(Double.NaN, 5));
        assertEquals(0.5, LinkStyle.strain(2.5, 5));
        LinkStyle s = new LinkStyle(0, 0, 255, 255, 2);
        s.setStrainColor(255, 0, 0, 255);
        s.setStrainGradient(true, 2);
        assertEquals(0xFFFF0000, s.colorAt(Double.POSITIVE_INFINITY));
        assertEquals(0xFF0000FF, s.colorAt(Double.NaN));
        assertEquals(0xFF0000FF, s.colorAt(-1));
    }

    @Test
    void contactsBubblesPlanesAndAttractorsAreHiddenByDefault() {
        PhysicalModel m = new PhysicalModel(1000, 50);
        m.addGround3D("a", v(-80, -50, 0));
        m.addGround3D("b", v(80, -50, 0));
        m.addMass3D("c", 1, v(-80, 50, 0), v(0, 0, 0));
        m.addMass3D("d", 1, v(80, 50, 0), v(0, 0, 0));
        m.addContact3D("contact", 500, 0.1, 0.01, "a", "b");
        m.addBubble3D("bubble", 10, 0.1, 0.01, "a", "c");
        m.addPlaneContact("floor", 0, 0.1, 0.01, 1, 100, "d");
        m.addAttractor3D("pull", 1, 0.001, "c", "d");
        m.init();
        ModelRenderer r = new ModelRenderer(new PApplet());
        r.displayMats(false);
        Canvas c = draw(m, r);
        assertTrue(c.allWhite(), "hidden links leave only background");

        // once given a colour, each shows up
        r.setColor(linkModuleType.Contact3D, 255, 0, 0, 255);
        r.setColor(linkModuleType.Attractor3D, 0, 0, 255, 255);
        r.setColor(linkModuleType.Bubble3D, 0, 255, 0, 255);
        r.setColor(linkModuleType.PlaneContact3D, 255, 0, 255, 255);
        Canvas shown = draw(m, r);
        assertPixel(rgb(255, 0, 0), shown, 0, -50, "contact");
        assertPixel(rgb(0, 0, 255), shown, 0, 50, "attractor");
        assertPixel(rgb(0, 255, 0), shown, -80, 0, "bubble");
        // the plane contact runs from its mass (80, 50) to the mass's foot on the plane y = 100
        assertPixel(rgb(255, 0, 255), shown, 80, 75, "plane contact");
        assertPixel(WHITE, shown, 80, 105, "beyond the plane");
    }

    @Test
    void zoomAndScaleMoveAndGrowTheDrawingAsDocumented() {
        PhysicalModel m = new PhysicalModel(1000, 50);
        m.addMass3D("m", 1, v(20, 15, 40), v(0, 0, 0));
        m.addGround3D("g", v(-20, 15, 0));
        m.addSpring3D("s", 40, 0.1, "m", "g");
        m.init();
        ModelRenderer r = new ModelRenderer(new PApplet());
        r.setZoomVector(2, -1, 7);
        r.setScale(1.5f);
        assertEquals(1.5f, r.getScale());
        Canvas c = draw(m, r);
        // drawing point = 1.5 * (2 x, -y, 7 z) projected on x-y; radius 1.5 * 10
        double mx = 1.5 * 2 * 20;
        double my = 1.5 * -15;
        double gx = 1.5 * 2 * -20;
        assertPixel(MASS3D, c, mx, my, "zoomed mass");
        assertPixel(MASS3D, c, mx + 13.5, my, "zoomed mass, radius 15");
        assertPixel(WHITE, c, mx + 16.5, my, "zoomed mass, radius 15");
        assertPixel(GREEN, c, gx, my, "zoomed ground");
        assertPixel(SPRING, c, 0, my, "zoomed spring between them");
        assertPixel(WHITE, c, 20, 15, "the unzoomed position is empty");
    }

    @Test
    void renderModelDrawsIntoTheSketchsCurrentRenderer() {
        PhysicalModel m = new PhysicalModel(1000, 50);
        m.addMass3D("m", 1, v(10, -20, 0), v(0, 0, 0));
        m.init();
        Canvas c = new Canvas(240, 240);
        ModelRenderer r = rendererFor(c.g);
        c.begin();
        r.renderModel(m);
        c.end();
        assertPixel(MASS3D, c, 10, -20, "mass drawn through app.g");
    }

    @Test
    void aMeshIsDrawnMassesOverLinks() {
        PhysicalModel m = new PhysicalModel(1000, 50);
        int n = 5;
        double step = 40;
        double o = -step * (n - 1) / 2;
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++) {
                m.addMass3D("m" + i + "_" + j, 1, v(o + i * step, o + j * step, 0), v(0, 0, 0));
            }
        }
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++) {
                if (i + 1 < n) {
                    m.addSpringDamper3D("h" + i + "_" + j, step, 0.1, 0.01, "m" + i + "_" + j, "m" + (i + 1) + "_" + j);
                }
                if (j + 1 < n) {
                    m.addSpringDamper3D("v" + i + "_" + j, step, 0.1, 0.01, "m" + i + "_" + j, "m" + i + "_" + (j + 1));
                }
            }
        }
        m.init();
        ModelRenderer r = new ModelRenderer(new PApplet());
        Canvas c = draw(m, r);
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++) {
                double x = o + i * step;
                double y = o + j * step;
                assertPixel(MASS3D, c, x, y, "mass " + i + "," + j);
                if (i + 1 < n) {
                    assertPixel(SPRING_DAMPER, c, x + step / 2, y, "link to the right of " + i + "," + j);
                }
                if (j + 1 < n) {
                    assertPixel(SPRING_DAMPER, c, x, y + step / 2, "link below " + i + "," + j);
                }
                if (i + 1 < n && j + 1 < n) {
                    assertPixel(WHITE, c, x + step / 2, y + step / 2, "middle of a cell");
                }
            }
        }
    }

    @Test
    void aFallingStringIsDrawnWhereItsSnapshotSaysAfterManyFrames() {
        PhysicalModel m = new PhysicalModel(1000, 50);
        int n = 9;
        m.addGround3D("left", v(-100, 0, 0));
        for (int i = 1; i < n; i++) {
            m.addMass3D("m" + i, 1, v(-100 + 200.0 * i / n, 0, 0), v(0, 0, 0));
        }
        m.addGround3D("right", v(100, 0, 0));
        for (int i = 0; i < n; i++) {
            String a = i == 0 ? "left" : "m" + i;
            String b = i + 1 == n ? "right" : "m" + (i + 1);
            m.addSpringDamper3D("s" + i, 200.0 / n, 0.05, 0.001, a, b);
        }
        m.setGravity(0.0005);
        m.setGravityDirection(new Vect3D(0, -1, 0));   // masses fall toward +y: down the screen
        m.init();
        ModelRenderer r = new ModelRenderer(new PApplet());
        r.setSize(matModuleType.Mass3D, 4);
        for (int f = 0; f < 15; f++) {
            m.draw_physics();
        }
        ModelSnapshot s = m.getSnapshot();
        double sag = s.y(n / 2);
        assertTrue(sag > 10, "the string sags: middle mass at y = " + sag);
        Canvas c = draw(m, r);
        for (int i = 0; i <= n; i++) {
            int expected = i == 0 || i == n ? GREEN : MASS3D;
            assertPixel(expected, c, s.x(i), s.y(i), "mass " + i);
        }
        assertPixel(WHITE, c, s.x(n / 2), s.y(n / 2) - 14, "above the middle mass, off the string");
    }

    @Test
    void theTargetsStyleIsRestored() {
        PhysicalModel m = new PhysicalModel(1000, 50);
        m.addMass3D("m", 1, v(0, 0, 0), v(0, 0, 0));
        m.addGround3D("g", v(50, 0, 0));
        m.addSpring3D("s", 50, 0.1, "m", "g");
        m.init();
        Canvas c = new Canvas(100, 100);
        PGraphics g = c.begin();
        g.fill(1, 2, 3);
        g.stroke(4, 5, 6);
        g.strokeWeight(7);
        new ModelDrawer().draw(m, g);   // ModelRenderer then leaves the paper engine's style (LeftStyleTest)
        assertEquals(rgb(1, 2, 3), g.fillColor);
        assertEquals(rgb(4, 5, 6), g.strokeColor);
        assertEquals(7f, g.strokeWeight);
        c.end();
    }
}
