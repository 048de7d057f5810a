package tactus;

/** What a {@link PhysicalModel} does when its stability analysis finds the explicit scheme unstable. */
public enum StabilityPolicy {
    /** Print one line naming the module, the parameter, its value and the limit (the default). */
    WARN,
    /** Throw an {@link UnstableModelException}; a change that caused it is undone first. */
    THROW,
    /** Do not analyse automatically (the analysis is still available on demand). */
    OFF
}
