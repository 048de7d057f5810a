/**
 * The soak tool ({@code gradle soak -Pseconds=600}): one model played by a {@code PhyUGen} on Minim's real audio
 * thread (the virtual output), touched by a haptic loop on the board emulator, drawn at 60 fps from its snapshot,
 * while a fourth thread makes random valid and invalid calls. It reports what escaped a thread, every API call
 * that took over a second, late audio blocks, missed haptic ticks and NaN reaching an output. See
 * {@link tactus.soak.Soak}.
 */
package tactus.soak;
