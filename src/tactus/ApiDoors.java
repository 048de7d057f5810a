package tactus;

import tactus.engine.LinkKind;
import tactus.engine.MassKind;
import tactus.internal.model.ApiAccess;
import tactus.internal.read.SnapshotBuffer;

/** The package's side of {@link ApiAccess}: the package-private doors the machinery may open. */
final class ApiDoors extends ApiAccess {
    @Override
    public Mass newMassHandle(PhysicalModel model, int id, MassKind kind) {
        return Mass.create(model, id, kind);
    }

    @Override
    public Interaction newLinkHandle(PhysicalModel model, int id, LinkKind kind) {
        return Interaction.create(model, id, kind);
    }

    @Override
    public PhysicalModel modelOf(Module handle) {
        return handle.model;
    }

    @Override
    public int idOf(Module handle) {
        return handle.id;
    }

    @Override
    public void checkLive(Module handle) {
        handle.checkValid();
    }

    @Override
    public void retire(Module handle) {
        handle.invalidate();
    }

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
    public DivergenceException divergence(String message, String massName, long step) {
        return new DivergenceException(message, massName, step);
    }
}
