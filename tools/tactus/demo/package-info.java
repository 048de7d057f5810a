/**
 * A headless demonstration of Tactus, run by {@code gradle demo}.
 *
 * <p>{@link tactus.demo.Demo} builds two models from the paper "Fast audio-haptic prototyping with
 * mass-interaction physics" (Leonard &amp; Villeneuve): the mass between two fixed points of its
 * Figure 4, and a plucked string like its audio-haptic string. It simulates two seconds of each,
 * prints a summary (final positions, energies, the string's pitch against theory) and writes CSV
 * files and PNG plots. It needs no display, no sound card and no haptic device.
 */
package tactus.demo;
