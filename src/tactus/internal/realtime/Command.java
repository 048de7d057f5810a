package tactus.internal.realtime;

import tactus.internal.ModelCore;


/**
 * A change of an audio-owned model, prepared by the thread that asked for it and applied by the thread that steps
 * the model, between two steps ({@link Ownership}). Commands form an intrusive queue through {@link #next}.
 */
public abstract class Command {
    /** The next command in the queue; written once by the producer that links it. */
    public volatile Command next;
    /** Position in the model's command sequence, assigned when posted. */
    public long seq;

    /**
     * Applies the change; runs on the thread that holds the gate (the owner, or an editor applying the queue of a
     * model nobody steps). Must not throw for a target that was removed after the command was posted: such a write
     * is skipped.
     *
     * @return true when the change was applied in full, false when some of its targets were gone (those writes were
     *     skipped, the others applied): the command is then counted as dropped
     */
    public abstract boolean apply(ModelCore core);
}
