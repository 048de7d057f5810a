package tactus.haptics.emulator;

/**
 * A simulated 3-DoF Inverse3 handle for the {@link InverseServiceEmulator}: a point mass (0.25 kg by default)
 * with viscous damping (1 N s/m), pushed by the commanded cursor force and by a {@link Hand3D}, kept inside a
 * box workspace (the handle stops at a wall: its outward velocity is removed). The device compensates gravity,
 * as the service does by default. Positions in metres, in the service's axes; the workspace is an approximation
 * around the home position of Haply's documented snapshot, not Haply's published figures. {@link #setPlant} replaces
 * the point mass with a Cartesian {@link DevicePlant} (per-axis inertia, damping, Coulomb friction with a static
 * threshold, actuation delay). Thread-safe.
 */
public final class SimulatedInverse3 {
    /** The home position: the cursor position of the snapshot in Haply's WebSocket protocol page (metres). */
    public static final double[] HOME = {0.0, -0.12, 0.15};
    /** Half-size of the box workspace around {@link #HOME} along x, y, z (metres). */
    public static final double[] HALF_EXTENT = {0.12, 0.10, 0.10};
    /** Longest integration step (seconds); longer steps are split. */
    static final double MAX_STEP = 2.5e-4;

    private final double mass;
    private final double damping;
    private volatile Hand3D hand = Hand3D.none();
    private final double[] p = HOME.clone();
    private final double[] v = new double[3];
    private final double[] f = new double[3];     // commanded force (N)
    private final double[] target = new double[3];
    private final double[] prevTarget = new double[3];
    private double time;
    private boolean started;
    private DevicePlant plant;                    // null: the point mass
    private final double[] handPush = new double[3];

    /** A handle of 0.25 kg with 1 N s/m of damping, at {@link #HOME}, with no hand. */
    public SimulatedInverse3() {
        this(0.25, 1.0);
    }

    /** A handle of this mass (kg, > 0) and damping (N s/m, >= 0), at {@link #HOME}, with no hand. */
    public SimulatedInverse3(double mass, double damping) {
        if (!(mass > 0) || !(damping >= 0)) {
            throw new IllegalArgumentException("SimulatedInverse3: need mass > 0 kg and damping >= 0 N s/m, got " + mass
                    + ", " + damping);
        }
        this.mass = mass;
        this.damping = damping;
    }

    /**
     * Replaces the point mass with a 3-axis Cartesian {@link DevicePlant} of these parameters (joint = axis: kg,
     * N s/m, N), at the present position, at rest; the commanded force becomes its motor force. The plant's substep
     * caps the integration step.
     */
    public synchronized void setPlant(PlantParameters parameters) {
        if (parameters == null) {
            throw new IllegalArgumentException("SimulatedInverse3.setPlant: parameters must not be null");
        }
        plant = new DevicePlant(parameters, new CartesianPlantKinematics(3), p);
        plant.commandTorques(f);
        v[0] = 0;
        v[1] = 0;
        v[2] = 0;
    }

    /** What a probe is told at every integration step of a plant ({@link #setPlant}) pushed by a hand. */
    public interface Probe {
        /**
         * One integration step: its end time (s), the handle's position (m) and velocity (m/s) at its end, and the
         * force the hand put on the handle over it (N). Called on the thread that advances the device; must not
         * allocate or block.
         */
        void sample(double t, double[] position, double[] velocity, double[] handForce);
    }

    private volatile Probe probe;

    /** Sets a probe called at every integration step of the plant (null for none). */
    public void setProbe(Probe p) {
        probe = p;
    }

    /** Sets the hand (never null: {@link Hand3D#none()} for none). */
    public void setHand(Hand3D h) {
        if (h == null) {
            throw new IllegalArgumentException("SimulatedInverse3.setHand: use Hand3D.none() for no hand");
        }
        hand = h;
    }

    /** The hand. */
    public Hand3D hand() {
        return hand;
    }

    /** Sets the commanded cursor force in newtons (non-finite components count as 0). */
    public synchronized void setForce(double fx, double fy, double fz) {
        f[0] = Double.isFinite(fx) ? fx : 0;
        f[1] = Double.isFinite(fy) ? fy : 0;
        f[2] = Double.isFinite(fz) ? fz : 0;
        if (plant != null) {
            plant.commandTorques(f);   // acts after the plant's actuation delay
        }
    }

    /** The commanded force (N) into out[0..2]. */
    public synchronized void force(double[] out) {
        out[0] = f[0];
        out[1] = f[1];
        out[2] = f[2];
    }

    /** Puts the handle at rest at this position (metres), clamped to the workspace. */
    public synchronized void place(double x, double y, double z) {
        p[0] = x;
        p[1] = y;
        p[2] = z;
        v[0] = 0;
        v[1] = 0;
        v[2] = 0;
        clamp();
        if (plant != null) {
            plant.setState(p, v);
        }
    }

    /** The handle position (metres) into out[0..2]. */
    public synchronized void position(double[] out) {
        out[0] = p[0];
        out[1] = p[1];
        out[2] = p[2];
    }

    /** The handle velocity (m/s) into out[0..2]. */
    public synchronized void velocity(double[] out) {
        out[0] = v[0];
        out[1] = v[1];
        out[2] = v[2];
    }

    /** Simulated time in seconds. */
    public synchronized double time() {
        return time;
    }

    /** Advances the simulation by dt seconds (split into steps of at most 0.25 ms). */
    public synchronized void advance(double dt) {
        if (!(dt > 0)) {
            return;
        }
        double maxStep = plant != null ? Math.min(MAX_STEP, plant.parameters().substep()) : MAX_STEP;
        int n = (int) Math.ceil(dt / maxStep);
        double h = dt / n;
        Hand3D hd = hand;
        for (int s = 0; s < n; s++) {
            time += h;
            if (plant != null && !hd.isRigid()) {
                stepPlant(hd, h);
            } else if (hd.isRigid()) {
                hd.target(time, target);
                if (!started) {
                    prevTarget[0] = target[0];
                    prevTarget[1] = target[1];
                    prevTarget[2] = target[2];
                }
                for (int i = 0; i < 3; i++) {
                    v[i] = (target[i] - prevTarget[i]) / h;
                    p[i] = target[i];
                    prevTarget[i] = target[i];
                }
            } else {
                double k = hd.stiffness();
                double b = hd.damping();
                if (k > 0) {
                    hd.target(time, target);
                }
                for (int i = 0; i < 3; i++) {
                    double handForce = k > 0 ? k * (target[i] - p[i]) - b * v[i] : 0;
                    double a = (f[i] + handForce - damping * v[i]) / mass;
                    v[i] += a * h;
                    p[i] += v[i] * h;
                }
            }
            started = true;
            clamp();
            if (plant != null && hd.isRigid()) {
                plant.setState(p, v);   // the hand carries the plant along
            }
        }
    }

    private void stepPlant(Hand3D hd, double h) {
        double k = hd.stiffness();
        double b = hd.damping();
        if (k > 0) {
            hd.target(time, target);
        }
        for (int i = 0; i < 3; i++) {
            handPush[i] = k > 0 ? k * (target[i] - p[i]) - b * v[i] : 0;
        }
        plant.step(h, handPush, 0);
        plant.position(p);
        plant.velocity(v);
        started = true;
        if (clamp()) {
            plant.setState(p, v);
        }
        Probe pr = probe;
        if (pr != null) {
            pr.sample(time, p, v, handPush);
        }
    }

    /** Keeps the handle in the box; returns true if it had to move it. */
    private boolean clamp() {
        boolean moved = false;
        for (int i = 0; i < 3; i++) {
            double lo = HOME[i] - HALF_EXTENT[i];
            double hi = HOME[i] + HALF_EXTENT[i];
            if (p[i] < lo) {
                p[i] = lo;
                moved = true;
                if (v[i] < 0) {
                    v[i] = 0;
                }
            } else if (p[i] > hi) {
                p[i] = hi;
                moved = true;
                if (v[i] > 0) {
                    v[i] = 0;
                }
            }
        }
        return moved;
    }
}
