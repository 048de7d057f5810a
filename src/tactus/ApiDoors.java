package tactus;

import tactus.internal.model.ApiAccess;
import tactus.internal.snapshot.SnapshotBuffer;

/** The package's side of {@link ApiAccess}: the package-private doors the machinery may open. */
final class ApiDoors extends ApiAccess {
    @Override
    public Object modelOf(Object handle) {
        return ((Module) handle).core;
    }

    @Override
    public int idOf(Object handle) {
        return ((Module) handle).id;
    }

    @Override
    public void checkLive(Object handle) {
        ((Module) handle).checkValid();
    }

    @Override
    public Object newSnapshotView(Object buffer) {
        return new ModelSnapshot((SnapshotBuffer) buffer);
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
