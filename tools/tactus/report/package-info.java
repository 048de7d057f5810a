/**
 * Report generators and their helpers: {@code gradle accuracyReport} ({@link tactus.report.AccuracyReport}),
 * the signal estimators it shares with the tests ({@link tactus.report.Measure}), and the line charts of the
 * reports and the demo ({@link tactus.report.LineChart}, drawn by JFreeChart).
 *
 * <p>This package belongs to the tools source set ({@code tools/}): it is not part of {@code Tactus.jar}, and
 * its chart library is not shipped in the Processing contribution.
 */
package tactus.report;
