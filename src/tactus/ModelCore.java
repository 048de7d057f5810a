package tactus;

import tactus.engine.Engine;

/**
 * The package-private rooms behind one {@link PhysicalModel}, wired together: the engine, the directory of
 * names and handles, the clock and medium, subsets and contact groups, the stability guard, the divergence
 * watch, the module builder and editor, and state access. {@code PhysicalModel} only takes the lock and
 * delegates here; every method of these rooms assumes the caller holds the model's lock.
 */
final class ModelCore {
    final PhysicalModel model;
    final Engine engine = new Engine();
    final Directory dir = new Directory(engine);
    final Timebase time;
    final SubsetBook subsets;
    final StabilityGuard guard;
    final DivergenceWatch watch = new DivergenceWatch(engine, dir);
    final ParamEditor params;
    final ModuleBuilder builder;
    final TopologyEditor topology;
    final StateAccess state;
    final SnapshotWriter snapshots;
    final PaperQueries paper;
    /** Parameter controllers by name, in creation order (see {@link ParamController}). */
    final java.util.LinkedHashMap<String, ParamController> controllers = new java.util.LinkedHashMap<>();
    /** True once init() has run: from then on topology edits compile at once, on the editing thread. */
    boolean initialized;

    ModelCore(PhysicalModel model, paramSystem system, int simRate, int displayRate) {
        this.model = model;
        this.time = new Timebase(engine, dir, system, simRate, displayRate);
        this.subsets = new SubsetBook(this);
        this.guard = new StabilityGuard(engine, dir, time, subsets);
        this.params = new ParamEditor(this);
        this.builder = new ModuleBuilder(this);
        this.topology = new TopologyEditor(this);
        this.state = new StateAccess(this);
        this.snapshots = new SnapshotWriter(this);
        this.paper = new PaperQueries(this);
    }

    /** @return true when some parameter controller is in the middle of a ramp. */
    boolean ramping() {
        for (ParamController pc : controllers.values()) {
            if (pc.isRamping()) {
                return true;
            }
        }
        return false;
    }

    /** Advances every running ramp by one step, with the stability check deferred to the end of the batch. */
    void advanceRamps() {
        guard.defer();
        try {
            for (ParamController pc : controllers.values()) {
                pc.updateParams();
            }
        } finally {
            guard.resume();
        }
    }

    UnitScale units() {
        return time.units;
    }
}
