package tactus.internal.model;

/**
 * What the rooms below the realtime rule ask of a realtime mode (implemented by
 * {@code tactus.internal.realtime.Ownership}): who is the owner, where a writer's changes go, how the stability check
 * and the avatar forces are shared with the owner. The rooms see the mode through this interface only, so the rule
 * can sit above them. Not API.
 */
public interface RealtimeMode {
    /** @return true when the current thread holds the stepping role. */
    boolean isOwnerThread();

    /** @return where the current thread's writes go: {@code direct} on the owner, else the batch it prepares. */
    EngineWrites writes(EngineWrites direct);

    /** @return true when the stability guard must not defer its check (see the guard). */
    boolean ignoresDeferral();

    /** @return true when the mode takes the stability check of this change over (run later, or by the owner). */
    boolean interceptCheck(Runnable undo);

    /**
     * Takes the force an avatar collected for readers on other threads.
     *
     * @param create true to start collecting for this avatar if nobody did yet (a reader that is not the owner)
     * @param xyz receives the force summed since the last take
     * @return the steps the force sums over, or -1 when nothing is collected for this avatar
     */
    long takeTappedForce(int id, double[] xyz, boolean create);

    /** Counts ramp members found removed while a ramp ran (see the owner's count of dropped commands). */
    void countDroppedRampMembers(int n);
}
