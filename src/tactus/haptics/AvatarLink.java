package tactus.haptics;

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

    /** Advances the model by n steps (haptics-only mode; in audio mode the audio thread steps it). */
    void step(int n);
}
