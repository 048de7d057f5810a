package tactus.render;

import processing.core.PApplet;
import processing.core.PConstants;
import processing.core.PGraphics;
import processing.event.MouseEvent;

/**
 * A simple camera that orbits a target point: drag with the left mouse button to turn around it, with the right
 * (or middle) button to pan, turn the wheel to zoom, double-click to go back to the start. It replaces third-party
 * camera libraries in the examples.
 *
 * <p>Geometry (Processing's axes: x right, y down, z towards the viewer). The eye is at
 * {@code target + distance × (cos(pitch) sin(yaw), -sin(pitch), cos(pitch) cos(yaw))} looking at the target with
 * y down on screen, so yaw = pitch = 0 is Processing's default view along -z, a positive yaw turns the eye towards
 * +x and a positive pitch raises it (looking down). Pitch stays within ±89°. On screen, right is
 * {@code (cos yaw, 0, -sin yaw)} and down is {@code (sin pitch sin yaw, cos pitch, sin pitch cos yaw)}. The field of
 * view is Processing's, 60° vertically, so a point at the target's depth moves {@code eyePixels / distance} pixels
 * per length unit, where {@code eyePixels = (height / 2) / tan(30°)}; the default distance is {@code eyePixels}, so
 * the plane through the target is then drawn at 1 pixel per unit, as with Processing's default camera centred on the
 * target. Panning moves the target so that the point under the mouse follows it.
 *
 * <p>In a 2D target (JAVA2D, P2D) there is no rotation: {@link #apply} translates the target to the centre and
 * scales by {@code eyePixels / distance}.
 *
 * <p>With a sketch ({@link #OrbitCamera(PApplet)}) it registers itself through {@code registerMethod}: {@code pre}
 * applies it to the sketch's renderer before each {@code draw()}, {@code mouseEvent} steers it, {@code dispose}
 * unregisters it. Without a sketch, call {@link #apply(PGraphics)} and the steering methods yourself.
 */
public final class OrbitCamera {
    /** Field of view, vertical, in radians (Processing's default). */
    public static final float FOV = PConstants.PI / 3;
    private static final double MAX_PITCH = Math.toRadians(89);
    private static final double ORBIT_PER_PIXEL = 0.01;
    private static final double ZOOM_PER_NOTCH = 1.1;

    private final PApplet app;
    private final Callbacks callbacks;
    private double yaw;
    private double pitch;
    private double distance = -1;   // < 0: eyePixels of the first target it is applied to
    private double tx;
    private double ty;
    private double tz;
    private double startYaw;
    private double startPitch;
    private double startDistance = -1;
    private double startX;
    private double startY;
    private double startZ;
    private double minDistance = 1e-3;
    private double maxDistance = 1e7;
    private int viewHeight = 100;
    private boolean mouse = true;
    private int orbitButton = PConstants.LEFT;
    private int panButton = PConstants.RIGHT;
    private int lastX;
    private int lastY;
    private boolean registered;

    /** Creates a camera to use by hand: looking at the origin, default distance, no rotation. */
    public OrbitCamera() {
        app = null;
        callbacks = null;
    }

    /**
     * Creates a camera for a sketch and registers it: applied before every {@code draw()}, steered by the mouse.
     * In {@code draw()}, do not {@code translate()} to the centre: the target is drawn there.
     *
     * @param parent the sketch ({@code this})
     */
    public OrbitCamera(PApplet parent) {
        if (parent == null) {
            throw new IllegalArgumentException("OrbitCamera: the sketch must not be null");
        }
        app = parent;
        callbacks = new Callbacks();
        parent.registerMethod("pre", callbacks);
        parent.registerMethod("mouseEvent", callbacks);
        parent.registerMethod("dispose", callbacks);
        registered = true;
    }

    /**
     * The methods the sketch calls through {@code registerMethod}; public because Processing calls them by
     * reflection. Not for direct use.
     */
    public final class Callbacks {
        private Callbacks() {
        }

        /** Applies the camera to the sketch's renderer (Processing calls this before {@code draw()}). */
        public void pre() {
            apply(app.g);
        }

        /** Steers the camera (Processing calls this for each mouse event). */
        public void mouseEvent(MouseEvent e) {
            handle(e);
        }

        /** Unregisters the camera (Processing calls this when the sketch ends). */
        public void dispose() {
            OrbitCamera.this.dispose();
        }
    }

    /** Stops listening to the sketch (idempotent); the camera can still be applied by hand. */
    public void dispose() {
        if (registered) {
            registered = false;
            app.unregisterMethod("pre", callbacks);
            app.unregisterMethod("mouseEvent", callbacks);
            app.unregisterMethod("dispose", callbacks);
        }
    }

    /** {@return true while registered with a sketch} */
    public boolean isRegistered() {
        return registered;
    }

    // ------------------------------------------------------------------------------------------- the view

    /** Points the camera at (x, y, z), in drawing units, keeping distance and angles; this becomes the start. */
    public void lookAt(double x, double y, double z) {
        checkFinite("lookAt", x, y, z);
        tx = startX = x;
        ty = startY = y;
        tz = startZ = z;
    }

    /** Sets yaw and pitch in radians (pitch clamped to ±89°); this becomes the start. */
    public void setRotation(double yaw, double pitch) {
        checkFinite("setRotation", yaw, pitch, 0);
        this.yaw = startYaw = yaw;
        this.pitch = startPitch = clampPitch(pitch);
    }

    /** Sets the eye's distance to the target, in drawing units, &gt; 0 (clamped to the zoom limits); this becomes the start. */
    public void setDistance(double d) {
        if (!(d > 0) || !Double.isFinite(d)) {
            throw new IllegalArgumentException("OrbitCamera.setDistance: the distance must be finite and > 0, got " + d);
        }
        distance = startDistance = clampDistance(d);
    }

    /** Sets the limits of zooming: 0 &lt; min &lt; max, finite. */
    public void setDistanceLimits(double min, double max) {
        if (!(min > 0) || !(max > min) || !Double.isFinite(max)) {
            throw new IllegalArgumentException("OrbitCamera.setDistanceLimits: need finite 0 < min < max, got [" + min
                    + ", " + max + "]");
        }
        minDistance = min;
        maxDistance = max;
        if (distance > 0) {
            distance = clampDistance(distance);
        }
    }

    /** Turns mouse steering on or off (for example while the mouse drives a haptic avatar). */
    public void setMouseEnabled(boolean on) {
        mouse = on;
    }

    /**
     * Chooses the mouse buttons that orbit and pan ({@code LEFT}, {@code RIGHT} or {@code CENTER}; 0 for none).
     * The defaults are LEFT and RIGHT; the middle button always pans.
     */
    public void setButtons(int orbit, int pan) {
        orbitButton = orbit;
        panButton = pan;
    }

    /** Turns around the target by these angles, in radians (pitch clamped to ±89°). */
    public void orbit(double dYaw, double dPitch) {
        checkFinite("orbit", dYaw, dPitch, 0);
        yaw += dYaw;
        pitch = clampPitch(pitch + dPitch);
    }

    /** Multiplies the distance by a factor &gt; 0 (&lt; 1 comes closer), within the limits. */
    public void zoom(double factor) {
        if (!(factor > 0) || !Double.isFinite(factor)) {
            throw new IllegalArgumentException("OrbitCamera.zoom: the factor must be finite and > 0, got " + factor);
        }
        distance = clampDistance(distance() * factor);
    }

    /**
     * Moves the view so that what was under the screen point p is now under p + (dx, dy) pixels, for points at
     * the target's depth: the target moves by {@code -(dx right + dy down) × distance / eyePixels}.
     */
    public void pan(double dxPixels, double dyPixels) {
        checkFinite("pan", dxPixels, dyPixels, 0);
        double k = distance() / eyePixels();
        double sy = Math.sin(yaw);
        double cy = Math.cos(yaw);
        double sp = Math.sin(pitch);
        double cp = Math.cos(pitch);
        tx -= k * (dxPixels * cy + dyPixels * sp * sy);
        ty -= k * (dyPixels * cp);
        tz -= k * (-dxPixels * sy + dyPixels * sp * cy);
    }

    /** Goes back to the start: the last target, rotation and distance set (or the defaults). */
    public void reset() {
        tx = startX;
        ty = startY;
        tz = startZ;
        yaw = startYaw;
        pitch = startPitch;
        distance = startDistance;
    }

    /** {@return the yaw, radians} */
    public double getYaw() {
        return yaw;
    }

    /** {@return the pitch, radians} */
    public double getPitch() {
        return pitch;
    }

    /** {@return the distance from eye to target, in drawing units} */
    public double getDistance() {
        return distance();
    }

    /** Writes the target into out[0..2] and returns out. */
    public double[] target(double[] out) {
        out[0] = tx;
        out[1] = ty;
        out[2] = tz;
        return out;
    }

    /** Writes the eye position into out[0..2] and returns out. */
    public double[] eye(double[] out) {
        double d = distance();
        double cp = Math.cos(pitch);
        out[0] = tx + d * cp * Math.sin(yaw);
        out[1] = ty - d * Math.sin(pitch);
        out[2] = tz + d * cp * Math.cos(yaw);
        return out;
    }

    /** {@return the eye distance in pixels of Processing's default camera, (height / 2) / tan(30°)} */
    public double eyePixels() {
        return viewHeight / 2.0 / Math.tan(Math.PI / 6);
    }

    /**
     * Applies the view to a target, replacing its camera and projection (3D) or adding a translation and scale to
     * its matrix (2D). The first call with no distance set takes the default distance from the target's height.
     */
    public void apply(PGraphics g) {
        if (g == null) {
            throw new IllegalArgumentException("OrbitCamera.apply: the target must not be null");
        }
        viewHeight = Math.max(1, g.height);
        if (distance < 0) {
            distance = startDistance = clampDistance(eyePixels());
        }
        if (g.is3D()) {
            double d = distance;
            double cp = Math.cos(pitch);
            float ex = (float) (tx + d * cp * Math.sin(yaw));
            float ey = (float) (ty - d * Math.sin(pitch));
            float ez = (float) (tz + d * cp * Math.cos(yaw));
            g.camera(ex, ey, ez, (float) tx, (float) ty, (float) tz, 0, 1, 0);
            g.perspective(FOV, (float) g.width / Math.max(1, g.height), (float) (d / 100), (float) (d * 100));
        } else {
            float k = (float) (eyePixels() / distance);
            g.translate(g.width / 2f, g.height / 2f);
            g.scale(k);
            g.translate((float) -tx, (float) -ty);
        }
    }

    /** Steers the camera with a Processing mouse event (what the registered {@code mouseEvent} does). */
    public void handle(MouseEvent e) {
        if (!mouse || e == null) {
            return;
        }
        switch (e.getAction()) {
            case MouseEvent.PRESS:
                lastX = e.getX();
                lastY = e.getY();
                break;
            case MouseEvent.DRAG: {
                int dx = e.getX() - lastX;
                int dy = e.getY() - lastY;
                lastX = e.getX();
                lastY = e.getY();
                int b = e.getButton();
                if (b != 0 && b == orbitButton) {
                    orbit(ORBIT_PER_PIXEL * dx, ORBIT_PER_PIXEL * dy);
                } else if (b != 0 && (b == panButton || b == PConstants.CENTER)) {
                    pan(dx, dy);
                }
                break;
            }
            case MouseEvent.WHEEL:
                zoom(Math.pow(ZOOM_PER_NOTCH, e.getCount()));
                break;
            case MouseEvent.CLICK:
                if (e.getCount() == 2) {
                    reset();
                }
                break;
            default:
                break;
        }
    }

    private double distance() {
        return distance > 0 ? distance : clampDistance(eyePixels());
    }

    private double clampDistance(double d) {
        return Math.max(minDistance, Math.min(maxDistance, d));
    }

    private static double clampPitch(double p) {
        return Math.max(-MAX_PITCH, Math.min(MAX_PITCH, p));
    }

    private static void checkFinite(String op, double a, double b, double c) {
        if (!Double.isFinite(a) || !Double.isFinite(b) || !Double.isFinite(c)) {
            throw new IllegalArgumentException("OrbitCamera." + op + ": arguments must be finite, got " + a + ", " + b
                    + ", " + c);
        }
    }
}
