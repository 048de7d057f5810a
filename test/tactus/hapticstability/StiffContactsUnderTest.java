package tactus.hapticstability;

import tactus.haptics.HapticLoop;

/**
 * The configuration {@link AdversarialHandsTest} asserts for: the one call the docs recommend for stiff walls.
 *
 * <p>PLACEHOLDER: until the recommended configuration's call exists on {@link HapticLoop}, this sets the configuration
 * that was recommended before it (the coupling sized for the pen grip with the passivity controller and its 1 mJ
 * tolerance), which the suite shows failing; the lead switches the body to the recommended call and removes the
 * {@code @Disabled} on {@link AdversarialHandsTest#theRecommendedConfigurationPassesEveryCase()}.
 */
final class StiffContactsUnderTest {
    private StiffContactsUnderTest() {
    }

    /** Configures the loop (before it starts) as recommended for stiff walls. */
    static void configure(HapticLoop loop) {
        AdversarialSuite.GRIP_COUPLING_PC.accept(loop);   // PLACEHOLDER: replace with the recommended call
    }
}
