package tactus.internal.realtime;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Supplier;
import tactus.internal.ModelCore;

/**
 * A structural change of an audio-owned model (adding or removing modules, subsets, contact groups, rates,
 * velocity control, ...): the facade call's own code, run on the stepping thread between two steps while the
 * calling thread waits. Its result or exception is handed back; the undo actions it registers with the stability
 * guard are collected so that the caller can analyse the model afterwards and undo under THROW.
 */
public final class RunCommand extends Command {
    private final Supplier<?> body;
    public Object result;
    public Throwable error;
    /** Undo actions registered during the run, in order; null entries are checks with nothing to undo. */
    public final List<Runnable> undo = new ArrayList<>();
    public boolean analyse;

    public RunCommand(Supplier<?> body) {
        this.body = body;
    }

    /** Records a change the stability guard should check (and how to undo it). */
    public void capture(Runnable u) {
        analyse = true;
        if (u != null) {
            undo.add(u);
        }
    }

    /** Runs the call's code; its result or exception goes back to the waiting caller, so it is never dropped. */
    @Override
    public boolean apply(ModelCore core) {
        try {
            result = body.get();
        } catch (Throwable t) {
            error = t;
        }
        return true;
    }
}
