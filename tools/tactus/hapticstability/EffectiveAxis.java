package tactus.hapticstability;

import tactus.haptics.HaplyPreset;
import tactus.haptics.emulator.PantographPlantKinematics;
import tactus.haptics.emulator.PlantParameters;

/**
 * The 1-D device the theory sees along the pantograph's y axis at a pose on its symmetry line x = d/2: the task-space mass and
 * damping matrices M = I_j (J J^T)^-1 + m 1 and B = b_j (J J^T)^-1 + b_t 1 (J the Jacobian dx/dq), read on their
 * yy entries. At the symmetric pose x = d/2 both matrices are diagonal, so motion along y does not couple to x.
 */
public final class EffectiveAxis {
    /** Mass along y, kg. */
    public final double mass;
    /** Damping along y, N s/m. */
    public final double damping;
    /** The largest off-diagonal entry of (J J^T)^-1 relative to its diagonal (0 at a symmetric pose). */
    public final double coupling;

    /** The axis of a configuration's plant at its wall's equilibrium (the pose the oscillation is about). */
    public static EffectiveAxis atEquilibrium(WallRig.Config c) {
        return new EffectiveAxis(c.preset, c.plant, WallRig.START_Y + WallRig.wallY(c));
    }

    /** The axis of this plant on this preset's pantograph at (d/2, y), y in metres. */
    public EffectiveAxis(HaplyPreset preset, PlantParameters p, double y) {
        PantographPlantKinematics k = new PantographPlantKinematics(preset.l(), preset.bigL(), preset.d());
        double[] q = new double[2];
        if (!k.inverse(new double[] {preset.d() / 2, y}, q)) {
            throw new IllegalStateException("EffectiveAxis: start pose out of reach");
        }
        double[] x = new double[2];
        double[] j = new double[4];
        k.forward(q, x, j);
        // J J^T
        double a = j[0] * j[0] + j[1] * j[1];
        double b = j[0] * j[2] + j[1] * j[3];
        double d = j[2] * j[2] + j[3] * j[3];
        double det = a * d - b * b;
        double iyy = a / det;
        double ixx = d / det;
        double ixy = -b / det;
        mass = p.jointInertia() * iyy + p.handleMass();
        damping = p.jointDamping() * iyy + p.taskDamping();
        coupling = Math.abs(ixy) / Math.max(ixx, iyy);
    }
}
