package tactus.internal.stability;

import tactus.engine.Engine;
import tactus.DivergenceException;
import tactus.DivergenceListener;
import tactus.internal.model.ApiAccess;
import tactus.internal.model.Directory;

/**
 * Turns a divergence found by the engine's guard into a {@link DivergenceException} naming the mass, thrown to
 * the stepping caller or handed once to a {@link DivergenceListener}. The caller holds the model's lock.
 */
public final class DivergenceWatch {
    private final Engine engine;
    private final Directory dir;
    private final double[] pos = new double[3];
    private DivergenceListener listener;
    private boolean notified;

    public DivergenceWatch(Engine engine, Directory dir) {
        this.engine = engine;
        this.dir = dir;
    }

    public void setListener(DivergenceListener l) {
        listener = l;
    }

    public boolean isDiverged() {
        return engine.divergedMass() >= 0;
    }

    /** Lets the engine step again and re-arms the listener. */
    public void clear() {
        engine.clearDivergence();
        notified = false;
    }

    /** Re-arms the listener after the model was cleared or its diverged mass removed. */
    public void reset() {
        notified = false;
    }

    /** Reports a divergence found by the last steps, if any: throws, or notifies the listener once. */
    public void check() {
        int id = engine.divergedMass();
        if (id < 0 || (listener != null && notified)) {
            return;
        }
        engine.position(id, pos);
        String name = dir.massName(id);
        DivergenceException ex = ApiAccess.get().divergence(dir.describeMass(id) + " diverged at step "
                + engine.divergedAt() + ": position (" + pos[0] + ", " + pos[1] + ", " + pos[2]
                + "); the model is frozen until clearDivergence()", name, engine.divergedAt());
        if (listener != null) {
            notified = true;
            listener.diverged(ex);
            return;
        }
        throw ex;
    }
}
