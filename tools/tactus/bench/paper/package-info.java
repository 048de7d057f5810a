/**
 * The side-by-side benchmark against the paper's engine: {@link tactus.bench.paper.PaperScenes} is written once against
 * the paper's API and compiled twice (against Tactus here, against a {@code miPhysics.jar} by
 * {@link tactus.bench.SideBySide}, which changes its engine import line only); the two other classes are the
 * Tactus-only parts it loads by name (a contact group and a snapshot reader).
 *
 * <p>Tools source set: not part of {@code Tactus.jar}.
 */
package tactus.bench.paper;
