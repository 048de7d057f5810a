/**
 * The haptic loop's machinery, beside {@link tactus.haptics.HapticLoop} itself: the
 * {@link tactus.haptics.loop.DecoupledAvatar} that keeps a tick from waiting for the model's lock in audio mode,
 * the lock-free histograms behind the loop's jitter and compute-time percentiles, and the heap warm-up before a
 * real-time start. Only {@code DecoupledAvatar} is API; the others are marked "Not API" and public only for the loop.
 */
package tactus.haptics.loop;
