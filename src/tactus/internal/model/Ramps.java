package tactus.internal.model;

/**
 * The parameter ramps of a model's controllers, as the stepping calls see them (the controllers themselves are API
 * types, kept above). Not API.
 */
public interface Ramps {
    /** @return true when some controller is in the middle of a ramp. */
    boolean ramping();

    /** Advances every running ramp by one step. */
    void advanceAll();

    /** Forgets every controller (the model was cleared). */
    void clear();
}
