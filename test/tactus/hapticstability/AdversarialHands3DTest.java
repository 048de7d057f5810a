package tactus.hapticstability;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * The adversarial suite on the emulated 3-DoF device ({@link AdversarialRig3D}: the Inverse3's Cartesian plant in
 * lockstep, no tick of delay, positions not quantised; docs/haptics-stability.md, "On the 3-DoF plant"): the energy
 * bound at 3300 N/m with half the plant's damping declared gives the hand at most the suite's tolerance and steps the
 * force by at most 0.5 N in every case, and holds the presses with friction that the pen grip and the stiff pinch
 * make (the stiff pinch at the bound's stiffness); without the declared damping a bounce loses the wall; the
 * self-check shows the rig can fail (the uncontrolled wall stiffened under the hand bounces it and gives it energy).
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class AdversarialHands3DTest {
    @Test
    @Timeout(value = 90, unit = TimeUnit.SECONDS)   // 24 runs of about 1 s of simulated time each
    void theEnergyBoundGivesTheHandNothingAndHoldsThePressesOnThe3DofPlant() {
        List<AdversarialCase> cases = AdversarialSuite.cases();
        long held = cases.stream().filter(AdversarialHands3DTest::heldPress).count();
        assertTrue(held >= 6, held + " presses checked");
        List<String> bad = AdversarialChecks.rejected(cases,
                c -> AdversarialRig3D.run(c, AdversarialSuite.STIFF_CONTACTS_3DOF),
                (c, r) -> AdversarialChecks.passiveWithoutBuzz(r) && (!heldPress(c) || r.stable
                        && r.felt >= (c.grip == AdversarialCase.Grip.STIFF_PINCH ? 3000 : 600)), "3-DoF");
        assertTrue(bad.isEmpty(), AdversarialSuite.HEADER + "\n" + String.join("\n", bad));
    }

    /** A press with friction by the pen grip or the stiff pinch: the wall must hold it. */
    private static boolean heldPress(AdversarialCase c) {
        return c.kind == AdversarialCase.Kind.PRESS && c.friction && c.grip != AdversarialCase.Grip.LOOSE_HOLD;
    }

    @Test
    void theDeclaredDampingKeepsTheWallThatABounceLosesOtherwise() {
        AdversarialCase press = new AdversarialCase(AdversarialCase.Kind.PRESS, AdversarialCase.Grip.PEN,
                200 * AdversarialCase.K0, 0.02, true, 0);
        AdversarialRig.Result with = AdversarialRig3D.run(press, AdversarialSuite.STIFF_CONTACTS_3DOF);
        AdversarialRig.Result without = AdversarialRig3D.run(press, AdversarialSuite.STIFF_CONTACTS_3DOF_UNDECLARED);
        String table = AdversarialSuite.HEADER + "\n" + AdversarialSuite.row("declared", with) + "\n"
                + AdversarialSuite.row("undeclared", without);
        assertTrue(without.felt < 0, "without the declaration the bounce loses the wall:\n" + table);
        assertTrue(with.felt > 800 && AdversarialSuite.passes(with), table);
    }

    @Test
    void theRigFlagsTheUncontrolledWallStiffenedUnderTheHand() {
        AdversarialCase stiffen = new AdversarialCase(AdversarialCase.Kind.STIFFEN, AdversarialCase.Grip.PEN,
                200 * AdversarialCase.K0, 0.02, true, 0);
        AdversarialRig.Result r = AdversarialRig3D.run(stiffen, AdversarialSuite.UNCONTROLLED);
        assertNull(r.failure, "the loop failed");
        assertFalse(r.stable, "residual " + r.residual + " m");
        assertTrue(r.maxEnergyToHand > 1e-3, "energy to the hand " + r.maxEnergyToHand + " J");
        assertFalse(AdversarialSuite.passes(r));
    }
}
