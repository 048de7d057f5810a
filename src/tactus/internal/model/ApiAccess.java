package tactus.internal.model;

import tactus.DivergenceException;
import tactus.ModelSnapshot;
import tactus.StabilityReport;
import tactus.UnstableModelException;

/**
 * The few doors of the API types that only the machinery may open: the snapshot view of a buffer, and the API's
 * exceptions and stability report. They stay package-private
 * in {@code tactus} (a sketch cannot call them); the package gives this object to the machinery once, when
 * {@link PhysicalModel} is loaded. Not API.
 */
public abstract class ApiAccess {
    private static volatile ApiAccess doors;

    /**
     * Called once by {@code tactus.PhysicalModel} when it is loaded; later calls change nothing.
     *
     * @param a the package's implementation
     */
    public static synchronized void install(ApiAccess a) {
        if (doors == null) {
            doors = a;
        }
    }

    /** @return the doors; the machinery exists only behind a {@code PhysicalModel}, so they are installed. */
    public static ApiAccess get() {
        return doors;
    }

    /** @return the public, read-only view ({@code ModelSnapshot}) of a snapshot buffer. */
    public abstract ModelSnapshot newSnapshotView(tactus.internal.snapshot.SnapshotBuffer buffer);

    /** @return the exception of a change refused under {@code StabilityPolicy.THROW}. */
    public abstract UnstableModelException unstable(String message, StabilityReport report);

    /** @return the public stability report of the engine's analysis. */
    public abstract StabilityReport stabilityReport(tactus.engine.StabilityReport r, String culprit,
                                                    String negativeDamping);

    /**
     * @return the exception of a divergence found while stepping, from its raw facts (its message is formatted when
     *     it is read, not on the stepping thread)
     * @param massLabel the kind of the mass, "Mass3D"; x, y, z its position when the divergence was found
     * @param suspect the module most likely at fault, its parameter and the fix, or null
     */
    public abstract DivergenceException divergence(String massLabel, String massName, long step,
                                                   double x, double y, double z, String suspect);
}
