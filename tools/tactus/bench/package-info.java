/**
 * The engine benchmarks behind {@code gradle bench}: standard scenes, each timed in its own forked JVM on
 * JDK 17 (and JDK 25 when installed), and the report they write to {@code docs/performance.md}.
 *
 * <p>This package belongs to the tools source set ({@code tools/}): it is not part of {@code Tactus.jar}
 * and never runs in {@code gradle test} (except for a short smoke test of the harness).
 */
package tactus.bench;
