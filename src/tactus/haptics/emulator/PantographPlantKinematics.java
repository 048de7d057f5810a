package tactus.haptics.emulator;

import tactus.haptics.pantograph.PantographKinematics;

/** {@link PlantKinematics} of a five-bar pantograph (the 2DIY), over {@link PantographKinematics}. */
public final class PantographPlantKinematics implements PlantKinematics {
    private final PantographKinematics kin;
    private final double[] tmp = new double[2];

    /** The pantograph with proximal links l, distal links bigL and motor spacing d, in metres. */
    public PantographPlantKinematics(double l, double bigL, double d) {
        kin = new PantographKinematics(l, bigL, d);
    }

    @Override
    public int joints() {
        return 2;
    }

    @Override
    public boolean forward(double[] q, double[] x, double[] j) {
        if (!kin.forward(q[0], q[1])) {
            return false;
        }
        x[0] = kin.x();
        x[1] = kin.y();
        j[0] = kin.jacobian(0, 0);
        j[1] = kin.jacobian(0, 1);
        j[2] = kin.jacobian(1, 0);
        j[3] = kin.jacobian(1, 1);
        return true;
    }

    @Override
    public boolean inverse(double[] x, double[] q) {
        if (!kin.inverse(x[0], x[1], tmp)) {
            return false;
        }
        q[0] = tmp[0];
        q[1] = tmp[1];
        return true;
    }
}
