/**
 * Real-time scheduling of threads on Linux, in a package that both the haptic side and the audio side may import:
 * SCHED_FIFO (and SCHED_DEADLINE) through util-linux's {@code chrt}, for a thread and for the JVM threads it may wait
 * for. Used by the haptic loop ({@code tactus.haptics.HapticLoop}) and by the audio output thread that plays a
 * {@code tactus.audio.PhyUGen} ({@code tactus.audio.AudioScheduling}). See docs/haptics.md ("Why
 * the loop was late") and docs/audio.md ("Audio under load").
 */
package tactus.scheduling;
