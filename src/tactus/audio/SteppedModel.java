package tactus.audio;

/**
 * What the audio code needs from a model, and nothing more: step it, read listening points, drive an
 * avatar and collect the force on it. Names are resolved once (outside the audio path) into small integer
 * handles; the per-sample methods take handles, never allocate and never print.
 *
 * <p>Every method may be called only by the thread that owns the stepping (the audio thread while a
 * {@link PhyUGen} runs), except the {@code resolve*} methods and {@link #setStepRate(int)}, which a sketch
 * calls while setting up.
 */
public interface SteppedModel {
    /** Axis index of x. */
    int X = 0;
    /** Axis index of y. */
    int Y = 1;
    /** Axis index of z. */
    int Z = 2;

    /** @return the simulation rate, in steps per second. */
    int stepRate();

    /** Sets the simulation rate, in steps per second (&gt; 0). */
    void setStepRate(int stepsPerSecond);

    /** Runs one simulation step. */
    void step();

    /**
     * @return the monitor to hold around one sample's calls (step, reads, avatar exchange) so that a model
     *     that locks per call pays for one lock per sample instead of several; a private object if the
     *     model needs no lock
     */
    java.util.concurrent.locks.Lock sampleLock();

    /** @return a handle for the mass with this name; throws IllegalArgumentException naming it if absent. */
    int resolveMass(String name);

    /**
     * @param withForce true if {@link #linkTension(int)} will be read (rejects kinds whose force law the
     *     adapter cannot reproduce)
     * @return a handle for the interaction with this name; throws IllegalArgumentException if absent
     */
    int resolveLink(String name, boolean withForce);

    /** @return a handle for the haptic avatar (an input module) with this name. */
    int resolveAvatar(String name);

    /** @return the position of a mass along an axis ({@link #X}, {@link #Y} or {@link #Z}), in model units. */
    double massPosition(int mass, int axis);

    /** @return the elongation of an interaction (distance minus its length parameter), in model units. */
    double linkElongation(int link);

    /**
     * @return the tension of an interaction, K e + Z de/dt, positive when stretched (REAL_UNITS: N); read it
     *     once per step, since the rate of elongation is taken from the previous read
     */
    double linkTension(int link);

    /** Sets the position (model units) that an avatar follows through its EWMA from the next step on. */
    void setAvatarTarget(int avatar, double x, double y, double z);

    /**
     * Writes into {@code out[0..2]} the force applied to an avatar since the last call, summed over the steps
     * in between (REAL_UNITS: N), and resets the model's accumulator.
     */
    void takeAvatarForce(int avatar, double[] out);
}
