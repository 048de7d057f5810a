package tactus.hapticstability;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import org.junit.jupiter.api.Disabled;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import tactus.haptics.HapticLoop;

/**
 * The adversarial suite of hands and walls (docs/haptics-stability.md, "The adversarial suite") asserted for the
 * configuration recommended for stiff walls ({@link StiffContactsUnderTest}): every case of
 * {@link AdversarialSuite#cases()} through the real loop on the emulated 2DIY in simulated time must be stable, give
 * the hand at most {@link AdversarialSuite#ENERGY_TOLERANCE} at every instant, and step the force by at most
 * {@link AdversarialSuite#FORCE_STEP_LIMIT} between ticks, and be felt at least {@link AdversarialSuite#feltFloor}.
 * The self-checks show that the suite can fail: it flags the uncontrolled wall at 200 K0, the grip coupling with the
 * controller's 1 mJ tolerance on a wall switched on around the handle, and a configuration that renders the wall as
 * 1 N/m; and it passes a wall the loop renders without control. Each run takes its simulated length (about 1 s).
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class AdversarialHandsTest {
    @Test
    @Timeout(value = 90, unit = TimeUnit.SECONDS)   // 24 runs of about 1 s of simulated time each
    @Disabled("on the 2DIY's stock encoders useStiffContacts() still fails 5 of 24 cases, none on passivity or force "
            + "steps (docs/haptics-stability.md, \"The adversarial suite\", \"What limits the 2DIY\"): enable when "
            + "it passes")
    void theRecommendedConfigurationPassesEveryCase() {
        List<AdversarialCase> cases = AdversarialSuite.cases();
        assertTrue(cases.size() >= 20, "the suite has " + cases.size() + " cases");
        List<String> failed = AdversarialChecks.rejected(cases,
                c -> AdversarialRig.run(c, StiffContactsUnderTest::configure), (c, r) -> AdversarialSuite.passes(r),
                "under test");
        assertTrue(failed.isEmpty(), failed.size() + " of " + cases.size() + " cases fail:\n"
                + AdversarialSuite.HEADER + "\n" + String.join("\n", failed));
    }

    @Test
    @Timeout(value = 90, unit = TimeUnit.SECONDS)   // 24 runs of about 1 s of simulated time each
    void theCountReserveGivesTheHandNothingInAnyCaseAndLosesNoWallThatHasFriction() {
        // every case: the energy to the hand and the force steps within the suite's limits; every press or stiffened
        // wall on the plant with friction is felt (at least 150 N/m) and still, where the bound alone loses the slow
        // presses and the loose hold's (felt at about 0 N/m)
        List<AdversarialCase> cases = AdversarialSuite.cases();
        long felt = cases.stream().filter(c -> c.friction && AdversarialSuite.feltFloor(c) > 0).count();
        assertTrue(felt >= 9, felt + " cases with friction read a felt stiffness");
        List<String> bad = AdversarialChecks.rejected(cases,
                c -> AdversarialRig.run(c, AdversarialSuite.STIFF_CONTACTS_COUNT_RESERVE),
                (c, r) -> AdversarialChecks.passiveWithoutBuzz(r)
                        && (!c.friction || AdversarialSuite.feltFloor(c) == 0 || r.stable && r.felt >= 150),
                "count reserve");
        assertTrue(bad.isEmpty(), AdversarialSuite.HEADER + "\n" + String.join("\n", bad));
    }

    @Test
    void theCountReserveKeepsTheSlowPressThatTheBoundAloneLoses() {
        AdversarialCase slow = new AdversarialCase(AdversarialCase.Kind.PRESS, AdversarialCase.Grip.PEN,
                200 * AdversarialCase.K0, 0.005, true, 0);
        AdversarialRig.Result with = AdversarialRig.run(slow, AdversarialSuite.STIFF_CONTACTS_COUNT_RESERVE);
        AdversarialRig.Result without = AdversarialRig.run(slow, AdversarialSuite.STIFF_CONTACTS);
        String table = AdversarialSuite.HEADER + "\n" + AdversarialSuite.row("with the reserve", with) + "\n"
                + AdversarialSuite.row("without", without);
        assertTrue(without.felt < 50, "the bound alone loses the slow press's wall:\n" + table);
        assertTrue(with.felt > 200 && with.stable && with.maxEnergyToHand <= AdversarialSuite.ENERGY_TOLERANCE,
                table);
    }

    @Test
    void theContactPlayKeepsAWallStiffenedUnderTheHandThatTheBoundAloneLoses() {
        AdversarialCase stiffen = new AdversarialCase(AdversarialCase.Kind.STIFFEN, AdversarialCase.Grip.PEN,
                200 * AdversarialCase.K0, 0.02, true, 0);
        AdversarialRig.Result with = AdversarialRig.run(stiffen, AdversarialSuite.STIFF_CONTACTS);
        AdversarialRig.Result without = AdversarialRig.run(stiffen, loop -> {
            AdversarialSuite.STIFF_CONTACTS.accept(loop);
            loop.setContactPlay(false);
        });
        String table = AdversarialSuite.HEADER + "\n" + AdversarialSuite.row("with the play", with) + "\n"
                + AdversarialSuite.row("without", without);
        assertTrue(AdversarialSuite.passes(with), table);
        assertTrue(with.felt >= AdversarialSuite.feltFloor(stiffen), table);
        assertTrue(without.felt < AdversarialSuite.feltFloor(stiffen), "without the play the encoders' flicker "
                + "drains the bound and the wall is lost:\n" + table);
    }

    @Test
    void theSuitePassesAWallTheLoopRendersWithoutControl() {
        // 10 K0 with the pen grip (it holds about 20 K0 uncontrolled): a press and a tap are passive and still
        AdversarialCase press = new AdversarialCase(AdversarialCase.Kind.PRESS, AdversarialCase.Grip.PEN,
                10 * AdversarialCase.K0, 0.02, true, 0);
        AdversarialCase tap = new AdversarialCase(AdversarialCase.Kind.TAP, AdversarialCase.Grip.PEN,
                10 * AdversarialCase.K0, 0.1, true, 0);
        for (AdversarialCase c : new AdversarialCase[] {press, tap}) {
            AdversarialRig.Result r = AdversarialRig.run(c, AdversarialSuite.UNCONTROLLED);
            assertTrue(AdversarialSuite.passes(r), AdversarialSuite.HEADER + "\n" + AdversarialSuite.row("uncontrolled", r));
        }
    }

    @Test
    void theSuiteFlagsTheUncontrolledWallAtTwoHundredK0() {
        AdversarialCase press = new AdversarialCase(AdversarialCase.Kind.PRESS, AdversarialCase.Grip.PEN,
                200 * AdversarialCase.K0, 0.02, true, 0);
        AdversarialRig.Result r = AdversarialRig.run(press, AdversarialSuite.UNCONTROLLED);
        assertNull(r.failure, "the loop failed");
        assertFalse(r.stable, "the uncontrolled wall at 200 K0 bounces the hand: residual " + r.residual + " m");
        assertTrue(r.maxEnergyToHand > AdversarialSuite.ENERGY_TOLERANCE, "energy to the hand " + r.maxEnergyToHand);
        assertFalse(AdversarialSuite.passes(r));
    }

    @Test
    void theSuiteFlagsTheGripCouplingWithItsToleranceOnAWallSwitchedOnAroundTheHandle() {
        AdversarialCase on = new AdversarialCase(AdversarialCase.Kind.SWITCH_ON, AdversarialCase.Grip.PEN,
                200 * AdversarialCase.K0, 0.02, true, 0);
        AdversarialRig.Result r = AdversarialRig.run(on, AdversarialSuite.GRIP_COUPLING_PC);
        assertNull(r.failure, "the loop failed");
        // the wall pushes the handle out 3 mm against the pen grip's 300 N/m: about 1.35 mJ into the hand's spring
        assertTrue(r.maxEnergyToHand > 1e-3, "energy to the hand " + r.maxEnergyToHand + " J");
        assertFalse(AdversarialSuite.passes(r));
    }

    @Test
    void theSuiteFlagsAConfigurationThatDoesNotRenderTheWall() {
        // passive and still, but the hand feels 1 N/m: not a wall
        AdversarialCase press = new AdversarialCase(AdversarialCase.Kind.PRESS, AdversarialCase.Grip.PEN,
                200 * AdversarialCase.K0, 0.02, true, 0);
        AdversarialRig.Result r = AdversarialRig.run(press, loop -> loop.useStiffContacts(1));
        assertTrue(r.felt < AdversarialSuite.feltFloor(press), "felt " + r.felt + " N/m");
        assertFalse(AdversarialSuite.passes(r), AdversarialSuite.row("1 N/m", r));
    }

    @Test
    void aRunDependsOnlyOnTheTickCountAndTheWallChangeLandsOnItsTick() {
        AdversarialCase on = new AdversarialCase(AdversarialCase.Kind.STIFFEN, AdversarialCase.Grip.PEN,
                400 * AdversarialCase.K0, 0.02, false, 0);
        AdversarialRig.Result a = AdversarialRig.run(on, AdversarialSuite.GRIP_COUPLING_PC);
        AdversarialRig.Result b = AdversarialRig.run(on, AdversarialSuite.GRIP_COUPLING_PC);
        assertEquals(a.maxEnergyToHand, b.maxEnergyToHand, 0, "the largest energy to the hand");
        assertEquals(a.endEnergyToHand, b.endEnergyToHand, 0, "the energy to the hand at the end");
        assertEquals(a.forceStep, b.forceStep, 0, "the largest force step");
        assertEquals(a.residual, b.residual, 0, "the residual");
    }
}
