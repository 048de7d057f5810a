package tactus.internal.stability;

import tactus.engine.Engine;
import tactus.engine.StabilityAnalyzer;
import tactus.engine.StepPlan;
import tactus.StabilityPolicy;
import tactus.StabilityReport;
import tactus.internal.model.ApiAccess;
import tactus.internal.model.Directory;
import tactus.internal.model.Timebase;
import tactus.internal.model.RealtimeMode;

/**
 * The automatic stability check of a model: after {@link PhysicalModel#init()}, every parameter or topology
 * change is followed by an analysis of the whole network; under {@link StabilityPolicy#WARN} an unstable
 * result prints one line (once per distinct message), under {@link StabilityPolicy#THROW} the change is undone
 * and an {@link UnstableModelException} is thrown. Changes made in a batch (a subset, a rate change) are
 * analysed once, at the end. The caller holds the model's lock. The analysis and its messages only read the engine:
 * a stiffness limit is found with an assumed coefficient ({@link StabilityAnalyzer.Assumption}), never by writing it.
 */
public final class StabilityGuard {
    private final Engine engine;
    private final Directory dir;
    private final Timebase time;
    /** The names of the live contact groups, for messages (set once by ModelCore: the subsets are made after the guard). */
    public java.util.function.Supplier<String[]> groupNames = () -> new String[0];
    private StabilityPolicy policy = StabilityPolicy.WARN;
    private int maxContacts = StabilityAnalyzer.DEFAULT_MAX_CONTACTS;
    private boolean armed;
    private int deferred;
    private String lastWarning;
    /** The realtime-stepping mode of the model, or null. */
    public volatile RealtimeMode own;

    public StabilityGuard(Engine engine, Directory dir, Timebase time) {
        this.engine = engine;
        this.dir = dir;
        this.time = time;
    }

    /** Starts checking every later change (called by init()); the model as it is now is checked at once. */
    public void arm() {
        armed = true;
        lastWarning = null;
        afterChange(null);
    }

    public StabilityPolicy policy() {
        return policy;
    }

    public void setPolicy(StabilityPolicy p) {
        policy = p;
        lastWarning = null;
    }

    public int maxContacts() {
        return maxContacts;
    }

    public void setMaxContacts(int n) {
        maxContacts = n;
    }

    /** Suspends the check until the matching {@link #resume()}: for changes made as one batch. */
    public void defer() {
        RealtimeMode o = own;
        if (o == null || !o.ignoresDeferral()) {
            deferred++;
        }
    }

    public void resume() {
        RealtimeMode o = own;
        if (o == null || !o.ignoresDeferral()) {
            deferred--;
        }
    }

    /**
     * Checks the model after a change. Under THROW an unstable model is restored with {@code undo} (which may be
     * null for a check of the model as built) and an exception is thrown.
     */
    public void afterChange(Runnable undo) {
        RealtimeMode o = own;
        if (o != null && o.interceptCheck(undo)) {
            return; // realtime stepping: collected for the editor, analysed later, or a ramp step
        }
        if (deferred > 0) {
            return;
        }
        check(undo);
    }

    /** Analyses the model now (whatever the deferral); under THROW an unstable model is undone and refused. */
    public void check(Runnable undo) {
        if (!armed || policy == StabilityPolicy.OFF) {
            return;
        }
        StepPlan p = planToAnalyse();
        tactus.engine.StabilityReport r = analyze(p);
        String msg = message(r, p);
        if (msg == null) {
            lastWarning = null;
            return;
        }
        if (!r.isStable() && policy == StabilityPolicy.THROW) {
            if (undo != null) {
                undo.run();
            }
            throw ApiAccess.get().unstable(msg, facadeReport(r));
        }
        if (!msg.equals(lastWarning)) {
            System.err.println(msg);
            lastWarning = msg;
        }
    }

    /** @return the report of the model as it is now, in facade terms. */
    public StabilityReport report() {
        return facadeReport(analyze(planToAnalyse()));
    }

    /** @return one line describing the model's stability: the margin, or the offending module and its limit. */
    public String describe() {
        StepPlan p = planToAnalyse();
        tactus.engine.StabilityReport r = analyze(p);
        String msg = message(r, p);
        return msg != null ? msg : String.format(java.util.Locale.ROOT,
                "Tactus: stable (lambda max = %.4g < 4, every stiffness could grow %.3gx)", r.lambda(), r.headroom());
    }

    /**
     * Names the module most likely at fault for a divergence: the one the stability analysis blames, with its
     * parameter, value, limit and the fix; when the model is linearly stable, the module closest to its limit and
     * the other causes to look for. Runs one analysis, whatever the policy.
     */
    public String suspect() {
        StepPlan p = planToAnalyse();
        tactus.engine.StabilityReport r = analyze(p);
        String[] groups = groupNames.get();
        return StabilityMessages.suspect(r, StabilityMessages.describe(r, p, engine, dir, time.units, maxContacts,
                groups), StabilityMessages.culprit(r, engine, dir, groups));
    }

    /**
     * @return the plan to analyse. The analysis only reads it: on another thread than a realtime owner (the drawing
     *     thread, the WARN helper thread) it is the live plan as it is, never compiled or re-selected there.
     */
    private StepPlan planToAnalyse() {
        RealtimeMode o = own;
        if (o != null && !o.isOwnerThread()) {
            StepPlan live = engine.livePlan();
            if (live != null) {
                return live;
            }
        }
        return engine.planForAnalysis();
    }

    private tactus.engine.StabilityReport analyze(StepPlan p) {
        return StabilityAnalyzer.analyze(p, maxContacts);
    }

    private String message(tactus.engine.StabilityReport r, StepPlan p) {
        return StabilityMessages.describe(r, p, engine, dir, time.units, maxContacts, groupNames.get());
    }

    private StabilityReport facadeReport(tactus.engine.StabilityReport r) {
        String[] groups = groupNames.get();
        return ApiAccess.get().stabilityReport(r, StabilityMessages.culprit(r, engine, dir, groups),
                StabilityMessages.negativeDampingModule(r, engine, dir));
    }
}
