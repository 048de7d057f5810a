package tactus.internal;

import tactus.internal.edit.GravityNote;
import tactus.internal.edit.ModuleBuilder;
import tactus.internal.edit.ParamEditor;
import tactus.internal.edit.SubsetBook;
import tactus.internal.edit.TopologyEditor;
import tactus.internal.model.ModuleListener;
import tactus.internal.model.ModelBase;
import tactus.internal.model.RealtimeMode;
import tactus.internal.read.PaperQueries;
import tactus.internal.read.StateAccess;
import tactus.internal.snapshot.SnapshotWriter;
import tactus.internal.stability.DivergenceWatch;
import tactus.internal.stability.StabilityGuard;
import tactus.paramSystem;

/**
 * The rooms behind one {@code PhysicalModel}, wired together on top of what they share ({@link ModelBase}): the
 * stability guard and the divergence watch, the snapshot writer, the module builder, the parameter and topology
 * editors, subsets and contact groups, state access and the paper engine's queries. Each room is given the rooms it
 * uses when it is made, so that none of them needs this class. Every method of the rooms assumes the caller is inside
 * a facade call. Not API.
 */
public final class ModelCore extends ModelBase {
    public final DivergenceWatch watch;
    public final StabilityGuard guard;
    public final SnapshotWriter snapshots;
    public final ParamEditor params;
    public final TopologyEditor topology;
    public final SubsetBook subsets;
    public final ModuleBuilder builder;
    public final StateAccess state;
    public final PaperQueries paper;
    public final GravityNote gravityNote;

    public ModelCore(paramSystem system, int simRate, int displayRate, ModuleListener handles) {
        super(system, simRate, displayRate, handles);
        this.guard = new StabilityGuard(engine, dir, time);
        this.watch = new DivergenceWatch(engine, dir, guard::suspect);
        this.snapshots = new SnapshotWriter(this);
        this.params = new ParamEditor(this, guard);
        this.topology = new TopologyEditor(this, snapshots, watch);
        this.subsets = new SubsetBook(this, params, topology, guard);
        this.topology.subsets = subsets;
        this.guard.groupNames = subsets::groupNames;
        this.builder = new ModuleBuilder(this, guard, topology);
        this.state = new StateAccess(this, params, topology);
        this.paper = new PaperQueries(this, params, subsets, guard);
        this.gravityNote = new GravityNote(this);
    }

    /** Enters or leaves the realtime-stepping mode (under the model's lock). */
    public void setOwnership(RealtimeMode o) {
        own = o;
        guard.own = o;
    }
}
