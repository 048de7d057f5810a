package tactus.io;

/**
 * Chooses the velocity to write for one coordinate so that a loader which rebuilds the delayed
 * position as {@code X - v / fs} (Tactus and the paper's engine both do) gets back the exact delayed
 * position the model had, not one a rounding away. The model only reports its velocity
 * {@code (X - XR) * fs}; the delayed position XR is recovered as the value near {@code X - v / fs}
 * that reports the same velocity and that a loader can reach.
 */
final class VelocityCodec {
    /** How many neighbouring doubles to try on each side; one or two always suffice in practice. */
    private static final int REACH = 16;

    private VelocityCodec() {
    }

    /**
     * @param x the current coordinate X
     * @param velocity the velocity the model reports, {@code (X - XR) * fs}
     * @param fs the simulation rate
     * @return a velocity v with {@code x - v / fs == XR}, or {@code velocity} itself when none is found
     */
    static double encode(double x, double velocity, double fs) {
        if (velocity == 0 || !Double.isFinite(velocity)) {
            return velocity;
        }
        double guess = x - velocity / fs;
        double up = guess, down = guess;
        for (int k = 0; k <= REACH; k++) {
            double v = reachable(x, up, velocity, fs);
            if (!Double.isNaN(v)) {
                return v;
            }
            v = reachable(x, down, velocity, fs);
            if (!Double.isNaN(v)) {
                return v;
            }
            up = Math.nextUp(up);
            down = Math.nextDown(down);
        }
        return velocity;
    }

    /**
     * @param x the current coordinate X
     * @param xr the delayed coordinate XR, exactly as the model holds it
     * @param fs the simulation rate
     * @return a velocity v with {@code x - v / fs == xr}, or {@code (x - xr) * fs} when none is found
     */
    static double fromDelayed(double x, double xr, double fs) {
        double v = reachable(x, xr, (x - xr) * fs, fs);
        return Double.isNaN(v) ? (x - xr) * fs : v;
    }

    /** @return a velocity that rebuilds {@code xr} if {@code xr} reports {@code velocity}, else NaN. */
    private static double reachable(double x, double xr, double velocity, double fs) {
        if ((x - xr) * fs != velocity) {
            return Double.NaN;
        }
        double v = (x - xr) * fs;
        double up = v, down = v;
        for (int k = 0; k <= REACH; k++) {
            if (x - up / fs == xr) {
                return up;
            }
            if (x - down / fs == xr) {
                return down;
            }
            up = Math.nextUp(up);
            down = Math.nextDown(down);
        }
        return Double.NaN;
    }
}
