package tactus;

/**
 * Benchmark helper (not a test class): reads engine counters of a model from outside the {@code tactus} package,
 * for measurements in other test packages (such as {@code tactus.audio.AudioBench}).
 */
public final class EngineProbe {
    private EngineProbe() {
    }

    /** @return how many plans prepared by an editor thread the stepping thread has installed in this model. */
    public static long preparedInstalls(PhysicalModel pm) {
        return pm.core.engine.preparedInstalls();
    }
}
