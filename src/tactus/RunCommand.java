package tactus;

import java.util.ArrayList;
import java.util.List;
import java.util.function.Supplier;

/**
 * A structural change of an audio-owned model (adding or removing modules, subsets, contact groups, rates,
 * velocity control, ...): the facade call's own code, run on the stepping thread between two steps while the
 * calling thread waits. Its result or exception is handed back; the undo actions it registers with the stability
 * guard are collected so that the caller can analyse the model afterwards and undo under THROW.
 */
final class RunCommand extends Command {
    private final Supplier<?> body;
    Object result;
    Throwable error;
    /** Undo actions registered during the run, in order; null entries are checks with nothing to undo. */
    final List<Runnable> undo = new ArrayList<>();
    boolean analyse;

    RunCommand(Supplier<?> body) {
        this.body = body;
    }

    /** Records a change the stability guard should check (and how to undo it). */
    void capture(Runnable u) {
        analyse = true;
        if (u != null) {
            undo.add(u);
        }
    }

    /** Runs the call's code; its result or exception goes back to the waiting caller, so it is never dropped. */
    @Override
    boolean apply(ModelCore core) {
        try {
            result = body.get();
        } catch (Throwable t) {
            error = t;
        }
        return true;
    }
}
