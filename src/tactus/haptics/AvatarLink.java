package tactus.haptics;

import tactus.haptics.loop.DecoupledAvatar;

/**
 * What the haptic loop needs from a physical model: set the avatar's target position, take the force the
 * model has put on the avatar, and step the model. Implementations must not allocate in these calls.
 * {@link PhysicalModelAvatar} adapts a {@link tactus.PhysicalModel}.
 */
public interface AvatarLink {

    /** Sets the position (model units) the avatar follows through its own smoothing. */
    void setTarget(double x, double y, double z);

    /**
     * Writes the force on the avatar (model force units), summed over the steps since the last call, into
     * out[0..2], and resets the sum.
     */
    void takeForce(double[] out);

    /**
     * As {@link #takeForce}, and returns how many model steps the sum covers (0 when no step ran since the
     * last call), or -1 if the link cannot tell (the default). The haptic loop uses the count in
     * {@link HapticLoop.Mode#AUDIO} to render the mean force per step, since the audio thread runs its steps
     * in bursts.
     */
    default long takeForceCounted(double[] out) {
        takeForce(out);
        return -1;
    }

    /**
     * True if {@link #setTarget} and {@link #takeForce} never wait for another thread (a link over lock-free
     * channels, such as an audio-side exchange); the haptic loop then calls it directly in
     * {@link HapticLoop.Mode#AUDIO} instead of wrapping it in a {@link DecoupledAvatar}. Default: false.
     */
    default boolean neverWaits() {
        return false;
    }

    /** Advances the model by n steps (haptics-only mode; in audio mode the audio thread steps it). */
    void step(int n);

    /**
     * Called by {@link HapticLoop#start()} in {@link HapticLoop.Mode#HAPTICS_ONLY}, on the thread that starts the
     * loop, before the loop thread runs: the link may hand its model to the loop thread as the one thread that
     * steps it, so that a tick never waits for a lock that a slower thread holds. Default: nothing.
     */
    default void beginStepping() {
    }

    /**
     * Called by {@link HapticLoop#stop()} after the loop thread has ended (haptics-only mode), on the thread that
     * stops the loop: undoes {@link #beginStepping()}. Default: nothing.
     */
    default void endStepping() {
    }
}
