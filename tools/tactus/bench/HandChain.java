package tactus.bench;

/**
 * The reference for the engine's overhead: a hand-written, minimal step loop for the springs-only chain, on plain
 * structure-of-arrays state. Nodes 0 and n + 1 are the fixed ends; nodes 1..n are the inertial masses. One step is
 * the explicit scheme of the engine, written out directly:
 * <pre>
 *   masses:  X(n+1) = 2 X(n) - X(n-1) + F / M          (then F = 0)
 *   springs: d = |X_a - X_b|,  f = -K (d - l0),  F_a += f (X_a - X_b) / d,  F_b -= f (X_a - X_b) / d
 * </pre>
 * Two flavours: with per-element parameter arrays (1/M per mass, K and l0 per spring: the same data a general
 * engine has to read), and with the three parameters as constants (the fastest a uniform chain can be written).
 * No divergence guard, no locking, no kernels: just the two loops.
 */
final class HandChain implements Workload {
    private final int n;
    private final boolean constants;
    private final double[] x;
    private final double[] y;
    private final double[] z;
    private final double[] px;
    private final double[] py;
    private final double[] pz;
    private final double[] fx;
    private final double[] fy;
    private final double[] fz;
    private final double[] invM;
    private final double[] k;
    private final double[] l0;
    private final double kc;
    private final double l0c;
    private final double imc;

    /**
     * @param n inertial masses (the chain has n + 2 nodes and n + 1 springs)
     * @param constants true for uniform parameters folded into constants, false for per-element arrays
     */
    HandChain(int n, boolean constants) {
        this.n = n;
        this.constants = constants;
        int nodes = n + 2;
        x = new double[nodes];
        y = new double[nodes];
        z = new double[nodes];
        px = new double[nodes];
        py = new double[nodes];
        pz = new double[nodes];
        fx = new double[nodes];
        fy = new double[nodes];
        fz = new double[nodes];
        invM = new double[nodes];
        k = new double[n + 1];
        l0 = new double[n + 1];
        for (int i = 0; i < nodes; i++) {
            double[] p = Scenes.chainNode(i, n);
            x[i] = p[0];
            y[i] = p[1];
            z[i] = p[2];
            px[i] = p[0];
            py[i] = p[1];
            pz[i] = p[2];
            invM[i] = (i == 0 || i == n + 1) ? 0.0 : 1.0 / Scenes.CHAIN_M;
        }
        for (int j = 0; j <= n; j++) {
            k[j] = Scenes.CHAIN_K;
            l0[j] = Scenes.CHAIN_L0;
        }
        kc = Scenes.CHAIN_K;
        l0c = Scenes.CHAIN_L0;
        imc = 1.0 / Scenes.CHAIN_M;
    }

    @Override
    public String variant() {
        return constants ? "hand loop, constants" : "hand loop, parameter arrays";
    }

    @Override
    public long elements() {
        return 2L * n + 1;
    }

    @Override
    public void advance(int steps) {
        if (constants) {
            for (int s = 0; s < steps; s++) {
                stepConstants();
            }
        } else {
            for (int s = 0; s < steps; s++) {
                stepArrays();
            }
        }
    }

    /** One step with per-element parameters. */
    void stepArrays() {
        final double[] x = this.x, y = this.y, z = this.z, px = this.px, py = this.py, pz = this.pz;
        final double[] fx = this.fx, fy = this.fy, fz = this.fz, im = invM, k = this.k, l0 = this.l0;
        final int n = this.n;
        for (int i = 1; i <= n; i++) {
            double xi = x[i], yi = y[i], zi = z[i], m = im[i];
            x[i] = 2 * xi - px[i] + fx[i] * m;
            y[i] = 2 * yi - py[i] + fy[i] * m;
            z[i] = 2 * zi - pz[i] + fz[i] * m;
            px[i] = xi;
            py[i] = yi;
            pz[i] = zi;
            fx[i] = 0;
            fy[i] = 0;
            fz[i] = 0;
        }
        fx[0] = fy[0] = fz[0] = 0;
        fx[n + 1] = fy[n + 1] = fz[n + 1] = 0;
        for (int j = 0; j <= n; j++) {
            int b = j + 1;
            double dx = x[j] - x[b], dy = y[j] - y[b], dz = z[j] - z[b];
            double d = Math.sqrt(dx * dx + dy * dy + dz * dz);
            double s = -k[j] * (d - l0[j]) / d;
            fx[j] += s * dx;
            fy[j] += s * dy;
            fz[j] += s * dz;
            fx[b] -= s * dx;
            fy[b] -= s * dy;
            fz[b] -= s * dz;
        }
    }

    /** One step with the parameters as constants. */
    void stepConstants() {
        final double[] x = this.x, y = this.y, z = this.z, px = this.px, py = this.py, pz = this.pz;
        final double[] fx = this.fx, fy = this.fy, fz = this.fz;
        final double kc = this.kc, l0c = this.l0c, m = imc;
        final int n = this.n;
        for (int i = 1; i <= n; i++) {
            double xi = x[i], yi = y[i], zi = z[i];
            x[i] = 2 * xi - px[i] + fx[i] * m;
            y[i] = 2 * yi - py[i] + fy[i] * m;
            z[i] = 2 * zi - pz[i] + fz[i] * m;
            px[i] = xi;
            py[i] = yi;
            pz[i] = zi;
            fx[i] = 0;
            fy[i] = 0;
            fz[i] = 0;
        }
        fx[0] = fy[0] = fz[0] = 0;
        fx[n + 1] = fy[n + 1] = fz[n + 1] = 0;
        for (int j = 0; j <= n; j++) {
            int b = j + 1;
            double dx = x[j] - x[b], dy = y[j] - y[b], dz = z[j] - z[b];
            double d = Math.sqrt(dx * dx + dy * dy + dz * dz);
            double s = -kc * (d - l0c) / d;
            fx[j] += s * dx;
            fy[j] += s * dy;
            fz[j] += s * dz;
            fx[b] -= s * dx;
            fy[b] -= s * dy;
            fz[b] -= s * dz;
        }
    }

    /** Writes the position of node i (0 and n + 1 are the fixed ends) into out[0..2]. */
    void position(int i, double[] out) {
        out[0] = x[i];
        out[1] = y[i];
        out[2] = z[i];
    }

    @Override
    public double probe() {
        return y[(n + 1) / 3];
    }

    @Override
    public Object model() {
        return null;
    }
}
