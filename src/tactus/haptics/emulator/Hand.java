package tactus.haptics.emulator;

/**
 * The hand that holds the emulated handle: a target position in metres (device coordinates: x from motor 1
 * towards motor 2, y into the workspace) and how stiffly the handle follows it. A rigid hand puts the handle
 * exactly on the target whatever the motors do; a compliant hand pulls it with a spring and damper, so the
 * motors' force moves the handle. A grasp ({@link #grasp}) is the lumped model of a hand holding a pen or a knob:
 * a mass that moves with the handle, tied to the intended motion (scripted) by a spring and a damper that acts
 * on the velocity relative to the intended motion. With {@link #none()} nothing holds the handle.
 */
public final class Hand {
    /** A scripted path: the target position at time t seconds, written into out[0] (x) and out[1] (y), metres. */
    public interface Script {
        /** Writes the target at time t (seconds since the emulator started) into out. */
        void at(double t, double[] out);
    }

    private final Script script;
    private final double stiffness;
    private final double damping;
    private final double mass;
    private final boolean relativeDamping;
    private volatile double targetX;
    private volatile double targetY;

    private Hand(Script script, double stiffness, double damping, double x, double y) {
        this(script, stiffness, damping, 0, false, x, y);
    }

    private Hand(Script script, double stiffness, double damping, double mass, boolean relativeDamping, double x,
                 double y) {
        this.script = script;
        this.stiffness = stiffness;
        this.damping = damping;
        this.mass = mass;
        this.relativeDamping = relativeDamping;
        this.targetX = x;
        this.targetY = y;
    }

    /** No hand: the handle moves only under the motors, its own friction and the end of its travel. */
    public static Hand none() {
        return new Hand(null, 0, 0, 0, 0);
    }

    /**
     * A grasp: a hand mass m (kg, >= 0) that moves with the handle, pulled along the intended motion (a script, in
     * metres) by a spring k (N/m, > 0) and a damper b (N s/m, >= 0) on the velocity relative to that motion.
     * Pen and knob grips measured in the literature span roughly m 0.01-0.2 kg, k 100-1000 N/m, b 1-10 N s/m
     * (see docs/haptics-stability.md).
     */
    public static Hand grasp(Script intended, double m, double k, double b) {
        if (intended == null) {
            throw new IllegalArgumentException("Hand.grasp: the intended motion must not be null");
        }
        checkGains("Hand.grasp", k, b);
        if (!(m >= 0) || !Double.isFinite(m)) {
            throw new IllegalArgumentException("Hand.grasp: mass m must be a finite number >= 0 kg, got " + m);
        }
        return new Hand(intended, k, b, m, true, 0, 0);
    }

    /** A rigid hand that moves the handle along a script. */
    public static Hand scripted(Script script) {
        if (script == null) {
            throw new IllegalArgumentException("Hand.scripted: script must not be null");
        }
        return new Hand(script, Double.POSITIVE_INFINITY, 0, 0, 0);
    }

    /**
     * A hand that pulls the handle towards a fixed point (x, y) in metres with a spring of stiffness k (N/m,
     * > 0) and damping b (N s/m, >= 0).
     */
    public static Hand spring(double x, double y, double k, double b) {
        checkGains("Hand.spring", k, b);
        return new Hand(null, k, b, x, y);
    }

    /**
     * A hand that follows a target set with {@link #setTarget} (for instance the mouse in a sketch) through a
     * spring k (N/m, > 0, or infinity for rigid) and damper b (N s/m).
     */
    public static Hand following(double x, double y, double k, double b) {
        checkGains("Hand.following", k, b);
        return new Hand(null, k, b, x, y);
    }

    private static void checkGains(String op, double k, double b) {
        if (!(k > 0)) {
            throw new IllegalArgumentException(op + ": stiffness k must be > 0 N/m, got " + k);
        }
        if (!(b >= 0) || !Double.isFinite(b)) {
            throw new IllegalArgumentException(op + ": damping b must be a finite number >= 0 N s/m, got " + b);
        }
    }

    /** Moves the target (metres); used by a following hand. */
    public void setTarget(double x, double y) {
        targetX = x;
        targetY = y;
    }

    /** True if the handle is put exactly on the target. */
    public boolean isRigid() {
        return stiffness == Double.POSITIVE_INFINITY;
    }

    /** Spring stiffness in N/m (infinity when rigid). */
    public double stiffness() {
        return stiffness;
    }

    /** Damping in N s/m. */
    public double damping() {
        return damping;
    }

    /** The hand's mass that moves with the handle, in kg (0 except for a grasp). */
    public double mass() {
        return mass;
    }

    /** True if the damper acts on the velocity relative to the target's (a grasp), false if on the handle's. */
    public boolean dampsRelativeVelocity() {
        return relativeDamping;
    }

    /** True for {@link #none()}: no force on the handle. */
    public boolean isNone() {
        return stiffness == 0 && damping == 0 && mass == 0;
    }

    void target(double t, double[] out) {
        if (script != null) {
            script.at(t, out);
        } else {
            out[0] = targetX;
            out[1] = targetY;
        }
    }
}
