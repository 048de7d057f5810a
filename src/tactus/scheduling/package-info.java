/**
 * Real-time scheduling of threads on Linux, in a package that both the haptic side and the audio side may import:
 * SCHED_FIFO through util-linux's {@code chrt}, for a thread and for the JVM threads it may wait for. Used by the
 * audio output thread that plays a {@code tactus.audio.PhyUGen} ({@code tactus.audio.AudioScheduling}); the haptic
 * loop's own copy ({@code tactus.haptics.RealtimeScheduling}) is meant to move here. See docs/haptics.md ("Why
 * the loop was late") and docs/audio.md ("Audio under load").
 */
package tactus.scheduling;
