package tactus.hapticstability;

import tactus.haptics.HapticLoop;

/**
 * The configuration {@link AdversarialHandsTest} asserts for: the one call the docs recommend for stiff walls.
 *
 * <p>The recommended call, {@link HapticLoop#useStiffContacts()} with one tick of exchange delay (on the 2DIY: the
 * bound at {@link HapticLoop#TWO_DIY_STIFF_CONTACT} with its count reserve; {@link
 * AdversarialSuite#STIFF_CONTACTS_COUNT_RESERVE}). On the 2DIY's stock encoders the suite still finds cases it fails
 * (docs/haptics-stability.md, "The adversarial suite" and "What limits the 2DIY"), so the test that asserts every
 * case is disabled until it passes.
 */
final class StiffContactsUnderTest {
    private StiffContactsUnderTest() {
    }

    /** Configures the loop (before it starts) as recommended for stiff walls. */
    static void configure(HapticLoop loop) {
        AdversarialSuite.STIFF_CONTACTS_COUNT_RESERVE.accept(loop);
    }
}
