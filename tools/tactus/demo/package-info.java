/**
 * A headless demonstration of Tactus, run by {@code gradle demo}.
 *
 * <p>{@link tactus.demo.Demo} runs three models from the paper "Fast audio-haptic prototyping with
 * mass-interaction physics" (Leonard &amp; Villeneuve). Two are simulated offline for two seconds each: the
 * mass between two fixed points of its Figure 4, and a plucked string in SI units; it prints a summary
 * (final positions, energies, the string's pitch against theory) and writes CSV files and PNG plots. The
 * third, {@link tactus.demo.AudioHapticPluck}, is the paper's audio-haptic plucked string run end to end in
 * real time: an emulated Haply through the real protocol code, the 1 kHz haptic loop, a 44.1 kHz
 * {@code PhyUGen}; it writes {@code pluck.wav}, a frame drawn by the library's renderer, the hand path with
 * the force felt, the waveform and the haptic telemetry, and compares the WAV's pitch with theory. It needs
 * no display, no sound card and no haptic device.
 */
package tactus.demo;
