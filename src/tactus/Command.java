package tactus;

/**
 * A change of an audio-owned model, prepared by the thread that asked for it and applied by the thread that steps
 * the model, between two steps ({@link Ownership}). Commands form an intrusive queue through {@link #next}.
 */
abstract class Command {
    /** The next command in the queue; written once by the producer that links it. */
    volatile Command next;
    /** Position in the model's command sequence, assigned when posted. */
    long seq;

    /** Applies the change; runs on the stepping thread (or an editor that took over an idle model). */
    abstract void apply(ModelCore core);
}
