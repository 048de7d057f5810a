package tactus.haptics.emulator;

/**
 * The geometry a {@link DevicePlant} needs: n joint coordinates to n task coordinates (a square Jacobian), in
 * radians (or metres for a prismatic joint) and metres. Implementations keep no per-call allocation.
 */
public interface PlantKinematics {
    /** Number of joints, equal to the number of task coordinates (2 for a pantograph, 3 for a 3-DoF device). */
    int joints();

    /**
     * Writes the handle position for joint coordinates q into x (metres) and the Jacobian dx/dq into j, row-major
     * (j[r * n + c] = d x_r / d q_c, m/rad). Returns false (outputs unspecified) at an unreachable or singular pose.
     */
    boolean forward(double[] q, double[] x, double[] j);

    /** Writes joint coordinates that put the handle at x into q; returns false (q unchanged) if out of reach. */
    boolean inverse(double[] x, double[] q);
}
