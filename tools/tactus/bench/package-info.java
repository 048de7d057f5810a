/**
 * The engine benchmarks behind {@code gradle bench}: standard scenes, each timed in its own forked JVM on
 * JDK 17 (and JDK 25 when installed), the side-by-side comparison with the paper's engine ({@link tactus.bench.SideBySide},
 * scenes in {@link tactus.bench.paper}), and the report they write to {@code docs/performance.md}; and
 * {@link tactus.bench.BeforeAfter} ({@code gradle beforeAfter}), the paired comparison of two builds in one JVM.
 *
 * <p>This package belongs to the tools source set ({@code tools/}): it is not part of {@code Tactus.jar}
 * and never runs in {@code gradle test} (except for short tests of the harness and the report logic).
 */
package tactus.bench;
