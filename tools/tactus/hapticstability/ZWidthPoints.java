package tactus.hapticstability;

import java.util.Arrays;

/**
 * The points of one variant's Z-width curve as the plot draws them, from what the sweep measured with a hand at each
 * wall damping B: the stiffness the hand felt at the stiffest wall of the scan that stayed stable, and whether that
 * wall was the scan's top (then the edge lies higher and the point is a lower bound, drawn as an arrow). A damping at
 * which no wall of the scan was stable has no point; a variant with no point of a kind gets no series of that kind.
 */
final class ZWidthPoints {
    /** Damping (N s/m) and felt stiffness (N/m) of the points whose edge was found inside the scan. */
    final double[] edgeB;
    final double[] edgeFelt;
    /** Damping (N s/m) and felt stiffness (N/m) of the points still stable at the scan's top: lower bounds. */
    final double[] boundB;
    final double[] boundFelt;

    private ZWidthPoints(double[] edgeB, double[] edgeFelt, double[] boundB, double[] boundFelt) {
        this.edgeB = edgeB;
        this.edgeFelt = edgeFelt;
        this.boundB = boundB;
        this.boundFelt = boundFelt;
    }

    /**
     * Sorts the measured points.
     *
     * @param b          the wall damping of each point, N s/m
     * @param lastStable the stiffest stable wall of the scan at each damping, N/m (0 or NaN: none was stable)
     * @param felt       the stiffness the hand felt at that wall, N/m (NaN: not measured)
     * @param scanTop    the scan's stiffest wall, N/m: a last stable wall at or above it is a lower bound
     */
    static ZWidthPoints of(double[] b, double[] lastStable, double[] felt, double scanTop) {
        double[] eb = new double[b.length];
        double[] ef = new double[b.length];
        double[] lb = new double[b.length];
        double[] lf = new double[b.length];
        int ne = 0;
        int nl = 0;
        for (int i = 0; i < b.length; i++) {
            if (!(lastStable[i] > 0) || !(felt[i] > 0) || !Double.isFinite(felt[i])) {
                continue;
            }
            if (lastStable[i] >= scanTop * (1 - 1e-9)) {
                lb[nl] = b[i];
                lf[nl++] = felt[i];
            } else {
                eb[ne] = b[i];
                ef[ne++] = felt[i];
            }
        }
        return new ZWidthPoints(Arrays.copyOf(eb, ne), Arrays.copyOf(ef, ne), Arrays.copyOf(lb, nl),
                Arrays.copyOf(lf, nl));
    }
}
