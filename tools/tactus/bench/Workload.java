package tactus.bench;

/**
 * One thing the harness times: a built model (or a hand-written loop) that can be advanced by some number of
 * steps. Every workload of a scene is built before the warm-up; {@link #advance(int)} must allocate nothing in
 * steady state for the allocation figure to mean anything.
 */
interface Workload {
    /** @return a short name for the variant, for example {@code "PhysicalModel"} or {@code "hand loop"}. */
    String variant();

    /**
     * @return the element updates per step: inertial masses that move plus every interaction (fixed points are
     *     stepped but not counted; see {@link Scenes} for each scene's count)
     */
    long elements();

    /** Advances the workload by {@code steps} simulation steps (samples, for the audio scenes). */
    void advance(int steps);

    /** @return a value read from the state (a position): keeps the work observable and shows a blow-up. */
    double probe();

    /** @return the {@code tactus.PhysicalModel} or {@code tactus.engine.Engine} behind it, or null. */
    Object model();
}
