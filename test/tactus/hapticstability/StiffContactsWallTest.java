package tactus.hapticstability;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import tactus.haptics.HapticLoop;
import tactus.haptics.emulator.PlantParameters;

/**
 * The recommended configuration for stiff walls ({@code HapticLoop.useStiffContacts} at
 * {@link HapticLoop#TWO_DIY_STIFF_CONTACT}, the "stiff contacts" variant) on the sweep's pen-grip press through the real
 * loop, protocol and board emulator on the 2DIY plant, in simulated time: at 40 to 400 K0 (K0 = 40.7 N/m) the wall is
 * stable, the plant never gave the hand energy at any instant, the force never stepped by more than 0.5 N, and the
 * hand felt more than the 814 N/m the grip holds without control (docs/haptics-stability.md, "Stiff contacts").
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class StiffContactsWallTest {
    private static final double K0 = 40.7;

    @Test
    void thePenGripFeelsMoreThanTheUncontrolledLimitPassivelyAndWithoutBuzz() {
        for (double multiple : new double[] {40, 80, 200, 400}) {
            double k = multiple * K0;
            WallRig.Config c = StabilitySweep.pressConfig(PlantParameters.twoDiy(), PassivityVariants.stiffContacts(1), k, 0);
            WallRig.Trace t = WallRig.run(c);
            Touch r = EmulatorBoundary.judge(c, t);
            assertTrue(r.stable, multiple + " K0: residual " + r.residual + " m");
            double peak = StiffContactScan.peakEnergyToHand(t);
            assertTrue(peak <= 1e-6, multiple + " K0: energy to the hand at some instant " + peak + " J");
            assertTrue(t.forceStep <= 0.5, multiple + " K0: largest force step " + t.forceStep + " N");
            double felt = StiffContactScan.feltHolding(c, t);
            assertTrue(felt > 1.2 * 814 && felt <= 1.05 * HapticLoop.TWO_DIY_STIFF_CONTACT,
                    multiple + " K0: felt " + felt + " N/m");
        }
        // the same press uncontrolled bounces the hand from 80 K0 on (the test can fail)
        WallRig.Config c = StabilitySweep.pressConfig(PlantParameters.twoDiy(), WallRig.UNCONTROLLED, 80 * K0, 0);
        assertFalse(EmulatorBoundary.judge(c, WallRig.run(c)).stable, "80 K0 uncontrolled");
    }
}
