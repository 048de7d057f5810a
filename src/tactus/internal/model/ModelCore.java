package tactus.internal.model;

import java.util.function.Predicate;
import tactus.engine.Engine;
import tactus.engine.MassKind;
import tactus.ParamController;
import tactus.PhysicalModel;
import tactus.internal.edit.GravityNote;
import tactus.internal.edit.ModuleBuilder;
import tactus.internal.edit.ParamEditor;
import tactus.internal.edit.SubsetBook;
import tactus.internal.edit.TopologyEditor;
import tactus.internal.read.PaperQueries;
import tactus.internal.read.SnapshotWriter;
import tactus.internal.read.StateAccess;
import tactus.internal.realtime.Ownership;
import tactus.internal.stability.DivergenceWatch;
import tactus.internal.stability.StabilityGuard;
import tactus.paramSystem;

/**
 * The package-private rooms behind one {@link PhysicalModel}, wired together: the engine, the directory of
 * names and handles, the clock and medium, subsets and contact groups, the stability guard, the divergence
 * watch, the module builder and editor, and state access. {@code PhysicalModel} only takes the lock and
 * delegates here; every method of these rooms assumes the caller holds the model's lock.
 */
public final class ModelCore {
    public final PhysicalModel model;
    public final Engine engine = new Engine();
    public final Directory dir = new Directory(engine);
    public final Timebase time;
    public final SubsetBook subsets;
    public final StabilityGuard guard;
    public final DivergenceWatch watch = new DivergenceWatch(engine, dir);
    public final ParamEditor params;
    public final ModuleBuilder builder;
    public final TopologyEditor topology;
    public final StateAccess state;
    public final SnapshotWriter snapshots;
    public final PaperQueries paper;
    public final GravityNote gravityNote;
    /** The calls of the paper's API forgiven as the paper's engine did, and the warnings printed once each. */
    public final PaperLeniency lenient = new PaperLeniency();
    /** Parameter controllers by name, in creation order (see {@link ParamController}). */
    private final java.util.LinkedHashMap<String, ParamController> controllers = new java.util.LinkedHashMap<>();
    /** The same controllers as an array, so that the stepping path checks them without allocating an iterator. */
    private volatile ParamController[] controllerArray = new ParamController[0];
    /** Engine writes that go straight to the engine. */
    public final EngineWrites direct = EngineWrites.direct(engine);
    /** The realtime-stepping mode, or null (see {@link PhysicalModel#beginRealtimeStepping()}). */
    public volatile Ownership own;
    /** True once init() has run: from then on topology edits compile at once, on the editing thread. */
    public boolean initialized;

    public ModelCore(PhysicalModel model, paramSystem system, int simRate, int displayRate) {
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
        this.gravityNote = new GravityNote(this);
        this.time.core = this;
    }

    /**
     * @return where the current thread's parameter and state writes go: the engine, or the batch an editor of a
     *     realtime-stepped model is preparing
     */
    public EngineWrites writes() {
        Ownership o = own;
        return o == null ? direct : o.writes(direct);
    }

    /** Enters or leaves the realtime-stepping mode (under the model's lock). */
    public void setOwnership(Ownership o) {
        own = o;
        guard.own = o;
    }

    /** Adds or replaces a named parameter controller. */
    public void putController(String name, ParamController pc) {
        controllers.put(name, pc);
        controllerArray = controllers.values().toArray(new ParamController[0]);
    }

    /** @return the named parameter controller, or null. */
    public ParamController controller(String name) {
        return controllers.get(name);
    }

    public void clearControllers() {
        controllers.clear();
        controllerArray = new ParamController[0];
    }

    /** @return true when some parameter controller is in the middle of a ramp. */
    public boolean ramping() {
        for (ParamController pc : controllerArray) {
            if (pc.isRamping()) {
                return true;
            }
        }
        return false;
    }

    /** Advances every running ramp by one step, with the stability check deferred to the end of the batch. */
    public void advanceRamps() {
        Ownership o = own;
        if (o != null) {
            o.inRamp = true;
        }
        guard.defer();
        try {
            for (ParamController pc : controllerArray) {
                pc.updateParams();
            }
        } finally {
            guard.resume();
            if (o != null) {
                o.inRamp = false;
            }
        }
    }

    public UnitScale units() {
        return time.units;
    }

    /**
     * For a call of the paper's API on a mass that must be of certain kinds.
     *
     * @param wanted the kinds the call works on
     * @param kind the kind of problem forgiven otherwise
     * @param op the call's name
     * @param id the mass
     * @param problem what is wrong, before ", this is a " and the mass's kind
     * @param skipped what the call did instead
     * @return true when the mass is of a wanted kind; otherwise false after one warning per kind of problem (the
     *     paper's engine answered 0 or did nothing), or the exception in strict mode
     */
    public boolean paperMassIs(Predicate<MassKind> wanted, PaperLeniency.Kind kind, String op, int id, String problem,
                        String skipped) {
        MassKind k = dir.massKind(id);
        if (wanted.test(k)) {
            return true;
        }
        lenient.forgive(kind, op, dir.massName(id), problem + ", this is a " + k.label(), skipped);
        return false;
    }
}
