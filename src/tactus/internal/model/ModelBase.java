package tactus.internal.model;

import java.util.function.Predicate;
import tactus.engine.Engine;
import tactus.engine.MassKind;
import tactus.paramSystem;

/**
 * What every room of one model shares: the engine, the directory of names and stamps, the clock and units, the
 * paper's leniency, the realtime mode (if any) and where the current thread's writes go. The rooms themselves are
 * wired above, in {@code tactus.internal.ModelCore}; every method here assumes the caller is inside a facade call
 * (holds the model's lock, or is the realtime owner). Not API.
 */
public class ModelBase {
    public final Engine engine = new Engine();
    public final Directory dir;
    public final Timebase time;
    /** The calls of the paper's API forgiven as the paper's engine did, and the warnings printed once each. */
    public final PaperLeniency lenient = new PaperLeniency();
    /** Engine writes that go straight to the engine. */
    public final EngineWrites direct = EngineWrites.direct(engine);
    /** The realtime-stepping mode, or null (see {@code PhysicalModel.beginRealtimeStepping()}). */
    public volatile RealtimeMode own;
    /** True once init() has run: from then on topology edits compile at once, on the editing thread. */
    public boolean initialized;
    /** The controllers' parameter ramps (none until the facade gives them). */
    public Ramps ramps = NO_RAMPS;

    private static final Ramps NO_RAMPS = new Ramps() {
        @Override
        public boolean ramping() {
            return false;
        }

        @Override
        public void advanceAll() {
        }

        @Override
        public void clear() {
        }
    };

    protected ModelBase(paramSystem system, int simRate, int displayRate, ModuleListener handles) {
        this.dir = new Directory(engine, handles);
        this.time = new Timebase(engine, dir, system, simRate, displayRate);
        this.time.writes = this::writes;
    }

    /**
     * @return where the current thread's parameter and state writes go: the engine, or the batch an editor of a
     *     realtime-stepped model is preparing
     */
    public EngineWrites writes() {
        RealtimeMode o = own;
        return o == null ? direct : o.writes(direct);
    }

    /** @return true when some parameter controller is in the middle of a ramp. */
    public boolean ramping() {
        return ramps.ramping();
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
