package tactus.haptics;

/**
 * A mechanism: the kinematic model that turns encoder angles into an end-effector position and forces
 * into motor torques (hAPI 2.x compatible).
 *
 * <p>Sketches may keep their own {@code Pantograph.java} or {@code SimpleActuatorMech.java} that extends
 * this class, so it declares exactly hAPI's ten abstract methods and nothing else abstract.
 */
public abstract class Mechanisms {

    /** Creates a mechanism. */
    public Mechanisms() {
    }

    /** Computes the end-effector position from joint angles in degrees (extra elements are ignored). */
    public abstract void forwardKinematics(float[] angles);

    /** Computes the joint torques (N m) for an end-effector force in newtons (extra elements are ignored). */
    public abstract void torqueCalculation(float[] force);

    /** Force control hook (unused by the pantograph). */
    public abstract void forceCalculation();

    /** Position control hook (unused by the pantograph). */
    public abstract void positionControl();

    /** Inverse kinematics hook (unused by the pantograph). */
    public abstract void inverseKinematics();

    /** Sets the mechanism's geometric parameters (for the pantograph: l, L, d in metres). */
    public abstract void set_mechanism_parameters(float[] parameters);

    /** Passes analog sensor data to the mechanism. */
    public abstract void set_sensor_data(float[] data);

    /** Returns the end-effector coordinates of the last forward kinematics (metres). */
    public abstract float[] get_coordinate();

    /** Returns the joint torques of the last torque calculation (N m). */
    public abstract float[] get_torque();

    /** Returns the joint angles of the last forward kinematics (radians). */
    public abstract float[] get_angle();
}
