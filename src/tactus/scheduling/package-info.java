/**
 * Real-time scheduling of threads on Linux, shared by the haptic loop ({@code tactus.haptics.HapticLoop}) and the
 * audio output thread that plays a {@code tactus.audio.PhyUGen} ({@code tactus.audio.AudioScheduling}): SCHED_FIFO
 * through util-linux's {@code chrt}, for a thread and for the JVM threads it may wait for. See docs/haptics.md ("Why
 * the loop was late") and docs/audio.md ("Audio under load").
 */
package tactus.scheduling;
