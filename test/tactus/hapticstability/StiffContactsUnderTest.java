package tactus.hapticstability;

import tactus.haptics.HapticLoop;

/**
 * The configuration {@link AdversarialHandsTest} asserts for: the one call the docs recommend for stiff walls.
 *
 * <p>The recommended call, {@link HapticLoop#useStiffContacts} at {@link HapticLoop#TWO_DIY_STIFF_CONTACT} with one
 * tick of exchange delay ({@link AdversarialSuite#STIFF_CONTACTS}). The suite still finds cases it fails
 * (docs/haptics-stability.md, "The adversarial suite"), so the test that asserts it is disabled until it passes.
 */
final class StiffContactsUnderTest {
    private StiffContactsUnderTest() {
    }

    /** Configures the loop (before it starts) as recommended for stiff walls. */
    static void configure(HapticLoop loop) {
        AdversarialSuite.STIFF_CONTACTS.accept(loop);
    }
}
