package tactus.haptics.inverse;

import tactus.haptics.HapticDevice;
import tactus.haptics.WorkspaceMapping;

/**
 * An Inverse3 presented as a planar pantograph, so that a sketch written for the 2DIY runs unchanged on it: the
 * device's vertical plane facing the user (x to the right, z up) becomes the pantograph's plane, in the
 * pantograph's own frame (u = -(x - cx), v = v0 - (z - cz), metres: u mirrored and v growing downwards, as a
 * 2DIY's x and y are seen by the paper's sketches), and the depth (device y) is free: it is neither read nor
 * pushed. {@link #dimensions()} is 2 and the default mapping is {@link WorkspaceMapping#pantograph()}, so a
 * {@link tactus.haptics.HapticLoop} maps it exactly as it maps a 2DIY.
 */
public final class PlanarInverse3 implements HapticDevice {
    /** The virtual pantograph frame's v at the workspace centre (metres), about a 2DIY's. */
    public static final double V0 = 0.1;

    private final Inverse3Device inverse;
    private final double cx;
    private final double cz;
    private final double[] p = new double[3];

    /** Wraps an Inverse3 whose workspace centre is (cx, *, cz) in the service's metres. */
    public PlanarInverse3(Inverse3Device inverse, double cx, double cz) {
        if (inverse == null) {
            throw new IllegalArgumentException("PlanarInverse3: device must not be null");
        }
        this.inverse = inverse;
        this.cx = cx;
        this.cz = cz;
    }

    /** The wrapped Inverse3 (for its VerseGrip, status and close). */
    public Inverse3Device inverse() {
        return inverse;
    }

    /** The comfortable workspace of half-size (hx, hz) metres around the centre, in this frame: umin, umax, vmin, vmax. */
    public static void box(double hx, double hz, double[] out) {
        out[0] = -hx;
        out[1] = hx;
        out[2] = V0 - hz;
        out[3] = V0 + hz;
    }

    @Override
    public int dimensions() {
        return 2;
    }

    @Override
    public boolean isReady() {
        return inverse.isReady();
    }

    @Override
    public void begin() {
        inverse.begin();
    }

    @Override
    public boolean update() {
        return inverse.update();
    }

    @Override
    public void position(double[] out) {
        inverse.position(p);
        out[0] = -(p[0] - cx);
        out[1] = V0 - (p[2] - cz);
        out[2] = Double.isNaN(p[0]) ? Double.NaN : 0;
    }

    @Override
    public void velocity(double[] out) {
        inverse.velocity(p);
        out[0] = -p[0];
        out[1] = -p[2];
        out[2] = 0;
    }

    @Override
    public void sendForce(double fu, double fv, double ignored) {
        inverse.sendForce(-fu, 0, -fv);   // the depth gets no force: it is free
    }

    @Override
    public void zeroForce() {
        inverse.zeroForce();
    }

    @Override
    public WorkspaceMapping defaultMapping() {
        return WorkspaceMapping.pantograph();
    }

    @Override
    public String describe() {
        return inverse.describe() + ", as a 2-D device (depth free)";
    }

    @Override
    public String status() {
        return inverse.status();
    }

    @Override
    public void close() {
        inverse.close();
    }
}
