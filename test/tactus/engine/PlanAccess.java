package tactus.engine;

/**
 * Test-only access to plan stepping without the engine's step count and divergence guard, for tests in
 * other packages that must watch a model diverge unhindered (the analyser agreement sweep).
 */
public final class PlanAccess {
    private PlanAccess() {
    }

    /** Runs one step of a plan's kernels, without the divergence guard. */
    public static void stepWithoutGuard(StepPlan p) {
        p.step();
    }
}
