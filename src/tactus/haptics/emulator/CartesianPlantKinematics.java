package tactus.haptics.emulator;

/**
 * {@link PlantKinematics} of a generic Cartesian device with n prismatic axes (joint i moves the handle along
 * task axis i, metres for metres): the identity Jacobian. The simplest 3-DoF form of a {@link DevicePlant}.
 */
public final class CartesianPlantKinematics implements PlantKinematics {
    private final int n;

    /** A Cartesian device with n axes (1..3). */
    public CartesianPlantKinematics(int n) {
        if (n < 1 || n > 3) {
            throw new IllegalArgumentException("CartesianPlantKinematics: axes must be 1..3, got " + n);
        }
        this.n = n;
    }

    @Override
    public int joints() {
        return n;
    }

    @Override
    public boolean forward(double[] q, double[] x, double[] j) {
        for (int r = 0; r < n; r++) {
            x[r] = q[r];
            for (int c = 0; c < n; c++) {
                j[r * n + c] = r == c ? 1 : 0;
            }
        }
        return true;
    }

    @Override
    public boolean inverse(double[] x, double[] q) {
        System.arraycopy(x, 0, q, 0, n);
        return true;
    }
}
