package tactus.haptics.emulator;

/**
 * The hand on an emulated 3-DoF handle ({@link SimulatedInverse3}), in the service's metres: none (the handle
 * is free), a rigid scripted path (the handle is exactly on it, whatever the force), or a spring and damper
 * that pull the handle towards a target that a sketch (the mouse) or a test moves.
 */
public final class Hand3D {
    /** A scripted path: the target position at time t seconds, written into out[0..2], metres. */
    public interface Script {
        /** Writes the target at time t (seconds since the emulator started) into out. */
        void at(double t, double[] out);
    }

    private final Script script;
    private final double stiffness;
    private final double damping;
    private volatile double tx;
    private volatile double ty;
    private volatile double tz;

    private Hand3D(Script script, double stiffness, double damping, double x, double y, double z) {
        this.script = script;
        this.stiffness = stiffness;
        this.damping = damping;
        tx = x;
        ty = y;
        tz = z;
    }

    /** No hand: the handle moves only under the commanded force, its damping and the workspace's walls. */
    public static Hand3D none() {
        return new Hand3D(null, 0, 0, 0, 0, 0);
    }

    /** A rigid hand that moves the handle along a script. */
    public static Hand3D scripted(Script script) {
        if (script == null) {
            throw new IllegalArgumentException("Hand3D.scripted: script must not be null");
        }
        return new Hand3D(script, Double.POSITIVE_INFINITY, 0, 0, 0, 0);
    }

    /**
     * A hand that pulls the handle towards (x, y, z) in metres with a spring k (N/m, > 0) and a damper b
     * (N s/m, >= 0); {@link #setTarget} moves the point.
     */
    public static Hand3D following(double x, double y, double z, double k, double b) {
        if (!(k > 0) || !(b >= 0) || !Double.isFinite(k) || !Double.isFinite(b)) {
            throw new IllegalArgumentException("Hand3D.following: need k > 0 and b >= 0, got " + k + ", " + b);
        }
        return new Hand3D(null, k, b, x, y, z);
    }

    /**
     * A hand that pulls the handle along a scripted path with a spring k (N/m, > 0) and a damper b (N s/m, >= 0):
     * the handle follows the path, and a force on it shows as a lag.
     */
    public static Hand3D followingScript(Script script, double k, double b) {
        if (script == null || !(k > 0) || !(b >= 0) || !Double.isFinite(k) || !Double.isFinite(b)) {
            throw new IllegalArgumentException("Hand3D.followingScript: need a script, k > 0 and b >= 0, got " + script
                    + ", " + k + ", " + b);
        }
        return new Hand3D(script, k, b, 0, 0, 0);
    }

    /** Moves the target of a following hand (metres). */
    public void setTarget(double x, double y, double z) {
        tx = x;
        ty = y;
        tz = z;
    }

    /** True for a rigid scripted hand. */
    public boolean isRigid() {
        return script != null && stiffness == Double.POSITIVE_INFINITY;
    }

    /** True when there is no hand at all. */
    public boolean isNone() {
        return script == null && stiffness == 0;
    }

    /** Writes the target at time t (seconds) into out[0..2]. */
    public void target(double t, double[] out) {
        if (script != null) {
            script.at(t, out);
        } else {
            out[0] = tx;
            out[1] = ty;
            out[2] = tz;
        }
    }

    /** Spring stiffness in N/m (infinite for a rigid hand, 0 for none). */
    public double stiffness() {
        return stiffness;
    }

    /** Damping in N s/m. */
    public double damping() {
        return damping;
    }
}
