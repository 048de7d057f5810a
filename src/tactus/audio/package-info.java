/**
 * Hearing a model: {@link tactus.audio.PhyUGen}, a Minim unit generator that steps a mass-interaction
 * model once (or k times) per audio sample and mixes listening points into mono or stereo; the lock-free
 * multirate {@link tactus.audio.AvatarExchange} between the 1 kHz haptic thread and the audio thread;
 * {@link tactus.audio.VoiceBank}, the voices of a polyphonic instrument side by side in one model;
 * {@link tactus.audio.OfflineRenderer} that writes any Minim UGen graph to a WAV file with no sound card;
 * and {@link tactus.audio.LineOut}, which never lets a missing sound card become a NullPointerException.
 *
 * <p>The audio code reaches a model only through {@link tactus.audio.SteppedModel}; today's only
 * implementation, {@link tactus.audio.PhysicalModelStepper}, adapts the public {@link tactus.PhysicalModel} API.
 */
package tactus.audio;
