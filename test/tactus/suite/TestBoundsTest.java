package tactus.suite;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.platform.engine.discovery.DiscoverySelectors.selectClass;

import java.time.Duration;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.TimeoutException;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.ExtendWith;
import org.junit.jupiter.api.extension.ExtensionContext;
import org.junit.jupiter.api.extension.ParameterContext;
import org.junit.jupiter.api.extension.ParameterResolver;
import org.junit.platform.launcher.Launcher;
import org.junit.platform.launcher.LauncherDiscoveryRequest;
import org.junit.platform.launcher.core.LauncherDiscoveryRequestBuilder;
import org.junit.platform.launcher.core.LauncherFactory;
import org.junit.platform.launcher.listeners.SummaryGeneratingListener;
import org.junit.platform.launcher.listeners.TestExecutionSummary;

/**
 * Every test of the suite is bounded in time: {@code test/junit-platform.properties} sets a default timeout for
 * every testable and lifecycle method and runs timed methods in a thread of their own, so that even a busy loop
 * becomes a failure that names its test. These tests check that the file is on the launcher's class path and in
 * effect, and that a spinning test is really failed under it.
 */
@ExtendWith(TestBoundsTest.ContextResolver.class)
class TestBoundsTest {
    static final String DEFAULT_TIMEOUT = "junit.jupiter.execution.timeout.default";
    static final String THREAD_MODE = "junit.jupiter.execution.timeout.thread.mode.default";
    /** The bound must leave room for the slowest healthy test and still end a hang in minutes, s. */
    static final long MIN_BOUND_S = 60;
    static final long MAX_BOUND_S = 600;
    /** When the spinning target is stopped from outside if the timeout did not end it, ms. */
    static final long WATCHDOG_MS = 30_000;

    @Test
    void theDefaultTimeoutIsConfiguredForEveryMethod(ExtensionContext context) {
        Optional<String> value = context.getConfigurationParameter(DEFAULT_TIMEOUT);
        assertTrue(value.isPresent(), DEFAULT_TIMEOUT + " is not set: is junit-platform.properties on the class path?");
        Duration bound = parseTimeout(value.get());
        assertTrue(bound.getSeconds() >= MIN_BOUND_S && bound.getSeconds() <= MAX_BOUND_S,
                DEFAULT_TIMEOUT + " = " + value.get() + " is outside " + MIN_BOUND_S + ".." + MAX_BOUND_S + " s");
        assertEquals(Optional.of("SEPARATE_THREAD"), context.getConfigurationParameter(THREAD_MODE),
                "a spinning test is only ended in SEPARATE_THREAD mode");
    }

    /** In SEPARATE_THREAD mode the method runs on JUnit's timeout thread, not on the launcher's thread. */
    @Test
    void thisTestRunsOnATimeoutThread() {
        String name = Thread.currentThread().getName();
        assertTrue(name.startsWith("junit-timeout-thread"), "runs on '" + name + "': the timeout is not in effect");
    }

    /**
     * A nested launch of {@link SpinningTarget} with this class path's configuration, the default timeout
     * shortened to 1 s: the busy loop is failed by a timeout that names its method, and the launch returns.
     */
    @Test
    void aSpinningTestIsFailedAndNamed() {
        LauncherDiscoveryRequest request = LauncherDiscoveryRequestBuilder.request()
                .selectors(selectClass(SpinningTarget.class))
                .configurationParameter(DEFAULT_TIMEOUT, "1 s")
                .configurationParameter(SpinningTarget.ENABLE, "true")
                .build();
        Launcher launcher = LauncherFactory.create();
        SummaryGeneratingListener listener = new SummaryGeneratingListener();
        // Without SEPARATE_THREAD nothing would end the loop: a watchdog does, late, so that this test still ends.
        SpinningTarget.stop = false;
        Thread watchdog = new Thread(() -> {
            try {
                Thread.sleep(WATCHDOG_MS);
            } catch (InterruptedException e) {
                // ended early: the target is stopped below
            }
            SpinningTarget.stop = true;
        }, "spinning-target-watchdog");
        watchdog.setDaemon(true);
        watchdog.start();
        long start = System.nanoTime();
        try {
            launcher.execute(request, listener);
        } finally {
            SpinningTarget.stop = true;
            watchdog.interrupt();
        }
        double seconds = (System.nanoTime() - start) * 1e-9;
        TestExecutionSummary summary = listener.getSummary();
        assertEquals(1, summary.getTestsFoundCount(), "the spinning target was not found");
        assertEquals(1, summary.getTestsFailedCount(), "the spinning test was not failed");
        List<TestExecutionSummary.Failure> failures = summary.getFailures();
        Throwable cause = failures.get(0).getException();
        String message = String.valueOf(cause.getMessage());
        assertTrue(cause instanceof TimeoutException || message.contains("timed out"),
                "failed by something other than the timeout: " + cause);
        assertTrue(message.contains("spinsForEver"), "the failure does not name the test: " + message);
        assertTrue(seconds * 1000 < WATCHDOG_MS, "the nested launch took " + seconds + " s for a 1 s timeout: "
                + "only the watchdog ended the loop");
    }

    /** Parses JUnit's timeout syntax: a number and an optional unit (ns, μs, ms, s, m, h, d). */
    static Duration parseTimeout(String text) {
        Matcher m = Pattern.compile("\\s*(\\d+)\\s*(ns|μs|ms|s|m|h|d)?\\s*", Pattern.CASE_INSENSITIVE).matcher(text);
        assertTrue(m.matches(), "not a JUnit timeout: '" + text + "'");
        long n = Long.parseLong(m.group(1));
        String unit = m.group(2) == null ? "s" : m.group(2).toLowerCase();
        switch (unit) {
            case "ns": return Duration.ofNanos(n);
            case "μs": return Duration.ofNanos(n * 1000);
            case "ms": return Duration.ofMillis(n);
            case "m": return Duration.ofMinutes(n);
            case "h": return Duration.ofHours(n);
            case "d": return Duration.ofDays(n);
            default: return Duration.ofSeconds(n);
        }
    }

    /** Hands the current {@link ExtensionContext} to a test method that asks for it. */
    static final class ContextResolver implements ParameterResolver {
        @Override
        public boolean supportsParameter(ParameterContext p, ExtensionContext e) {
            return p.getParameter().getType() == ExtensionContext.class;
        }

        @Override
        public Object resolveParameter(ParameterContext p, ExtensionContext e) {
            return e;
        }
    }
}
