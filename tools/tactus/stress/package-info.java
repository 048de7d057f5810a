/**
 * Stress tools that run for minutes, outside {@code gradle test}: {@link tactus.stress.HapticStallStress} runs the
 * haptic loop in hundreds of fresh JVMs beside a CPU hog and counts the ticks that come more than 20 ms late.
 */
package tactus.stress;
