package tactus.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static tactus.render.Canvas.hex;

import org.junit.jupiter.api.Test;

import processing.core.PApplet;
import tactus.ModelRenderer;
import tactus.ModelSnapshot;
import tactus.PhysicalModel;
import tactus.Vect3D;
import tactus.linkModuleType;
import tactus.matModuleType;

/**
 * Pixel tests, in an off-screen JAVA2D target, of colouring by speed, force and strain, and of the avatar's force
 * arrow. Expected colours are the scale's colours of values computed from the model's equations; expected arrow
 * pixels come from the documented length, arrowScale × force.
 */
class ColouringTest {
    private static final int AVATAR = Canvas.rgb(255, 50, 50);
    private static final int GREEN = Canvas.rgb(0, 220, 130);

    private static Canvas draw(PhysicalModel m, ModelDrawer d) {
        Canvas c = new Canvas(240, 240);
        d.draw(m, c.begin());
        c.end();
        return c;
    }

    private static void assertPixel(int expected, Canvas c, double x, double y, String what) {
        assertEquals(hex(expected), hex(c.at(x, y)), what + " at (" + x + ", " + y + ")");
    }

    @Test
    void bySpeedEachMovingMassTakesTheColourOfItsSpeed() {
        PhysicalModel m = new PhysicalModel(1000, 50);
        double[] speeds = {0, 2.5, 5, 10, 40};
        for (int i = 0; i < speeds.length; i++) {
            // moving along z only, so that they stay where they are drawn in 2D
            m.addMass3D("m" + i, 1, new Vect3D(-80 + 40 * i, -50, 0), new Vect3D(0, 0, speeds[i]));
        }
        m.addGround3D("g", new Vect3D(0, 50, 0));
        m.addHapticInput3D("hand", new Vect3D(60, 50, 0), 1);
        m.init();
        m.getSnapshot().requestMotion(true);   // what the drawer asks for when it first colours by speed
        m.computeNSteps(10);
        ModelDrawer d = new ModelDrawer();
        ColorScale scale = ColorScale.heat(0, 10);
        d.setColorBy(ColorBy.SPEED, scale);
        Canvas c = draw(m, d);
        for (int i = 0; i < speeds.length; i++) {
            assertPixel(scale.colorAt(speeds[i]), c, -80 + 40 * i, -50, "mass at speed " + speeds[i]);
        }
        assertNotEquals(scale.colorAt(0), scale.colorAt(5));
        assertPixel(GREEN, c, 0, 50, "a fixed point keeps its type colour");
        assertPixel(AVATAR, c, 60, 50, "the avatar keeps its type colour");
    }

    @Test
    void byForceAMassTakesTheColourOfTheSpringForceOnIt() {
        double k = 0.01;
        PhysicalModel m = new PhysicalModel(1000, 50);
        m.addGround3D("g", new Vect3D(-60, 0, 0));
        m.addMass3D("m", 1e6, new Vect3D(60, 0, 0), new Vect3D());   // heavy: it stays put
        m.addSpring3D("s", 40, k, "g", "m");
        m.init();
        m.getSnapshot().requestMotion(true);
        m.computeNSteps(10);
        ModelSnapshot s = m.getSnapshot();
        double force = k * ((s.x(1) - s.x(0)) - 40);   // 0.8
        ModelDrawer d = new ModelDrawer();
        ColorScale scale = ColorScale.heat(0, 1);
        d.setColorBy(ColorBy.FORCE, scale);
        d.style().link(linkModuleType.Spring3D).setWeight(4);
        Canvas c = draw(m, d);
        assertPixel(scale.colorAt(force), c, 60, 0, "mass under force " + force);
        // the spring takes the mean of its ends: the fixed end counts 0
        assertPixel(scale.colorAt(force / 2), c, 0, 0, "spring between a fixed point and the mass");
        assertNotEquals(scale.colorAt(force), scale.colorAt(force / 2));
    }

    @Test
    void byStrainALinkTakesTheColourOfItsStrainAndHiddenTypesStayHidden() {
        PhysicalModel m = new PhysicalModel(1000, 50);
        m.addGround3D("g", new Vect3D(-80, 0, 0));
        m.addMass3D("m", 1e6, new Vect3D(80, 0, 0), new Vect3D());
        m.addSpring3D("s", 100, 0.01, "g", "m");                      // strain (160 - 100) / 100 = 0.6
        m.addGround3D("a", new Vect3D(-80, 60, 0));
        m.addGround3D("b", new Vect3D(80, 60, 0));
        m.addContact3D("c", 500, 0.01, 0.001, "a", "b");           // contacts are hidden by default
        m.init();
        ModelRenderer r = new ModelRenderer(new PApplet());
        r.setSize(linkModuleType.Spring3D, 4);
        r.setSize(linkModuleType.Contact3D, 4);
        r.colorBy(ColorBy.STRAIN, -1, 1);
        ColorScale scale = r.getDrawer().getColorScale();
        Canvas c = new Canvas(240, 240);
        r.renderModel(m, c.begin());
        c.end();
        ModelSnapshot s = m.getSnapshot();
        double strain = ((s.x(1) - s.x(0)) - 100) / 100;
        assertEquals(0.6, strain, 1e-12);
        assertPixel(scale.colorAt(strain), c, 0, 0, "spring at strain 0.6");
        assertPixel(Canvas.WHITE, c, 0, 60, "a hidden contact stays hidden when coloured by strain");
        r.colorBy(ColorBy.TYPE, 0, 1);
        c = new Canvas(240, 240);
        r.renderModel(m, c.begin());
        c.end();
        assertPixel(Canvas.rgb(30, 100, 100), c, 0, 0, "by type again");
    }

    /** An avatar pulled by a zero-length spring towards a fixed point 80 units to its right. */
    private static PhysicalModel pulledAvatar(double k) {
        PhysicalModel m = new PhysicalModel(1000, 50);
        m.addHapticInput3D("hand", new Vect3D(-40, 0, 0), 1);
        m.addGround3D("g", new Vect3D(40, 0, 0));
        m.addSpring3D("s", 0, k, "g", "hand");
        m.init();
        m.computeNSteps(10);
        return m;
    }

    @Test
    void theAvatarsForceArrowPointsAlongTheForceWithTheSetLength() {
        double k = 0.002;
        PhysicalModel m = pulledAvatar(k);
        ModelSnapshot s = m.getSnapshot();
        double force = k * (s.x(1) - s.x(0));   // 0.16, towards the fixed point
        assertEquals(force, s.fx(0), 1e-12);
        ModelDrawer d = new ModelDrawer();
        d.setShowLinks(false);
        d.setForceArrowStyle(0, 0, 255, 255, 3);
        d.setForceArrowScale((float) (60 / force));   // 60 units long: from x = -40 to x = 20
        int blue = Canvas.rgb(0, 0, 255);
        Canvas c = draw(m, d);
        for (double x = -25; x <= 15; x += 10) {
            assertPixel(blue, c, x, 0, "arrow shaft");
        }
        assertPixel(Canvas.WHITE, c, 25, 0, "beyond the tip");
        assertPixel(Canvas.WHITE, c, 0, -10, "beside the shaft");
        // the head: two strokes from the tip (20, 0) back to (5, +-6)
        assertPixel(blue, c, 12.5, 3, "lower stroke of the head");
        assertPixel(blue, c, 12.5, -3, "upper stroke of the head");
        assertPixel(AVATAR, c, -40, -7, "the avatar itself, under the arrow");

        d.setForceArrowScale((float) (30 / force));
        c = draw(m, d);
        assertPixel(blue, c, -15, 0, "half as long: shaft");
        assertPixel(Canvas.WHITE, c, 0, 0, "half as long: beyond its tip");

        d.setShowForceArrows(false);
        c = draw(m, d);
        assertPixel(Canvas.WHITE, c, -20, 0, "arrows off");
        d.setShowForceArrows(true);
        d.setForceArrow(matModuleType.HapticInput3D, false);
        c = draw(m, d);
        assertPixel(Canvas.WHITE, c, -20, 0, "arrows off for avatars");
    }

    @Test
    void theArrowPainterCanBeReplaced() {
        PhysicalModel m = pulledAvatar(0.002);
        ModelDrawer d = new ModelDrawer();
        float[] seen = new float[7];
        d.setArrowPainter((g, index, type, x, y, z, dx, dy, dz, weight, argb) -> {
            seen[0] = index;
            seen[1] = x;
            seen[2] = y;
            seen[3] = dx;
            seen[4] = dy;
            seen[5] = dz;
            seen[6] = type == matModuleType.HapticInput3D ? 1 : 0;
        });
        d.setScale(2);
        d.setForceArrowScale(100);
        draw(m, d);
        ModelSnapshot s = m.getSnapshot();
        assertEquals(0, seen[0]);
        assertEquals(1, seen[6]);
        assertEquals(2 * s.x(0), seen[1], 1e-4);
        assertEquals(2 * 100 * s.fx(0), seen[3], 1e-4, "scale x arrow scale x force");
        assertEquals(0, seen[4], 0);
        assertTrue(seen[3] > 0, "towards the fixed point on the right");
    }
}
