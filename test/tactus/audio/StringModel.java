package tactus.audio;

import tactus.PhysicalModel;
import tactus.Vect3D;

/**
 * The paper's plucked string, for the audio tests: N Mass2DPlane masses of mass M, spacing D along x,
 * between two Ground3D ends, joined by SpringDamper3D links (stiffness K, rest length L0 &lt; D, so the string
 * is under tension; no damping). Small transverse (y) motion is then linear with a transverse stiffness
 * k_t = K (1 - L0 / D) per link, and the explicit scheme gives mode m the exact discrete frequency
 * cos(w_m) = 1 - 2 (k_t / M) sin^2(m pi / (2 (N + 1))).
 */
final class StringModel {
    static final int N = 30;
    static final double M = 1;
    static final double D = 0.1;
    static final double K = 0.2;
    static final double L0 = 0.05;

    private StringModel() {
    }

    /** Transverse stiffness per link. */
    static double transverseStiffness() {
        return K * (1 - L0 / D);
    }

    /** @return the frequency of mode m (1-based) in Hz at a step rate. */
    static double modeHz(int m, double stepRate) {
        double s = Math.sin(m * Math.PI / (2.0 * (N + 1)));
        double cosW = 1 - 2 * (transverseStiffness() / M) * s * s;
        return Math.acos(cosW) * stepRate / (2 * Math.PI);
    }

    /** Mass name of index i (1..N); "g0" and "g(N+1)" are the grounds. */
    static String mass(int i) {
        return i == 0 || i == N + 1 ? "g" + i : "m" + i;
    }

    /**
     * Adds the string to a model, plucked into a triangle of height {@code pluck} (y) with its apex at mass
     * {@code apex}; call init() afterwards.
     */
    static void build(PhysicalModel pm, int apex, double pluck) {
        pm.addGround3D(mass(0), new Vect3D(0, 0, 0));
        for (int i = 1; i <= N; i++) {
            double y = i <= apex ? pluck * i / apex : pluck * (N + 1 - i) / (N + 1 - apex);
            pm.addMass2DPlane(mass(i), M, new Vect3D(i * D, y, 0), new Vect3D());
        }
        pm.addGround3D(mass(N + 1), new Vect3D((N + 1) * D, 0, 0));
        for (int i = 0; i <= N; i++) {
            pm.addSpringDamper3D("s" + i, L0, K, 0, mass(i), mass(i + 1));
        }
    }
}
