package tactus.haptics;

import tactus.haptics.pantograph.PantographKinematics;

/**
 * The Haply 2-DoF pantograph as a {@link Mechanisms} (hAPI 2.x compatible), computed in double precision
 * by {@link PantographKinematics}.
 *
 * <p>{@link #Pantograph()} is the 2018 hAPI example: l, L, d = 0.05, 0.07, 0.02 m and torques
 * (0.1 / l) J^T F, i.e. twice the physical torque for l = 0.05 m; ported sketches keep that feel.
 * {@link #Pantograph(int)} is the 2021 "2DIY" version with gain 1 (physically exact torques):
 * hardware version 2 gives 0.07, 0.09, 0 m, any other 0.07, 0.09, 0.038 m.
 */
public class Pantograph extends Mechanisms {
    private final PantographKinematics kinematics;
    private final boolean legacyGain;
    private final double[] tau = new double[2];
    private float th1;
    private float th2;
    private float x;
    private float y;
    private float tau1;
    private float tau2;

    /** The 2018 hAPI pantograph: l = 0.05 m, L = 0.07 m, d = 0.02 m, torque gain 0.1 / l. */
    public Pantograph() {
        this.kinematics = new PantographKinematics(0.05, 0.07, 0.02);
        this.legacyGain = true;
    }

    /** The 2021 pantograph of a 2DIY hardware version (2: d = 0; 3 or other: d = 0.038 m), torque gain 1. */
    public Pantograph(int hardwareVersion) {
        this.kinematics = new PantographKinematics(0.07, 0.09, hardwareVersion == 2 ? 0.0 : 0.038);
        this.legacyGain = false;
    }

    /** Creates a pantograph with explicit link lengths (metres) and a torque gain of 1. */
    public Pantograph(double l, double bigL, double d) {
        this.kinematics = new PantographKinematics(l, bigL, d);
        this.legacyGain = false;
    }

    /** The torque gain applied to J^T F: 0.1 / l for {@link #Pantograph()}, otherwise 1. */
    public double gain() {
        return legacyGain ? 0.1 / kinematics.l() : 1.0;
    }

    /** The underlying double-precision kinematics (its parameters can be changed). */
    public PantographKinematics kinematics() {
        return kinematics;
    }

    @Override
    public void forwardKinematics(float[] angles) {
        if (angles == null || angles.length < 2) {
            throw new IllegalArgumentException("Pantograph.forwardKinematics: needs 2 angles (degrees), got "
                    + (angles == null ? "null" : angles.length + " element(s)"));
        }
        th1 = (float) Math.toRadians(angles[0]);
        th2 = (float) Math.toRadians(angles[1]);
        kinematics.forward(Math.toRadians(angles[0]), Math.toRadians(angles[1]));
        x = (float) kinematics.x();
        y = (float) kinematics.y();
    }

    @Override
    public void torqueCalculation(float[] force) {
        if (force == null || force.length < 2) {
            throw new IllegalArgumentException("Pantograph.torqueCalculation: needs 2 force components (N), got "
                    + (force == null ? "null" : force.length + " element(s)"));
        }
        kinematics.torques(force[0], force[1], gain(), tau);
        tau1 = (float) tau[0];
        tau2 = (float) tau[1];
    }

    @Override
    public void forceCalculation() {
    }

    @Override
    public void positionControl() {
    }

    @Override
    public void inverseKinematics() {
    }

    @Override
    public void set_mechanism_parameters(float[] parameters) {
        if (parameters == null || parameters.length < 3) {
            throw new IllegalArgumentException("Pantograph.set_mechanism_parameters: needs {l, L, d} in metres, got "
                    + (parameters == null ? "null" : parameters.length + " element(s)"));
        }
        kinematics.setParameters(parameters[0], parameters[1], parameters[2]);
    }

    @Override
    public void set_sensor_data(float[] data) {
    }

    @Override
    public float[] get_coordinate() {
        return new float[] {x, y};
    }

    @Override
    public float[] get_torque() {
        return new float[] {tau1, tau2};
    }

    @Override
    public float[] get_angle() {
        return new float[] {th1, th2};
    }
}
