package tactus.internal.calls;

import tactus.DivergenceListener;
import tactus.StabilityPolicy;
import tactus.StabilityReport;
import tactus.Vect3D;
import tactus.paramSystem;
import tactus.internal.model.Check;
import tactus.internal.read.PlanLabels;
import tactus.internal.realtime.ModelLock;
import tactus.internal.ModelCore;

/**
 * The facade calls that set and read how a model runs: rates, threads, the medium, strictness, the stability
 * policy and the divergence watch. Each enters the model once and hands the work to its room. Not API.
 */
public final class SettingsCalls extends Calls {
    public SettingsCalls(ModelCore core, ModelLock gate) {
        super(core, gate);
    }

    public paramSystem getParamSystem() {
        enter();
        try {
            return core.units().isReal() ? paramSystem.REAL_UNITS : paramSystem.ALGO_UNITS;
        } finally {
            exit();
        }
    }

    public void setParamSystem(paramSystem system) {
        if (system == null) {
            throw new IllegalArgumentException("setParamSystem: the unit system must not be null");
        }
        structuralDo(() -> {
            core.time.setParamSystem(system);
        });
    }

    public int getSimRate() {
        enter();
        try {
            return core.time.simRate();
        } finally {
            exit();
        }
    }

    public int getDisplayRate() {
        enter();
        try {
            return core.time.displayRate();
        } finally {
            exit();
        }
    }

    public void setDisplayRate(int rate) {
        if (rate <= 0) {
            throw new IllegalArgumentException("setDisplayRate: the rate must be > 0 Hz, got " + rate);
        }
        structuralDo(() -> {
            core.time.setDisplayRate(rate);
        });
    }

    public void init() {
        structuralDo(() -> {
            core.engine.compile();
            core.initialized = true;
            core.guard.arm();
            core.snapshots.topologyChanged();
        });
    }

    public void setThreads(int threads) {
        if (threads < 1 || threads > 64) {
            throw new IllegalArgumentException("setThreads: the thread count must be in 1..64, got " + threads);
        }
        structuralDo(() -> {
            core.engine.setThreads(threads);
            core.topology.compileIfRunning();
        });
    }

    public int getThreads() {
        enter();
        try {
            return core.engine.threads();
        } finally {
            exit();
        }
    }

    public long getStepCount() {
        enter();
        try {
            return core.engine.stepCount();
        } finally {
            exit();
        }
    }

    public String[] getSimulatedEffects() {
        enter();
        try {
            return PlanLabels.of(core.engine.kernelNames());
        } finally {
            exit();
        }
    }

    public void dispose() {
        structuralDo(() -> {
            core.engine.close();
        });
    }

    public void setGravity(double magnitude) {
        Check.finite("setGravity", "gravity", "magnitude", magnitude);
        enterChange();
        try {
            core.time.setGravity(magnitude);
            core.gravityNote.afterGravityChange();
        } finally {
            exit();
        }
    }

    public double getGravity() {
        enter();
        try {
            return core.time.gravity();
        } finally {
            exit();
        }
    }

    public void setGravityDirection(Vect3D direction) {
        Check.vector("setGravityDirection", "gravity", "direction", direction);
        if (direction.x == 0 && direction.y == 0 && direction.z == 0) {
            throw Check.fail("setGravityDirection", "gravity", "direction must not be the zero vector");
        }
        enterChange();
        try {
            core.time.setGravityDirection(direction.x, direction.y, direction.z);
            core.gravityNote.afterGravityChange();
        } finally {
            exit();
        }
    }

    public Vect3D getGravityDirection() {
        enter();
        try {
            return core.time.gravityDirection(new Vect3D());
        } finally {
            exit();
        }
    }

    public void setFriction(double f) {
        Check.finite("setFriction", "friction", "friction", f);
        enterChange();
        try {
            double old = core.time.friction();
            core.time.setFriction(f);
            core.guard.afterChange(() -> core.time.setFriction(old));
        } finally {
            exit();
        }
    }

    public double getFriction() {
        enter();
        try {
            return core.time.friction();
        } finally {
            exit();
        }
    }

    public void setStrict(boolean strict) {
        core.lenient.setStrict(strict);
    }

    public boolean isStrict() {
        return core.lenient.strict();
    }

    public void setStabilityPolicy(StabilityPolicy policy) {
        if (policy == null) {
            throw new IllegalArgumentException("setStabilityPolicy: the policy must not be null");
        }
        enter();
        try {
            core.guard.setPolicy(policy);
        } finally {
            exit();
        }
    }

    public StabilityPolicy getStabilityPolicy() {
        enter();
        try {
            return core.guard.policy();
        } finally {
            exit();
        }
    }

    public void setMaxContactsPerMass(int n) {
        if (n < 0) {
            throw new IllegalArgumentException("setMaxContactsPerMass: the count must be >= 0, got " + n);
        }
        enter();
        try {
            core.guard.setMaxContacts(n);
        } finally {
            exit();
        }
    }

    public StabilityReport getStabilityReport() {
        enter();
        try {
            return core.guard.report();
        } finally {
            exit();
        }
    }

    public String describeStability() {
        enter();
        try {
            return core.guard.describe();
        } finally {
            exit();
        }
    }

    public void setDivergenceListener(DivergenceListener listener) {
        structuralDo(() -> {
            core.watch.setListener(listener);
        });
    }

    public void setDivergenceCheckInterval(int steps) {
        if (steps < 1) {
            throw new IllegalArgumentException("setDivergenceCheckInterval: the interval must be >= 1 step, got "
                    + steps);
        }
        structuralDo(() -> {
            core.engine.setDivergenceCheckInterval(steps);
        });
    }

    public void setDivergenceLimit(double limit) {
        Check.positive("setDivergenceLimit", "limit", "limit", limit);
        structuralDo(() -> {
            core.engine.guard().setLimit(limit);
        });
    }

    public boolean isDiverged() {
        enter();
        try {
            return core.watch.isDiverged();
        } finally {
            exit();
        }
    }

    /** @return the published divergence flag (see {@code PhysicalModel.isDivergedNow()}); enters nothing. */
    public boolean isDivergedNow() {
        return core.watch.divergedFlag();
    }

    public void clearDivergence() {
        structuralDo(() -> {
            core.watch.clear();
        });
    }
}
