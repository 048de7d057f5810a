package tactus.suite;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ConditionEvaluationResult;
import org.junit.jupiter.api.extension.ExecutionCondition;
import org.junit.jupiter.api.extension.ExtendWith;
import org.junit.jupiter.api.extension.ExtensionContext;

/**
 * Not a test of the suite: the target of {@link TestBoundsTest#aSpinningTestIsFailedAndNamed()}, a test that
 * spins without ever reaching an interruptible call. {@code gradle test} leaves it out by name (build.gradle's
 * {@code --exclude-classname}); run from anywhere else, it is disabled unless the launch sets {@link #ENABLE}.
 */
@ExtendWith(SpinningTarget.OnlyWhenEnabled.class)
class SpinningTarget {
    static final String ENABLE = "tactus.suite.spinningTarget";
    /** Set by the test that launched this one, so that the abandoned timeout thread ends. */
    static volatile boolean stop;
    /** How many times the loop ran, once it has stopped. */
    static volatile long spins;

    @Test
    void spinsForEver() {
        long n = 0;
        while (!stop) {
            n++;   // no sleep, no wait: only a separate thread can end this test in time
        }
        spins = n;
    }

    /** Runs the target only in a launch that asks for it. */
    static final class OnlyWhenEnabled implements ExecutionCondition {
        @Override
        public ConditionEvaluationResult evaluateExecutionCondition(ExtensionContext context) {
            return context.getConfigurationParameter(ENABLE).map(Boolean::parseBoolean).orElse(false)
                    ? ConditionEvaluationResult.enabled("launched by TestBoundsTest")
                    : ConditionEvaluationResult.disabled("only TestBoundsTest runs this spinning target");
        }
    }
}
