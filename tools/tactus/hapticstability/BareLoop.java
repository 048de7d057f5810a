package tactus.hapticstability;

import tactus.haptics.emulator.CartesianPlantKinematics;
import tactus.haptics.emulator.DevicePlant;
import tactus.haptics.emulator.PlantParameters;

/**
 * The sampled loop of the theory run directly on a one-axis {@link DevicePlant} (no protocol, no haptic loop):
 * every period T the wall force F = -K x - B (x - x_prev) / T is computed from the position sampled d ticks
 * earlier and held for one period. It checks the theory's method (including d = 0, which the Haply protocol
 * cannot produce: its reply always carries the position of the previous write) and the plant's integration.
 */
public final class BareLoop {
    private BareLoop() {
    }

    /**
     * Runs a step of 1 mm against a two-sided wall for the given time and returns the RMS of the position over the
     * last third divided by the first third's (> 1: growing).
     */
    public static double growth(double m, double b, double T, int d, double K, double B, double seconds) {
        PlantParameters p = PlantParameters.cartesian3Dof().withoutFriction().withJointInertia(m).withJointDamping(b)
                .withSubstep(T / 20);
        DevicePlant pl = new DevicePlant(p, new CartesianPlantKinematics(1), new double[] {0.001});
        int ticks = (int) Math.round(seconds / T);
        double[] hist = new double[d + 2];
        java.util.Arrays.fill(hist, 0.001);
        double[] f = new double[1];
        double[] none = new double[1];
        double h = T / 20;
        double s1 = 0;
        double s3 = 0;
        int third = ticks / 3;
        for (int k = 0; k < ticks; k++) {
            System.arraycopy(hist, 0, hist, 1, d + 1);
            hist[0] = pl.q(0);
            double xs = hist[d];
            double xp = hist[d + 1];
            f[0] = -K * xs - B * (xs - xp) / T;
            pl.commandTorques(f);
            for (int s = 0; s < 20; s++) {
                pl.step(h, none, 0);
            }
            double e = pl.q(0);
            if (k < third) {
                s1 += e * e;
            } else if (k >= ticks - third) {
                s3 += e * e;
            }
        }
        return Math.sqrt(s3 / s1);
    }

    /** The largest stable K by bisection between lo (stable) and hi (unstable), to a relative tolerance. */
    public static double boundary(double m, double b, double T, int d, double B, double lo, double hi, double tol,
                                  double seconds) {
        while (hi - lo > tol * hi) {
            double mid = 0.5 * (lo + hi);
            if (growth(m, b, T, d, mid, B, seconds) < 1) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        return 0.5 * (lo + hi);
    }
}
