package tactus.internal.stability;

import tactus.engine.Engine;
import tactus.DivergenceException;
import tactus.DivergenceListener;
import tactus.internal.model.ApiAccess;
import tactus.internal.model.Directory;

/**
 * Turns a divergence found by the engine's guard into a {@link DivergenceException} naming the mass and the module
 * most likely at fault, thrown to the stepping caller or handed once to a {@link DivergenceListener}. The caller
 * holds the model's lock. Finding the suspect runs one stability analysis, once per divergence (the model is then
 * frozen until it is cleared).
 */
public final class DivergenceWatch {
    private final Engine engine;
    private final Directory dir;
    private final double[] pos = new double[3];
    private DivergenceListener listener;
    private boolean notified;
    /**
     * Whether the engine holds a divergence, published for lock-free readers ({@link #divergedFlag()}): written by
     * the thread that steps (after each stepping call) or clears the model.
     */
    private volatile boolean diverged;

    /** The module most likely at fault, found when a divergence is reported (once per divergence). */
    private final java.util.function.Supplier<String> suspect;

    /**
     * @param suspect names the module most likely at fault, with its parameter and limit (the stability guard's
     *     analysis); asked once per divergence, under the model's lock; may return null
     */
    public DivergenceWatch(Engine engine, Directory dir, java.util.function.Supplier<String> suspect) {
        this.engine = engine;
        this.dir = dir;
        this.suspect = suspect;
    }

    public void setListener(DivergenceListener l) {
        listener = l;
    }

    public boolean isDiverged() {
        return engine.divergedMass() >= 0;
    }

    /**
     * @return the published divergence flag, read without the model's lock: on the stepping thread it is
     *     {@link #isDiverged()}; on another thread, as of the last stepping call or {@link #clear()} that returned
     */
    public boolean divergedFlag() {
        return diverged;
    }

    /** Lets the engine step again and re-arms the listener. */
    public void clear() {
        engine.clearDivergence();
        diverged = false;
        notified = false;
    }

    /** Re-arms the listener after the model was cleared or its diverged mass removed. */
    public void reset() {
        notified = false;
    }

    /**
     * Reports a divergence found by the last steps, if any: throws, or notifies the listener once. Publishes the
     * flag of {@link #divergedFlag()} first. Formats no string: the exception carries the raw facts and formats its
     * message when it is read.
     */
    public void check() {
        int id = engine.divergedMass();
        if ((id >= 0) != diverged) {
            diverged = id >= 0;
        }
        if (id < 0 || (listener != null && notified)) {
            return;
        }
        engine.position(id, pos);
        String cause;
        try {
            cause = suspect.get();
        } catch (RuntimeException e) {
            cause = null; // the analysis failed: the exception still names the mass
        }
        DivergenceException ex = ApiAccess.get().divergence(engine.massKind(id).label(), dir.massName(id),
                engine.divergedAt(), pos[0], pos[1], pos[2], cause);
        if (listener != null) {
            notified = true;
            listener.diverged(ex);
            return;
        }
        throw ex;
    }
}
