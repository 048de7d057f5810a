package tactus.hapticstability;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import tactus.haptics.emulator.PlantParameters;

/**
 * The coupling sized for a pen grip, with the passivity controller and its tolerance, holds the 2DIY's pen-grip wall
 * at 200 and 400 times the uncontrolled bound K0 = 40.7 N/m (10 and 20 times the 814 N/m the grip holds without
 * control): the sweep's press through the real loop, protocol and board emulator on the 2DIY plant, in simulated
 * time (docs/haptics-stability.md, "Passivity control").
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class GripCouplingWallTest {
    private static final double K0 = 40.7;

    private static WallRig.Variant variant(String name) {
        for (WallRig.Variant v : StabilitySweep.VARIANTS) {
            if (v.name().equals(name)) {
                return v;
            }
        }
        throw new AssertionError("no variant " + name);
    }

    private static Object[] press(String variant, double k) {
        WallRig.Config c = StabilitySweep.pressConfig(PlantParameters.twoDiy(), variant(variant), k, 0);
        WallRig.Trace t = WallRig.run(c);
        return new Object[] {EmulatorBoundary.judge(c, t), t};
    }

    @Test
    void thePenGripWallHoldsAtTwoAndFourHundredK0StablyPassivelyAndWithoutBuzz() {
        for (double multiple : new double[] {200, 400}) {
            double k = multiple * K0;
            Touch direct = (Touch) press("uncontrolled", k)[0];
            assertFalse(direct.stable, multiple + " K0 uncontrolled: the wall bounces the hand");
            assertTrue(direct.energyToHand > 1e-3, multiple + " K0 uncontrolled: energy to the hand " + direct.energyToHand);
            Object[] r = press("grip coupling + PC", k);
            Touch grip = (Touch) r[0];
            WallRig.Trace trace = (WallRig.Trace) r[1];
            assertTrue(grip.stable, multiple + " K0 with the grip coupling: residual " + grip.residual + " m");
            assertTrue(grip.energyToHand <= 0, multiple + " K0 with the grip coupling: energy to the hand "
                    + grip.energyToHand + " J");
            // no buzz: the force steps only by what the encoders' steps give through the coupling (0.3 N measured;
            // with no tolerance the controller's bursts step it by 1.7 N)
            assertTrue(trace.forceStep < 0.6, multiple + " K0: largest force step " + trace.forceStep + " N");
            // felt: the coupling in series with the wall
            double series = k * PassivityVariants.GRIP_COUPLING_STIFFNESS / (k + PassivityVariants.GRIP_COUPLING_STIFFNESS);
            assertEquals(series, grip.feltFraction * k, 0.15 * series, multiple + " K0: felt stiffness");
        }
    }
}
