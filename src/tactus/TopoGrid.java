package tactus;

import java.util.ArrayList;
import java.util.EnumSet;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;

/**
 * The geometry behind {@link TopoGenerator}: the names of the grid masses, the neighbour
 * offsets each mass links to, and the masses that a set of {@link Bound}s fixes. Pure
 * arithmetic, no model access.
 */
final class TopoGrid {
    private TopoGrid() {
    }

    /** @return the name of the mass at grid point (i, j, k): {@code prefix_i_j_k}. */
    static String massName(String prefix, int i, int j, int k) {
        return prefix + "_" + i + "_" + j + "_" + k;
    }

    /**
     * @return the name the paper's engine gives every link that starts at grid point (i, j, k):
     * the mass prefix, "1_", then i, j and k written one after the other (so it is shared by all
     * the links of that mass and can repeat across masses, for example (1, 11, 0) and (11, 1, 0)).
     */
    static String linkName(String massPrefix, int i, int j, int k) {
        return massPrefix + "1_" + i + j + k;
    }

    /**
     * The offsets (di, dj, dk) from a mass to the neighbours it links to, in the order in which
     * the links are created: every offset of Chebyshev length 1..span in the half space that
     * makes each unordered pair appear once ({@code di > 0}; or {@code di = 0, dj > 0}; or
     * {@code di = dj = 0, dk < 0}).
     */
    static int[][] halfOffsets(int span) {
        List<int[]> out = new ArrayList<>();
        for (int di = 0; di <= span; di++) {
            for (int dj = -span; dj <= span; dj++) {
                if (di == 0 && dj < 0) {
                    continue;
                }
                for (int dk = -span; dk <= span; dk++) {
                    if (di == 0 && dj == 0 && dk >= 0) {
                        break;
                    }
                    out.add(new int[] {di, dj, dk});
                }
            }
        }
        return out.toArray(new int[0][]);
    }

    /** @return the names of the masses that a set of bounds fixes, each once, in the order the bounds are listed. */
    static Set<String> fixedMasses(String prefix, int nx, int ny, int nz, EnumSet<Bound> bounds) {
        Set<String> out = new LinkedHashSet<>();
        for (Bound b : bounds) {
            switch (b) {
                case X_LEFT:
                case X_RIGHT:
                    for (int j = 0; j < ny; j++) {
                        for (int k = 0; k < nz; k++) {
                            out.add(massName(prefix, b == Bound.X_LEFT ? 0 : nx - 1, j, k));
                        }
                    }
                    break;
                case Y_LEFT:
                case Y_RIGHT:
                    for (int i = 0; i < nx; i++) {
                        for (int k = 0; k < nz; k++) {
                            out.add(massName(prefix, i, b == Bound.Y_LEFT ? 0 : ny - 1, k));
                        }
                    }
                    break;
                case Z_LEFT:
                case Z_RIGHT:
                    for (int i = 0; i < nx; i++) {
                        for (int j = 0; j < ny; j++) {
                            out.add(massName(prefix, i, j, b == Bound.Z_LEFT ? 0 : nz - 1));
                        }
                    }
                    break;
                case FIXED_CORNERS:
                    for (int c = 0; c < 8; c++) {
                        out.add(massName(prefix, (c & 1) * (nx - 1), ((c >> 1) & 1) * (ny - 1), ((c >> 2) & 1) * (nz - 1)));
                    }
                    break;
                case FIXED_CENTRE:
                    out.add(massName(prefix, nx / 2, ny / 2, nz / 2));
                    break;
                default:
                    throw new IllegalStateException("unhandled bound " + b);
            }
        }
        return out;
    }

    /**
     * @return the 3x3 rotation matrix (row-major) that turns by {@code ax} about x, then
     * {@code ay} about y, then {@code az} about z (radians): {@code Rz * Ry * Rx}.
     */
    static double[] rotation(double ax, double ay, double az) {
        double ca = Math.cos(ax), sa = Math.sin(ax);
        double cb = Math.cos(ay), sb = Math.sin(ay);
        double cc = Math.cos(az), sc = Math.sin(az);
        return new double[] {
            cc * cb, cc * sb * sa - sc * ca, cc * sb * ca + sc * sa,
            sc * cb, sc * sb * sa + cc * ca, sc * sb * ca - cc * sa,
            -sb, cb * sa, cb * ca
        };
    }

    /** @return {@code r * (x, y, z) + t}. */
    static Vect3D transform(double[] r, double x, double y, double z, double tx, double ty, double tz) {
        return new Vect3D(r[0] * x + r[1] * y + r[2] * z + tx,
                r[3] * x + r[4] * y + r[5] * z + ty,
                r[6] * x + r[7] * y + r[8] * z + tz);
    }
}
