package tactus;

import tactus.internal.model.ApiAccess;
import tactus.internal.snapshot.SnapshotBuffer;

/** The package's side of {@link ApiAccess}: the package-private doors the machinery may open. */
final class ApiDoors extends ApiAccess {
    @Override
    public ModelSnapshot newSnapshotView(SnapshotBuffer buffer) {
        return new ModelSnapshot(buffer);
    }

    @Override
    public UnstableModelException unstable(String message, StabilityReport report) {
        return new UnstableModelException(message, report);
    }

    @Override
    public StabilityReport stabilityReport(tactus.engine.StabilityReport r, String culprit, String negativeDamping) {
        return new StabilityReport(r, culprit, negativeDamping);
    }

    @Override
    public DivergenceException divergence(String massLabel, String massName, long step, double x, double y, double z,
                                          String suspect) {
        return new DivergenceException(massLabel, massName, step, x, y, z, suspect);
    }
}
