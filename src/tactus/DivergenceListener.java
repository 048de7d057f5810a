package tactus;

/**
 * Receives divergence events instead of an exception being thrown from the stepping call. It is called
 * once per divergence, on the thread that steps the model (for example the audio or haptic thread), so
 * it must return quickly: a haptic loop typically zeroes its motor torque here.
 */
public interface DivergenceListener {
    /** Called once when the model diverges; the model is frozen until it is cleared. */
    void diverged(DivergenceException event);
}
