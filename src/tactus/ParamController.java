package tactus;

import tactus.internal.realtime.Command;
import tactus.internal.realtime.Ownership;
import tactus.internal.realtime.RampTargets;
import tactus.internal.ModelCore;

/**
 * Ramps one parameter of a subset to a target over a set time, one simulation step at a time, as the paper's
 * engine does for parameter changes driven by MIDI or the GUI. Create it with
 * {@link PhysicalModel#addParamController(String, String, String, float)}; the model advances its ramp at every
 * step, whichever way the model is stepped.
 *
 * <p>The parameter is "mass", "stiffness", "damping" or "dist" (applied with
 * {@link PhysicalModel#changeParamOfSubset(double, String, String)}, in the model's units), or "distX" (the spacing
 * of a mass subset along x, around its barycenter at {@link #init(float)}, with
 * {@link PhysicalModel#changeDistXBetweenSubset(Vect3D, double, String)}). During a ramp the stability analysis runs
 * once per stepping call, not once per step.
 */
public class ParamController extends AbstractController {
    private final float rampTime;
    private float previous;
    private boolean ramping;
    private long step;
    private long rampSteps;
    private Vect3D center;
    /** The resolved members while a ramp started by a realtime stepping thread runs (else null). */
    private RampTargets targets;

    /**
     * Creates a controller; the model normally does this ({@link PhysicalModel#addParamController}).
     *
     * @param rampTime the duration of a ramp, in seconds (&ge; 0; 0 jumps at the next step)
     */
    public ParamController(PhysicalModel pm, float rampTime, String subsetName, String param) {
        super(pm, subsetName, param);
        if (!(rampTime >= 0) || !Float.isFinite(rampTime)) {
            throw new IllegalArgumentException("controller of \"" + subsetName + "\": rampTime must be a finite "
                    + "number of seconds >= 0, got " + rampTime);
        }
        this.rampTime = rampTime;
    }

    /** Sets the parameter to {@code value} at once, and makes it the start of the next ramp. */
    public void init(float value) {
        previous = value;
        ramping = false;
        if ("distX".equals(param)) {
            center = pm.getBarycenterOfSubset(subsetName);
        }
        apply(value);
    }

    /** Starts a linear ramp from the last target (or initial value) to {@code target}, over the ramp time. */
    public void triggerRamp(float target) {
        if (!Float.isFinite(target)) {
            throw new IllegalArgumentException("triggerRamp(\"" + subsetName + "\"): the target must be finite, got "
                    + target);
        }
        long steps = Math.max(1, Math.round((double) rampTime * pm.getSimRate()));
        if ("distX".equals(param) && center == null) {
            center = pm.getBarycenterOfSubset(subsetName);
        }
        if (postRamp(target, steps)) {
            return; // realtime stepping: the stepping thread starts the ramp between two steps
        }
        rampSteps = steps;
        setParam("vmin", 0);
        setParam("vmax", rampSteps);
        setParam("min", previous);
        setParam("max", target);
        previous = target;
        step = 0;
        ramping = true;
    }

    /**
     * Starts a ramp from the last target to {@code target} over {@code steps} steps without allocating: what
     * {@link #triggerRamp(float)} does on the thread that steps a realtime-stepped model.
     */
    /**
     * Queues the start of this ramp when the model is stepped in realtime by another thread.
     *
     * @return false when the caller should start the ramp itself (no realtime stepping, or it is the owner)
     */
    private boolean postRamp(float target, long steps) {
        Ownership o = (Ownership) pm.core.own;
        if (o == null || o.isOwnerThread()) {
            return false;
        }
        pm.gate.enterChange();
        try {
            RampTargets t = RampTargets.resolve(pm.core, subsetName, param, previous, target, center);
            Ownership now = (Ownership) pm.core.own;
            if (now == null) {
                return false; // the mode ended while this thread waited for the lock
            }
            now.post(new RampStart(this, target, steps, t));
        } finally {
            pm.gate.exit();
        }
        return true;
    }

    /** The owner's half of {@link #postRamp}: starts the ramp between two steps. */
    private static final class RampStart extends Command {
        private final ParamController pc;
        private final float target;
        private final long steps;
        private final RampTargets targets;

        RampStart(ParamController pc, float target, long steps, RampTargets targets) {
            this.pc = pc;
            this.target = target;
            this.steps = steps;
            this.targets = targets;
        }

        @Override
        public boolean apply(ModelCore c) {
            pc.startRamp(target, steps, targets);
            return true;
        }
    }

    void startRamp(float target, long steps, RampTargets resolved) {
        targets = resolved;
        rampSteps = steps;
        a = (target - previous) / (float) steps;
        b = target - a * steps;
        previous = target;
        step = 0;
        ramping = true;
    }


    /** {@return true while a ramp is running} */
    public boolean isRamping() {
        return ramping;
    }

    /** Advances the ramp by one simulation step; the model calls it before each step while the ramp runs. */
    public void updateParams() {
        if (!ramping) {
            return;
        }
        step++;
        apply(linearScale(step));
        if (step >= rampSteps) {
            ramping = false;
        }
    }

    private void apply(float value) {
        RampTargets t = targets;
        if (t != null && pm.core.own != null && pm.core.own.isOwnerThread()) {
            t.apply(pm.core, value);
            return;
        }
        if ("distX".equals(param)) {
            if (center == null) {
                center = pm.getBarycenterOfSubset(subsetName);
            }
            pm.changeDistXBetweenSubset(center, value, subsetName);
        } else {
            pm.changeParamOfSubset(value, subsetName, param);
        }
    }
}
