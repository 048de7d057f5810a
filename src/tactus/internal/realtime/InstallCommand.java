package tactus.internal.realtime;

import tactus.engine.Engine;
import tactus.internal.ModelCore;

/**
 * The second half of a structural change of an audio-owned model: swaps in the step plan that the calling thread
 * compiled while the owner kept stepping the old one ({@link Engine#install}), then has the snapshot writer publish the
 * new topology ({@link SnapshotWriter#topologyChanged()}). Runs on the stepping thread between two steps; costs O(masses + links) copies, not a compile.
 */
public final class InstallCommand extends Command {
    private final Engine.PreparedPlan prepared;

    public InstallCommand(Engine.PreparedPlan prepared) {
        this.prepared = prepared;
    }

    @Override
    public boolean apply(ModelCore core) {
        core.engine.install(prepared);
        if (core.initialized) {
            core.snapshots.topologyChanged();
        }
        return true;
    }
}
