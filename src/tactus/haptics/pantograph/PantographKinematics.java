package tactus.haptics.pantograph;

/**
 * Kinematics of the Haply 2-DoF pantograph (a symmetric five-bar linkage), in double precision.
 *
 * <p>Motor 1 sits at the origin, motor 2 at (d, 0). Proximal links have length l, distal links length L
 * (metres). x points from motor 1 towards motor 2, y into the workspace. Angles are joint angles in
 * radians, measured from the +x axis. The end effector is the intersection of the two distal circles on
 * the side reached by turning elbow A towards elbow B by +90 degrees.
 *
 * <p>Instances are mutable and not thread-safe; {@link #forward} and {@link #torques} allocate nothing.
 */
public final class PantographKinematics {
    private double l;
    private double bigL;
    private double d;

    // Results of the last forward() call.
    private double x;
    private double y;
    private double jxx; // dx/dth1
    private double jxy; // dx/dth2
    private double jyx; // dy/dth1
    private double jyy; // dy/dth2
    private boolean valid;

    /**
     * Creates the kinematics of a pantograph.
     *
     * @param l proximal link length in metres (> 0)
     * @param bigL distal link length in metres (> 0)
     * @param d distance between the motor axes in metres (>= 0)
     */
    public PantographKinematics(double l, double bigL, double d) {
        setParameters(l, bigL, d);
    }

    /** Sets the link lengths l, L and the motor spacing d, in metres; rejects non-finite or non-positive lengths. */
    public void setParameters(double l, double bigL, double d) {
        if (!(l > 0) || !Double.isFinite(l)) {
            throw new IllegalArgumentException("pantograph: l (proximal link) must be a finite length > 0 m, got " + l);
        }
        if (!(bigL > 0) || !Double.isFinite(bigL)) {
            throw new IllegalArgumentException("pantograph: L (distal link) must be a finite length > 0 m, got " + bigL);
        }
        if (!(d >= 0) || !Double.isFinite(d)) {
            throw new IllegalArgumentException("pantograph: d (motor spacing) must be a finite length >= 0 m, got " + d);
        }
        this.l = l;
        this.bigL = bigL;
        this.d = d;
        this.valid = false;
    }

    /** Proximal link length l in metres. */
    public double l() {
        return l;
    }

    /** Distal link length L in metres. */
    public double bigL() {
        return bigL;
    }

    /** Motor spacing d in metres. */
    public double d() {
        return d;
    }

    /**
     * Computes the end-effector position and the Jacobian for joint angles th1, th2 (radians).
     *
     * @return true if the pose is reachable; false (position and Jacobian NaN) if the distal circles do
     *         not meet or the linkage is singular
     */
    public boolean forward(double th1, double th2) {
        double c1 = Math.cos(th1);
        double s1 = Math.sin(th1);
        double c2 = Math.cos(th2);
        double s2 = Math.sin(th2);
        double ax = l * c1;
        double ay = l * s1;
        double bx = d + l * c2;
        double by = l * s2;
        double hx = bx - ax;
        double hy = by - ay;
        double h2 = hx * hx + hy * hy;
        double rest = bigL * bigL - h2 / 4;
        if (!(h2 > 0) || !(rest > 0)) {
            invalidate();
            return false;
        }
        double h = Math.sqrt(h2);
        double k = Math.sqrt(rest) / h;
        x = (ax + bx) / 2 - k * hy;
        y = (ay + by) / 2 + k * hx;
        // Distal angles from the elbows to the end effector.
        double phi1 = Math.atan2(y - ay, x - ax);
        double phi2 = Math.atan2(y - by, x - bx);
        double s21 = Math.sin(phi2 - phi1);
        if (Math.abs(s21) < 1e-12) {
            invalidate();
            return false;
        }
        // Closure of the loop: l e(th1) + L e(phi1) = (d,0) + l e(th2) + L e(phi2); differentiate and
        // solve for dphi1/dth1 and dphi1/dth2.
        double dphi1dth1 = l * Math.sin(th1 - phi2) / (bigL * s21);
        double dphi1dth2 = l * Math.sin(phi2 - th2) / (bigL * s21);
        double sp1 = Math.sin(phi1);
        double cp1 = Math.cos(phi1);
        jxx = -l * s1 - bigL * sp1 * dphi1dth1;
        jyx = l * c1 + bigL * cp1 * dphi1dth1;
        jxy = -bigL * sp1 * dphi1dth2;
        jyy = bigL * cp1 * dphi1dth2;
        valid = true;
        return true;
    }

    private void invalidate() {
        x = y = Double.NaN;
        jxx = jxy = jyx = jyy = Double.NaN;
        valid = false;
    }

    /** True if the last {@link #forward} call found a reachable pose. */
    public boolean isValid() {
        return valid;
    }

    /** End-effector x of the last {@link #forward} call, in metres. */
    public double x() {
        return x;
    }

    /** End-effector y of the last {@link #forward} call, in metres. */
    public double y() {
        return y;
    }

    /** Jacobian entry d(row)/d(theta col) of the last forward call, row 0 = x, 1 = y, col 0 = th1, 1 = th2 (m/rad). */
    public double jacobian(int row, int col) {
        if (row == 0) {
            return col == 0 ? jxx : jxy;
        }
        return col == 0 ? jyx : jyy;
    }

    /**
     * The largest change of x and y (m) at the pose of the last {@link #forward} call when joint 1 moves by at most
     * step1 and joint 2 by at most step2 (radians, &gt;= 0), to first order: |J| times the steps, into out[0], out[1].
     */
    public void quantum(double step1, double step2, double[] out) {
        out[0] = Math.abs(jxx) * step1 + Math.abs(jxy) * step2;
        out[1] = Math.abs(jyx) * step1 + Math.abs(jyy) * step2;
    }

    /**
     * Joint torques tau = gain * J^T F for a task-space force (fx, fy) in newtons at the pose of the last
     * {@link #forward} call; writes tau1, tau2 (N m times gain) into out[0], out[1].
     */
    public void torques(double fx, double fy, double gain, double[] out) {
        out[0] = gain * (jxx * fx + jyx * fy);
        out[1] = gain * (jxy * fx + jyy * fy);
    }

    /**
     * Task-space force F = J^-T tau that joint torques tau1, tau2 (N m) exert on the end effector at the
     * pose of the last {@link #forward} call; writes Fx, Fy (N) into out. NaN at a singular pose.
     */
    public void forceFromTorques(double tau1, double tau2, double[] out) {
        // J^T = [[jxx, jyx], [jxy, jyy]]; solve J^T F = tau.
        double det = jxx * jyy - jyx * jxy;
        out[0] = (jyy * tau1 - jyx * tau2) / det;
        out[1] = (-jxy * tau1 + jxx * tau2) / det;
    }

    /**
     * Inverse kinematics: the joint angles (radians) that put the end effector at (px, py) with the
     * elbows out (elbow A left of motor 1's reach line, elbow B right of motor 2's); writes th1, th2 into
     * out. Returns false (out unchanged) if the point is out of reach.
     */
    public boolean inverse(double px, double py, double[] out) {
        double r1 = Math.hypot(px, py);
        double r2 = Math.hypot(px - d, py);
        double c1 = (l * l + r1 * r1 - bigL * bigL) / (2 * l * r1);
        double c2 = (l * l + r2 * r2 - bigL * bigL) / (2 * l * r2);
        if (!(r1 > 0) || !(r2 > 0) || !(Math.abs(c1) <= 1) || !(Math.abs(c2) <= 1)) {
            return false;
        }
        out[0] = Math.atan2(py, px) + Math.acos(c1);
        out[1] = Math.atan2(py, px - d) - Math.acos(c2);
        return true;
    }
}
