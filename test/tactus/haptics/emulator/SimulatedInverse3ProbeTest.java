package tactus.haptics.emulator;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * {@link SimulatedInverse3#setProbe}: on a plant pushed by a hand, the probe sees every integration step, and the
 * hand's force it reports is the hand's spring and damper at the step's start; the work it integrates balances the
 * plant's kinetic energy and damping.
 */
@Timeout(value = 10, unit = TimeUnit.SECONDS)
class SimulatedInverse3ProbeTest {
    @Test
    void theProbeSeesEveryStepAndTheHandsForceAndItsWorkBalancesThePlant() {
        SimulatedInverse3 sim = new SimulatedInverse3();
        PlantParameters p = PlantParameters.cartesian3Dof().withoutFriction();
        sim.setPlant(p);
        double[] home = SimulatedInverse3.HOME;
        double k = 300;
        double b = 2;
        sim.setHand(Hand3D.followingScript((t, out) -> {
            out[0] = home[0];
            out[1] = home[1] - 0.005;   // a 5 mm step along -y
            out[2] = home[2];
        }, k, b));
        int[] steps = {0};
        double[] work = {0};
        double[] damped = {0};
        double[] last = {0};
        sim.setProbe((t, pos, vel, hand) -> {
            double h = t - last[0];
            last[0] = t;
            steps[0]++;
            for (int i = 0; i < 3; i++) {
                work[0] += hand[i] * vel[i] * h;
                damped[0] += p.jointDamping() * vel[i] * vel[i] * h;
            }
            // the hand's force is its spring towards the target and its damper, along y
            assertTrue(Math.abs(hand[0]) < 1e-9 && Math.abs(hand[2]) < 1e-9, "only along y: " + hand[0] + ", "
                    + hand[2]);
        });
        sim.advance(0.2);
        int expected = (int) Math.round(0.2 / p.substep());
        assertEquals(expected, steps[0], "one sample per 50 us step");
        double[] v = new double[3];
        sim.velocity(v);
        double kinetic = 0.5 * p.jointInertia() * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
        // what the hand put in went to the plant's motion and its damping (to within the integration's error)
        assertEquals(work[0], kinetic + damped[0], 0.02 * work[0] + 1e-7, "work " + work[0] + " J, kinetic "
                + kinetic + " J, damped " + damped[0] + " J");
        assertTrue(work[0] > 1e-4, "the hand did work: " + work[0] + " J");
    }
}
