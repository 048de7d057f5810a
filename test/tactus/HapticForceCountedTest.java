package tactus;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicReference;

import org.junit.jupiter.api.Test;

/**
 * getHapticForceCounted reads the avatar's summed force and the number of steps it covers together, so that
 * force / steps is the exact mean force per step, also while another thread steps the model in realtime and in
 * bursts (as Minim's audio thread does). The scene holds the avatar still against a stretched spring to a fixed
 * point, so every step puts the same force on it: any read whose count and sum disagree by one step is off by at
 * least 1/burst of that force.
 */
class HapticForceCountedTest {

    private static final double K = 0.01;
    private static final double STRETCH = 0.5;

    private static PhysicalModel scene() {
        PhysicalModel m = new PhysicalModel(44100, 60);
        m.setGravity(0);
        m.addGround3D("anchor", new Vect3D(0, 0, 0));
        m.addHapticInput3D("avatar", new Vect3D(1 + STRETCH, 0, 0), 1);
        m.addSpring3D("spring", 1, K, "anchor", "avatar");
        m.init();
        return m;
    }

    @Test
    void withoutRealtimeSteppingTheCountIsTheStepsBetweenReads() {
        PhysicalModel m = scene();
        Vect3D f = new Vect3D();
        m.getHapticForceCounted("avatar", f);
        for (int steps : new int[] {1, 7, 44, 0, 1000}) {
            m.computeNSteps(steps);
            long n = m.getHapticForceCounted("avatar", f);
            assertEquals(steps, n, "steps covered");
            assertEquals(-K * STRETCH * steps, f.x, 1e-12 * Math.max(1, steps), "summed force after " + steps);
        }
        assertThrows(IllegalArgumentException.class, () -> m.getHapticForceCounted("avatar", null));
        assertThrows(IllegalArgumentException.class, () -> m.getHapticForceCounted("anchor", new Vect3D()));
    }

    @Test
    void whileAnotherThreadStepsInBurstsEveryReadIsTheExactMeanTimesItsCount() throws Exception {
        for (int burst : new int[] {1, 64, 1024}) {
            PhysicalModel m = scene();
            m.beginRealtimeStepping();
            AtomicBoolean stop = new AtomicBoolean();
            AtomicReference<Throwable> failure = new AtomicReference<>();
            Thread audio = new Thread(() -> {
                try {
                    while (!stop.get()) {
                        for (int i = 0; i < burst; i++) {
                            m.computeStep();
                        }
                        Thread.sleep(0, 200_000);
                    }
                } catch (Throwable t) {
                    failure.set(t);
                }
            });
            audio.start();
            Vect3D f = new Vect3D();
            long total = 0;
            int reads = 0;
            long deadline = System.nanoTime() + 400_000_000L;
            while (System.nanoTime() < deadline) {
                long n = m.getHapticForceCounted("avatar", f);
                if (n > 0) {
                    assertEquals(-K * STRETCH, f.x / n, 1e-12, "mean force per step over " + n + " steps (burst " + burst + ")");
                    reads++;
                } else {
                    assertEquals(0, f.x, 0, "no step, no force (burst " + burst + ")");
                }
                total += n;
                Thread.sleep(1);
            }
            stop.set(true);
            audio.join();
            assertEquals(null, failure.get());
            assertTrue(reads > 20, "reads with steps: " + reads);
            assertTrue(total > 0 && total <= m.getStepCount(), "steps counted " + total + " of " + m.getStepCount());
        }
    }
}
