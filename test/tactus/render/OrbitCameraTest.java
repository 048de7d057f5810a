package tactus.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static tactus.render.Canvas.hex;

import org.junit.jupiter.api.Test;

import processing.core.PConstants;
import processing.event.MouseEvent;
import tactus.PhysicalModel;
import tactus.Vect3D;

/**
 * The orbit camera's geometry, checked against a pinhole projection written here from first principles (eye,
 * target, world "up" = -y), its mouse steering, and its 2D mode in a real JAVA2D target.
 */
class OrbitCameraTest {
    private static final int H = 240;

    private static double dot(double[] a, double[] b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }

    private static double[] cross(double[] a, double[] b) {
        return new double[] {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    }

    private static double[] unit(double[] a) {
        double n = Math.sqrt(dot(a, a));
        return new double[] {a[0] / n, a[1] / n, a[2] / n};
    }

    private static double[] minus(double[] a, double[] b) {
        return new double[] {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
    }

    /**
     * Screen offset from the centre, in pixels, of world point p: a pinhole at the eye, looking at the target,
     * with screen up towards world -y, and focal length (H / 2) / tan(30°) (Processing's 60° field of view).
     */
    private static double[] project(OrbitCamera cam, double[] p) {
        double[] eye = cam.eye(new double[3]);
        double[] fwd = unit(minus(cam.target(new double[3]), eye));
        double[] right = unit(cross(new double[] {0, -1, 0}, fwd));
        double[] down = cross(right, fwd);
        double[] q = minus(p, eye);
        double f = (H / 2.0) / Math.tan(Math.PI / 6);
        double depth = dot(q, fwd);
        return new double[] {f * dot(q, right) / depth, f * dot(q, down) / depth};
    }

    private static OrbitCamera camera() {
        OrbitCamera cam = new OrbitCamera();
        Canvas c = new Canvas(H, H);
        c.g.beginDraw();
        cam.apply(c.g);   // takes the default distance from the target's height
        c.g.endDraw();
        return cam;
    }

    @Test
    void byDefaultItIsProcessingsDefaultCameraCentredOnTheTarget() {
        OrbitCamera cam = camera();
        double f = (H / 2.0) / Math.tan(Math.PI / 6);
        assertEquals(f, cam.getDistance(), 1e-9);
        double[] eye = cam.eye(new double[3]);
        assertEquals(0, eye[0], 1e-12);
        assertEquals(0, eye[1], 1e-12);
        assertEquals(f, eye[2], 1e-9);
        // a point of the plane z = 0 lands 1 pixel per unit from the centre
        double[] p = project(cam, new double[] {30, -20, 0});
        assertEquals(30, p[0], 1e-9);
        assertEquals(-20, p[1], 1e-9);
    }

    @Test
    void orbitingKeepsTheDistanceAndTurnsTheEyeAsDocumented() {
        OrbitCamera cam = camera();
        double d = cam.getDistance();
        cam.orbit(Math.PI / 2, 0);
        double[] eye = cam.eye(new double[3]);
        assertEquals(d, eye[0], 1e-9, "yaw +90 degrees: the eye on +x");
        assertEquals(0, eye[2], 1e-9);
        // looking along -x, screen right is world -z: a point at z = -50 at the target's depth shows 50 px right
        double[] p = project(cam, new double[] {0, 0, -50});
        assertEquals(50, p[0], 1e-9);
        assertEquals(0, p[1], 1e-9);
        cam.orbit(-Math.PI / 2, 0.5);
        eye = cam.eye(new double[3]);
        assertEquals(d, Math.sqrt(dot(eye, eye)), 1e-9);
        assertTrue(eye[1] < 0, "a positive pitch raises the eye (y up is negative)");
        cam.orbit(0, 10);
        assertEquals(Math.toRadians(89), cam.getPitch(), 1e-12, "pitch stops short of the pole");
        cam.orbit(0, -20);
        assertEquals(-Math.toRadians(89), cam.getPitch(), 1e-12);
    }

    @Test
    void panningMovesWhatWasUnderTheMouseWithTheMouse() {
        for (double[] angles : new double[][] {{0, 0}, {0.7, 0.3}, {-2.1, -1.2}, {3, 1.5}}) {
            OrbitCamera cam = camera();
            cam.setRotation(angles[0], angles[1]);
            cam.zoom(1.7);
            double[] t0 = cam.target(new double[3]);
            double[] eye0 = cam.eye(new double[3]);
            cam.pan(25, -40);
            double[] p = project(cam, t0);
            assertEquals(25, p[0], 1e-9, "yaw " + angles[0] + ", pitch " + angles[1]);
            assertEquals(-40, p[1], 1e-9, "yaw " + angles[0] + ", pitch " + angles[1]);
            double[] moved = minus(cam.target(new double[3]), t0);
            assertEquals(0, dot(moved, unit(minus(t0, eye0))), 1e-9, "panning keeps the depth");
        }
    }

    @Test
    void zoomingScalesTheDistanceWithinItsLimits() {
        OrbitCamera cam = camera();
        double d = cam.getDistance();
        cam.zoom(0.5);
        assertEquals(d / 2, cam.getDistance(), 1e-9);
        double[] p = project(cam, new double[] {10, 0, 0});
        assertEquals(20, p[0], 1e-9, "half as far: twice as large at the target's depth");
        cam.setDistanceLimits(10, 1000);
        cam.zoom(1e-6);
        assertEquals(10, cam.getDistance(), 0);
        cam.zoom(1e9);
        assertEquals(1000, cam.getDistance(), 0);
        assertThrows(IllegalArgumentException.class, () -> cam.zoom(0));
        assertThrows(IllegalArgumentException.class, () -> cam.pan(Double.NaN, 0));
        assertEquals(1000, cam.getDistance(), 0, "a rejected call changes nothing");
    }

    private static MouseEvent mouse(int action, int x, int y, int button, int count) {
        return new MouseEvent(null, 0, action, 0, x, y, button, count);
    }

    @Test
    void theMouseOrbitsPansZoomsAndResets() {
        OrbitCamera cam = camera();
        double d = cam.getDistance();
        cam.handle(mouse(MouseEvent.PRESS, 100, 100, PConstants.LEFT, 1));
        cam.handle(mouse(MouseEvent.DRAG, 120, 90, PConstants.LEFT, 1));
        assertEquals(0.2, cam.getYaw(), 1e-12);
        assertEquals(-0.1, cam.getPitch(), 1e-12);
        double[] t0 = cam.target(new double[3]);
        cam.handle(mouse(MouseEvent.PRESS, 50, 50, PConstants.RIGHT, 1));
        cam.handle(mouse(MouseEvent.DRAG, 80, 50, PConstants.RIGHT, 1));
        double[] p = project(cam, t0);
        assertEquals(30, p[0], 1e-9, "right drag pans");
        cam.handle(mouse(MouseEvent.WHEEL, 80, 50, 0, 2));
        assertEquals(d * 1.21, cam.getDistance(), 1e-9, "two notches of the wheel: 1.1^2 further");
        cam.handle(mouse(MouseEvent.CLICK, 80, 50, PConstants.LEFT, 2));
        assertEquals(0, cam.getYaw(), 0);
        assertEquals(d, cam.getDistance(), 1e-9);
        assertEquals(0, cam.target(new double[3])[0], 0, "double-click: back to the start");
        cam.setMouseEnabled(false);
        cam.handle(mouse(MouseEvent.WHEEL, 80, 50, 0, 5));
        assertEquals(d, cam.getDistance(), 1e-9, "mouse off");
    }

    @Test
    void inA2dTargetItCentresTheTargetAndScalesByTheZoom() {
        PhysicalModel m = new PhysicalModel(1000, 50);
        m.addGround3D("a", new Vect3D(100, 50, 0));
        m.addGround3D("b", new Vect3D(120, 50, 0));
        m.init();
        ModelDrawer drawer = new ModelDrawer();
        drawer.style().mass(tactus.matModuleType.Ground3D).setSize(3);
        OrbitCamera cam = new OrbitCamera();
        cam.lookAt(100, 50, 0);
        Canvas c = new Canvas(H, H);
        c.g.beginDraw();
        c.g.background(255);
        cam.apply(c.g);
        cam.zoom(0.5);   // the next frame: twice as large
        c.g.endDraw();
        c.g.beginDraw();
        c.g.background(255);
        cam.apply(c.g);
        drawer.draw(m, c.g);
        c.end();
        int green = Canvas.rgb(0, 220, 130);
        assertEquals(hex(green), hex(c.at(0, 0)), "the target at the centre");
        assertEquals(hex(green), hex(c.at(40, 0)), "20 units away at twice the scale");
        assertEquals(hex(green), hex(c.at(45, 0)), "radius 3 drawn 6");
        assertEquals(hex(Canvas.WHITE), hex(c.at(20, 0)), "nothing between");
        assertFalse(c.allWhite());
    }
}
