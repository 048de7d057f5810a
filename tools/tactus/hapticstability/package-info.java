/**
 * The stability of stiff virtual walls on an emulated haptic device: the sampled-data theory
 * ({@link tactus.hapticstability.SampledWallTheory}), a deterministic rig that runs the real haptic loop against the
 * emulated board and plant in simulated time ({@link tactus.hapticstability.WallRig}), and the sweep
 * ({@link tactus.hapticstability.StabilitySweep}, {@code gradle stabilitySweep}) that writes docs/haptics-stability-*.csv and
 * plots. Never part of the library.
 */
package tactus.hapticstability;
