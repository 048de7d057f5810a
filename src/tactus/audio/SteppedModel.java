package tactus.audio;

/**
 * What the audio code needs from a model, and nothing more: step it, read listening points, drive an
 * avatar and collect the force on it. Names are resolved once (outside the audio path) into small integer
 * handles; the per-sample methods take handles, never allocate and never print.
 *
 * <p>Every method may be called only by the thread that owns the stepping (the audio thread while a
 * {@link PhyUGen} runs), except the {@code resolve*} methods, {@link #massPositionForSetup(int, int)} and
 * {@link #setStepRate(int)}, which a sketch calls while setting up; these share no scratch state with the
 * per-sample methods.
 *
 * <p>A per-sample method may throw when its element has left the model (removed, cleared): {@link PhyUGen} catches
 * that once, silences what it can no longer read, and asks {@code reattach*} now and then whether the element is
 * back under the same name.
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
     * @return true while the model cannot step (a diverged model, frozen until it is cleared): the audio thread
     *     then writes silence and does not step it; false by default
     */
    default boolean isHalted() {
        return false;
    }

    /**
     * @return the monitor to hold around one sample's calls (step, reads, avatar exchange) so that a model
     *     that locks per call pays for one lock per sample instead of several; a private object if the
     *     model needs no lock
     */
    java.util.concurrent.locks.Lock sampleLock();

    /**
     * Begins one sample's calls on the audio thread (its steps, reads and avatar exchange), ended by
     * {@link #endSample()} in a {@code finally}: a model that enters itself per call may enter once per sample
     * instead. The default locks {@link #sampleLock()}.
     */
    default void beginSample() {
        sampleLock().lock();
    }

    /** Ends the sample begun by {@link #beginSample()}; the default unlocks {@link #sampleLock()}. */
    default void endSample() {
        sampleLock().unlock();
    }

    /**
     * Runs up to n steps and records after each step the position of mass handle {@code masses[i]} along axis
     * {@code axes[i]} into {@code out[s * count + i]} (model units; s = 0 for the first step): one block of audio in
     * one pass, called between {@link #beginSample()} and {@link #endSample()} as one sample's calls are. The default
     * steps and reads one at a time; a model that can do it in one call overrides it. Throws as {@link #step()} and
     * {@link #massPosition(int, int)} do.
     *
     * @return the number of steps run: fewer than n when the model halted (see {@link #isHalted()})
     */
    default int stepRecording(int n, int[] masses, int[] axes, int count, double[] out) {
        for (int s = 0; s < n; s++) {
            if (isHalted()) {
                return s;
            }
            step();
            for (int i = 0; i < count; i++) {
                out[s * count + i] = massPosition(masses[i], axes[i]);
            }
        }
        return n;
    }

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

    /**
     * As {@link #massPosition(int, int)}, for the sketch's thread while it sets up (where a listening point starts
     * from); shares no scratch state with the audio thread's reads.
     */
    default double massPositionForSetup(int mass, int axis) {
        return massPosition(mass, axis);
    }

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

    /**
     * Looks again, by name, for a mass that left the model (audio thread, rarely: never per sample).
     *
     * @return true when the mass is in the model again and {@code mass} reads it; false by default
     */
    default boolean reattachMass(int mass) {
        return false;
    }

    /** As {@link #reattachMass(int)}, for an interaction. */
    default boolean reattachLink(int link) {
        return false;
    }

    /** As {@link #reattachMass(int)}, for a haptic avatar. */
    default boolean reattachAvatar(int avatar) {
        return false;
    }
}
