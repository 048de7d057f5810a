package tactus.haptics.emulator;

/**
 * The dynamics of an emulated haptic device in joint space, for n = 2 (a pantograph) or 3 joints: joint inertia
 * and a point mass at the handle, M(q) = I_j 1 + m J^T J (m = handle mass + the mass a hand adds); viscous damping
 * on the joints and at the handle, integrated implicitly; Coulomb friction with a static threshold on each joint
 * (Karnopp's model: a joint at rest, |dq| below 1e-4 rad/s, stays at rest while the other torques on it stay below
 * the threshold); motor torques that act {@link PlantParameters#actuationDelay()} after they are commanded; an
 * external task-space force (the hand). Velocities are integrated implicitly in the damping, positions by the
 * trapezoidal rule (so a torque held over a tick moves the handle as the zero-order hold of the theory says, with
 * no half-substep lag). The handle mass's velocity-product term m J^T (dJ/dt) dq is included, from
 * the change of J over the last step. Allocation-free after construction; not thread-safe (its owner locks).
 *
 * <p>Simplifications (see docs/haptics-stability.md): rigid links and transmission, no motor electrical dynamics
 * beyond the actuation delay, the static test of a joint uses the torques on that joint alone (the inertial
 * coupling of the joints is not in the test), and a pose out of reach stops the handle (velocity zeroed).
 */
public final class DevicePlant {
    private static final double STICK_VELOCITY = 1e-4;

    private final PlantParameters p;
    private final PlantKinematics kin;
    private final int n;
    private final double[] q;
    private final double[] qd;
    private final double[] x;
    private final double[] j;
    private final double[] jPrev;
    private final double[] xd;
    private final double[] tau;
    private final double[] pendingTau;
    private double pendingAt = Double.NaN;
    private final double[] a;       // the n x n system
    private final double[] rhs;
    private final double[] other;   // torques other than friction
    private final double[] jdqd;
    private final boolean[] stuck;
    private final double[] qSaved;
    private boolean hasPrevJ;
    private double time;

    /** A plant with these parameters and kinematics, at rest at joint coordinates q0 (radians or metres). */
    public DevicePlant(PlantParameters parameters, PlantKinematics kinematics, double[] q0) {
        if (parameters == null || kinematics == null || q0 == null) {
            throw new IllegalArgumentException("DevicePlant: parameters, kinematics and q0 must not be null");
        }
        n = kinematics.joints();
        if (n < 1 || n > 3 || q0.length < n) {
            throw new IllegalArgumentException("DevicePlant: need 1..3 joints and q0 of that length, got " + n
                    + " joints and " + q0.length + " coordinates");
        }
        p = parameters;
        kin = kinematics;
        q = new double[n];
        qd = new double[n];
        x = new double[n];
        j = new double[n * n];
        jPrev = new double[n * n];
        xd = new double[n];
        tau = new double[n];
        pendingTau = new double[n];
        a = new double[n * n];
        rhs = new double[n];
        other = new double[n];
        jdqd = new double[n];
        stuck = new boolean[n];
        qSaved = new double[n];
        System.arraycopy(q0, 0, q, 0, n);
        if (!kin.forward(q, x, j)) {
            throw new IllegalArgumentException("DevicePlant: the start pose is out of reach");
        }
    }

    /** The parameters. */
    public PlantParameters parameters() {
        return p;
    }

    /** Number of joints. */
    public int joints() {
        return n;
    }

    /** Simulated time in seconds since construction. */
    public double time() {
        return time;
    }

    /** Joint coordinate i (radians or metres). */
    public double q(int i) {
        return q[i];
    }

    /** Joint velocity i (rad/s or m/s). */
    public double qd(int i) {
        return qd[i];
    }

    /** The handle position (metres) into out[0..n-1]. */
    public void position(double[] out) {
        System.arraycopy(x, 0, out, 0, n);
    }

    /** The handle velocity (m/s) into out[0..n-1]. */
    public void velocity(double[] out) {
        System.arraycopy(xd, 0, out, 0, n);
    }

    /** The torque motor i produces now (N m or N). */
    public double motorTorque(int i) {
        return tau[i];
    }

    /**
     * Commands motor torques (N m or N, one per joint): they act after the actuation delay (at once if it is 0), from
     * the first substep that starts at or after it (a delay between two substeps is rounded up to the next). A
     * command still waiting when the next arrives is applied first, so a delay longer than the command period
     * shortens to it.
     */
    public void commandTorques(double[] torques) {
        if (pendingAt == pendingAt) {
            System.arraycopy(pendingTau, 0, tau, 0, n);
        }
        if (p.actuationDelay() > 0) {
            System.arraycopy(torques, 0, pendingTau, 0, n);
            pendingAt = time + p.actuationDelay();
        } else {
            System.arraycopy(torques, 0, tau, 0, n);
            pendingAt = Double.NaN;
        }
    }

    /** Puts the handle at rest at x (metres); returns false (nothing changed) if x is out of reach. */
    public boolean place(double[] target) {
        System.arraycopy(q, 0, qSaved, 0, n);
        if (!kin.inverse(target, q) || !kin.forward(q, x, j)) {
            System.arraycopy(qSaved, 0, q, 0, n);
            kin.forward(q, x, j);
            return false;
        }
        java.util.Arrays.fill(qd, 0);
        java.util.Arrays.fill(xd, 0);
        hasPrevJ = false;
        return true;
    }

    /**
     * Sets the joint coordinates and velocities (radians or metres, per second) directly, for an owner that imposes a
     * constraint the plant does not model (the end of a workspace). Returns false (nothing changed) if out of reach.
     */
    public boolean setState(double[] joints, double[] velocities) {
        System.arraycopy(q, 0, qSaved, 0, n);
        System.arraycopy(joints, 0, q, 0, n);
        if (!kin.forward(q, x, j)) {
            System.arraycopy(qSaved, 0, q, 0, n);
            kin.forward(q, x, j);
            return false;
        }
        System.arraycopy(velocities, 0, qd, 0, n);
        taskVelocity();
        hasPrevJ = false;
        return true;
    }

    /**
     * Moves the handle to x over h seconds whatever the forces (a rigid hand): joint velocities by difference.
     * Returns false (the handle stays, at rest) if x is out of reach.
     */
    public boolean moveRigidly(double[] target, double h) {
        System.arraycopy(q, 0, qSaved, 0, n);
        applyPending();
        time += h;
        if (!kin.inverse(target, q) || !kin.forward(q, x, j)) {
            System.arraycopy(qSaved, 0, q, 0, n);
            kin.forward(q, x, j);
            java.util.Arrays.fill(qd, 0);
            java.util.Arrays.fill(xd, 0);
            return false;
        }
        for (int i = 0; i < n; i++) {
            qd[i] = (q[i] - qSaved[i]) / h;
        }
        taskVelocity();
        hasPrevJ = false;
        return true;
    }

    /**
     * Advances by h seconds (semi-implicit Euler) under the motor torques, an external task-space force (N, the
     * hand's push on the handle) and an added task-space mass (kg, the hand's, moving with the handle).
     */
    public void step(double h, double[] externalForce, double addedMass) {
        applyPending();   // a torque due at the start of this substep acts over all of it (not over the one before)
        time += h;
        double m = p.handleMass() + addedMass;
        // dJ/dt dq from the change of J since the last step
        for (int r = 0; r < n; r++) {
            double s = 0;
            if (hasPrevJ) {
                for (int c = 0; c < n; c++) {
                    s += (j[r * n + c] - jPrev[r * n + c]) / h * qd[c];
                }
            }
            jdqd[r] = s;
        }
        double bj = p.jointDamping();
        double bt = p.taskDamping();
        for (int r = 0; r < n; r++) {
            // torques other than friction and viscous damping: motor + J^T (F_ext - m dJ dq)
            double s = tau[r];
            for (int k = 0; k < n; k++) {
                s += j[k * n + r] * (externalForce[k] - m * jdqd[k]);
            }
            other[r] = s;
            for (int c = 0; c < n; c++) {
                double jtj = 0;
                for (int k = 0; k < n; k++) {
                    jtj += j[k * n + r] * j[k * n + c];
                }
                // (M + h B) with B = b_j 1 + b_t J^T J: viscous damping implicit
                a[r * n + c] = (m + h * bt) * jtj + (r == c ? p.jointInertia() + h * bj : 0);
            }
        }
        for (int r = 0; r < n; r++) {
            double mqd = 0;
            for (int c = 0; c < n; c++) {
                double jtj = 0;
                for (int k = 0; k < n; k++) {
                    jtj += j[k * n + r] * j[k * n + c];
                }
                mqd += (m * jtj + (r == c ? p.jointInertia() : 0)) * qd[c];
            }
            double f = 0;
            double v = qd[r];
            stuck[r] = false;
            if (p.staticTorque() > 0) {
                if (Math.abs(v) < STICK_VELOCITY) {
                    if (Math.abs(other[r]) <= p.staticTorque()) {
                        stuck[r] = true;
                    } else {
                        f = -Math.copySign(p.coulombTorque(), other[r]);   // breaking away: sliding friction
                    }
                } else {
                    f = -Math.copySign(p.coulombTorque(), v);
                }
            }
            rhs[r] = mqd + h * (other[r] + f);
        }
        for (int r = 0; r < n; r++) {
            if (stuck[r]) {   // the joint is held: its row becomes dq_r = 0
                for (int c = 0; c < n; c++) {
                    a[r * n + c] = r == c ? 1 : 0;
                }
                rhs[r] = 0;
            }
        }
        for (int r = 0; r < n; r++) {
            if (!stuck[r]) {
                for (int c = 0; c < n; c++) {
                    if (stuck[c]) {
                        a[r * n + c] = 0;   // a held joint's velocity is 0: its column drops out
                    }
                }
            }
        }
        solve();
        System.arraycopy(q, 0, qSaved, 0, n);
        System.arraycopy(j, 0, jPrev, 0, n * n);
        for (int r = 0; r < n; r++) {
            double v = rhs[r];
            // sliding friction stops a joint, it never reverses it
            if (p.coulombTorque() > 0 && !stuck[r] && v * qd[r] < 0 && Math.abs(qd[r]) >= STICK_VELOCITY
                    && Math.abs(other[r]) <= p.staticTorque()) {
                v = 0;
            }
            q[r] += h * 0.5 * (qd[r] + v);   // trapezoidal: exact for a constant acceleration, no half-step bias
            qd[r] = v;
        }
        if (!kin.forward(q, x, j)) {
            System.arraycopy(qSaved, 0, q, 0, n);   // the linkage reaches the end of its travel
            kin.forward(q, x, j);
            java.util.Arrays.fill(qd, 0);
            hasPrevJ = false;
        } else {
            hasPrevJ = true;
        }
        taskVelocity();
    }

    private void applyPending() {
        if (pendingAt == pendingAt && time >= pendingAt - 1e-12) {
            System.arraycopy(pendingTau, 0, tau, 0, n);
            pendingAt = Double.NaN;
        }
    }

    private void taskVelocity() {
        for (int r = 0; r < n; r++) {
            double s = 0;
            for (int c = 0; c < n; c++) {
                s += j[r * n + c] * qd[c];
            }
            xd[r] = s;
        }
    }

    /** Solves a rhs-in-place system by Gaussian elimination with partial pivoting (n &lt;= 3). */
    private void solve() {
        for (int col = 0; col < n; col++) {
            int piv = col;
            for (int r = col + 1; r < n; r++) {
                if (Math.abs(a[r * n + col]) > Math.abs(a[piv * n + col])) {
                    piv = r;
                }
            }
            if (piv != col) {
                for (int c = 0; c < n; c++) {
                    double t = a[col * n + c];
                    a[col * n + c] = a[piv * n + c];
                    a[piv * n + c] = t;
                }
                double t = rhs[col];
                rhs[col] = rhs[piv];
                rhs[piv] = t;
            }
            double d = a[col * n + col];
            for (int r = col + 1; r < n; r++) {
                double f = a[r * n + col] / d;
                if (f != 0) {
                    for (int c = col; c < n; c++) {
                        a[r * n + c] -= f * a[col * n + c];
                    }
                    rhs[r] -= f * rhs[col];
                }
            }
        }
        for (int r = n - 1; r >= 0; r--) {
            double s = rhs[r];
            for (int c = r + 1; c < n; c++) {
                s -= a[r * n + c] * rhs[c];
            }
            rhs[r] = s / a[r * n + r];
        }
    }
}
