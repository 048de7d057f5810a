package tactus.internal.model;

import tactus.DivergenceException;
import tactus.Interaction;
import tactus.Mass;
import tactus.ModelSnapshot;
import tactus.Module;
import tactus.PhysicalModel;
import tactus.StabilityReport;
import tactus.UnstableModelException;
import tactus.engine.LinkKind;
import tactus.engine.MassKind;
import tactus.internal.read.SnapshotBuffer;

/**
 * The few doors of the API types that only the machinery may open: making and retiring a module handle, making
 * the snapshot view of a buffer, and making the API's exceptions and stability report. They stay package-private
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

    /** @return a new handle of the kind's class on a mass of the model. */
    public abstract Mass newMassHandle(PhysicalModel model, int id, MassKind kind);

    /** @return a new handle of the kind's class on an interaction of the model. */
    public abstract Interaction newLinkHandle(PhysicalModel model, int id, LinkKind kind);

    /** @return the model a handle belongs to. */
    public abstract PhysicalModel modelOf(Module handle);

    /** @return the engine id of a handle's module. */
    public abstract int idOf(Module handle);

    /** Throws the handle's {@code IllegalStateException} if its module is no longer part of its model. */
    public abstract void checkLive(Module handle);

    /** Marks a handle as no longer part of its model: every later call on it throws. */
    public abstract void retire(Module handle);

    /** @return the public, read-only view of a snapshot buffer. */
    public abstract ModelSnapshot newSnapshotView(SnapshotBuffer buffer);

    /** @return the exception of a change refused under {@code StabilityPolicy.THROW}. */
    public abstract UnstableModelException unstable(String message, StabilityReport report);

    /** @return the public stability report of the engine's analysis. */
    public abstract StabilityReport stabilityReport(tactus.engine.StabilityReport r, String culprit,
                                                    String negativeDamping);

    /** @return the exception of a divergence found while stepping. */
    public abstract DivergenceException divergence(String message, String massName, long step);
}
