package tactus.haptics.emulator;

/**
 * The physical parameters of an emulated device ({@link DevicePlant}), the same for every joint: inertia on each
 * joint (link and motor rotor), viscous damping on each joint (bearings, the motor's back-EMF through the
 * driver), Coulomb friction with a higher static threshold (a torque below it does not move a joint at rest),
 * a point mass at the handle, viscous damping at the handle, the internal integration step and the actuation
 * latency (from the firmware receiving a torque to the motor producing it). Units for a revolute joint: kg m^2,
 * N m s/rad, N m; for a prismatic (Cartesian) joint: kg, N s/m, N. Immutable; the {@code with...} methods return
 * a changed copy.
 *
 * <p>The values of {@link #twoDiy()} are assumptions, not measurements of a 2DIY: see
 * docs/haptics-stability.md for how each was chosen and how an owner can measure it.
 */
public final class PlantParameters {
    private final double jointInertia;
    private final double jointDamping;
    private final double coulombTorque;
    private final double staticTorque;
    private final double handleMass;
    private final double taskDamping;
    private final double substep;
    private final double actuationDelay;

    private PlantParameters(double jointInertia, double jointDamping, double coulombTorque, double staticTorque,
                            double handleMass, double taskDamping, double substep, double actuationDelay) {
        check("joint inertia", jointInertia, true);
        check("joint damping", jointDamping, true);
        check("Coulomb torque", coulombTorque, true);
        check("static torque", staticTorque, true);
        check("handle mass", handleMass, true);
        check("task damping", taskDamping, true);
        check("substep", substep, false);
        check("actuation delay", actuationDelay, true);
        if (staticTorque < coulombTorque) {
            throw new IllegalArgumentException("PlantParameters: the static torque (" + staticTorque
                    + ") must be >= the Coulomb torque (" + coulombTorque + ")");
        }
        if (!(jointInertia > 0) && !(handleMass > 0)) {
            throw new IllegalArgumentException("PlantParameters: the joint inertia or the handle mass must be > 0");
        }
        if (substep > 1e-3) {
            throw new IllegalArgumentException("PlantParameters: substep must be <= 1e-3 s, got " + substep);
        }
        this.jointInertia = jointInertia;
        this.jointDamping = jointDamping;
        this.coulombTorque = coulombTorque;
        this.staticTorque = staticTorque;
        this.handleMass = handleMass;
        this.taskDamping = taskDamping;
        this.substep = substep;
        this.actuationDelay = actuationDelay;
    }

    private static void check(String what, double v, boolean zeroOk) {
        if (!Double.isFinite(v) || v < 0 || (!zeroOk && v == 0)) {
            throw new IllegalArgumentException("PlantParameters: " + what + " must be a finite number "
                    + (zeroOk ? ">= 0" : "> 0") + ", got " + v);
        }
    }

    /**
     * The 2DIY (hardware version 3, direct drive) as assumed here: joint inertia 2.5e-5 kg m^2, joint damping
     * 4e-4 N m s/rad, Coulomb friction 2e-3 N m with a static threshold of 3e-3 N m (2.4 % of the firmware's
     * 0.123 N m), 15 g at the handle, no handle damping, 50 microsecond substeps (20 kHz), no actuation latency.
     */
    public static PlantParameters twoDiy() {
        return new PlantParameters(2.5e-5, 4e-4, 2e-3, 3e-3, 0.015, 0, 5e-5, 0);
    }

    /**
     * A generic 3-DoF Cartesian device of the Inverse3's class (assumed): 0.2 kg per axis, 0.5 N s/m, Coulomb
     * friction 0.05 N with a static threshold of 0.08 N, 50 microsecond substeps; use with
     * {@link CartesianPlantKinematics}.
     */
    public static PlantParameters cartesian3Dof() {
        return new PlantParameters(0.2, 0.5, 0.05, 0.08, 0, 0, 5e-5, 0);
    }

    /** A frictionless plant: only inertia and viscous damping (for checks against linear theory). */
    public PlantParameters withoutFriction() {
        return new PlantParameters(jointInertia, jointDamping, 0, 0, handleMass, taskDamping, substep, actuationDelay);
    }

    /** A copy with this joint inertia (kg m^2 or kg, >= 0). */
    public PlantParameters withJointInertia(double v) {
        return new PlantParameters(v, jointDamping, coulombTorque, staticTorque, handleMass, taskDamping, substep, actuationDelay);
    }

    /** A copy with this joint viscous damping (N m s/rad or N s/m, >= 0). */
    public PlantParameters withJointDamping(double v) {
        return new PlantParameters(jointInertia, v, coulombTorque, staticTorque, handleMass, taskDamping, substep, actuationDelay);
    }

    /** A copy with this Coulomb torque and static threshold (N m or N, 0 &lt;= coulomb &lt;= threshold). */
    public PlantParameters withFriction(double coulomb, double threshold) {
        return new PlantParameters(jointInertia, jointDamping, coulomb, threshold, handleMass, taskDamping, substep, actuationDelay);
    }

    /** A copy with this point mass at the handle (kg, >= 0). */
    public PlantParameters withHandleMass(double v) {
        return new PlantParameters(jointInertia, jointDamping, coulombTorque, staticTorque, v, taskDamping, substep, actuationDelay);
    }

    /** A copy with this viscous damping at the handle (N s/m, >= 0). */
    public PlantParameters withTaskDamping(double v) {
        return new PlantParameters(jointInertia, jointDamping, coulombTorque, staticTorque, handleMass, v, substep, actuationDelay);
    }

    /** A copy with this internal integration step (seconds, 0 &lt; step &lt;= 1e-3). */
    public PlantParameters withSubstep(double v) {
        return new PlantParameters(jointInertia, jointDamping, coulombTorque, staticTorque, handleMass, taskDamping, v, actuationDelay);
    }

    /** A copy with this actuation latency (seconds, >= 0): a torque acts this long after the firmware got it. */
    public PlantParameters withActuationDelay(double v) {
        return new PlantParameters(jointInertia, jointDamping, coulombTorque, staticTorque, handleMass, taskDamping, substep, v);
    }

    /** Inertia on each joint (kg m^2; kg for a prismatic joint). */
    public double jointInertia() {
        return jointInertia;
    }

    /** Viscous damping on each joint (N m s/rad; N s/m for a prismatic joint). */
    public double jointDamping() {
        return jointDamping;
    }

    /** Coulomb (sliding) friction on each joint (N m; N). */
    public double coulombTorque() {
        return coulombTorque;
    }

    /** Static threshold on each joint: a joint at rest moves only under a larger torque (N m; N). */
    public double staticTorque() {
        return staticTorque;
    }

    /** Point mass at the handle (kg). */
    public double handleMass() {
        return handleMass;
    }

    /** Viscous damping at the handle, in task space (N s/m). */
    public double taskDamping() {
        return taskDamping;
    }

    /** Internal integration step (seconds). */
    public double substep() {
        return substep;
    }

    /** Actuation latency (seconds). */
    public double actuationDelay() {
        return actuationDelay;
    }

    @Override
    public String toString() {
        return "PlantParameters[inertia " + jointInertia + ", damping " + jointDamping + ", Coulomb " + coulombTorque
                + ", static " + staticTorque + ", handle " + handleMass + " kg, handle damping " + taskDamping
                + " N s/m, substep " + substep + " s, actuation delay " + actuationDelay + " s]";
    }
}
