package tactus;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * {@link PhysicalModel#computeNStepsRecording}: the positions it records are those that {@code computeStep()} and
 * {@code getPosition()} read after each step, bit for bit (locked and realtime mode, one and several masses, a ramp
 * running); a bad argument is refused naming it and what to do, and leaves the model where it was; a mass that left
 * the model is refused before any step; a thread that does not own a realtime-stepped model steps nothing.
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class StepRecordingTest {
    private static final int N = 12;

    /** A plucked 3-D chain of N masses between two grounds, a ramp on the middle spring's stiffness. */
    private static PhysicalModel chain() {
        PhysicalModel pm = new PhysicalModel(44100, 60);
        pm.addGround3D("g0", new Vect3D(0, 0, 0));
        for (int i = 1; i <= N; i++) {
            pm.addMass3D("m" + i, 1, new Vect3D(i, 0.01 * Math.sin(i), 0.002 * i), new Vect3D());
        }
        pm.addGround3D("g1", new Vect3D(N + 1, 0, 0));
        pm.createLinkSubset("middle");
        for (int i = 0; i <= N; i++) {
            String a = i == 0 ? "g0" : "m" + i;
            String b = i == N ? "g1" : "m" + (i + 1);
            pm.addSpringDamper3D("s" + i, 0.9, 0.1, 0.001, a, b);
        }
        pm.addLinkToSubset("s6", "middle");
        pm.init();
        pm.addParamController("k", "middle", "stiffness", 0.002f);
        pm.getParamController("k").init(0.1f);
        return pm;
    }

    @Test
    void recordsWhatStepAndReadSeeBitForBit() {
        String[] names = {"m3", "m9", "m3"};
        int[] axes = {1, 0, 2};
        for (boolean realtime : new boolean[] {false, true}) {
            for (int count : new int[] {1, 3}) {
                PhysicalModel want = chain();
                PhysicalModel got = chain();
                if (realtime) {
                    got.beginRealtimeStepping();
                }
                Mass[] masses = new Mass[count];
                for (int i = 0; i < count; i++) {
                    masses[i] = got.getMass(names[i]);
                }
                int[] ax = java.util.Arrays.copyOf(axes, count);
                double[] out = new double[64 * count];
                Vect3D p = new Vect3D();
                for (int block = 0; block < 20; block++) {
                    if (block == 5) {
                        want.getParamController("k").triggerRamp(0.4f);   // 88 steps: over two blocks
                        got.getParamController("k").triggerRamp(0.4f);
                    }
                    assertEquals(64, got.computeNStepsRecording(64, masses, ax, out));
                    for (int s = 0; s < 64; s++) {
                        want.computeStep();
                        for (int i = 0; i < count; i++) {
                            want.getMass(names[i]).getPosition(p);
                            double v = ax[i] == 0 ? p.x : ax[i] == 1 ? p.y : p.z;
                            assertEquals(Double.doubleToLongBits(v), Double.doubleToLongBits(out[s * count + i]),
                                    "realtime " + realtime + ", block " + block + ", step " + s + ", mass " + i);
                        }
                    }
                }
                assertEquals(want.getStepCount(), got.getStepCount());
                assertTrue(Math.abs(got.getLinkStiffness("s6") - 0.4) < 1e-6, "the ramp ran to its end");
            }
        }
    }

    @Test
    void aBadArgumentIsRefusedNamingItAndNothingSteps() {
        PhysicalModel pm = chain();
        PhysicalModel other = chain();
        Mass m = pm.getMass("m2");
        Vect3D before = m.getPosition();
        Object[][] cases = {
            {-1, new Mass[] {m}, new int[] {0}, new double[4], "-1"},
            {2, null, new int[] {0}, new double[4], "no masses"},
            {2, new Mass[] {m}, null, new double[4], "no axes"},
            {2, new Mass[] {m}, new int[] {0}, null, "no output array"},
            {2, new Mass[] {m}, new int[] {0, 1}, new double[4], "one axis per mass"},
            {5, new Mass[] {m}, new int[] {0}, new double[4], "need 5"},
            {2, new Mass[] {m}, new int[] {3}, new double[4], "axes[0]"},
            {2, new Mass[] {null}, new int[] {0}, new double[4], "masses[0] is null"},
            {2, new Mass[] {other.getMass("m2")}, new int[] {0}, new double[4], "another model"},
        };
        for (Object[] c : cases) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                    () -> pm.computeNStepsRecording((Integer) c[0], (Mass[]) c[1], (int[]) c[2], (double[]) c[3]));
            assertTrue(e.getMessage().startsWith("computeNStepsRecording") && e.getMessage().contains((String) c[4]),
                    e.getMessage());
            assertEquals(0, pm.getStepCount(), "nothing stepped: " + e.getMessage());
        }
        pm.removeMatAndConnectedLinks("m5");
        Mass gone = pm.getMass("m4");
        pm.removeMatAndConnectedLinks("m4");
        IllegalStateException e = assertThrows(IllegalStateException.class,
                () -> pm.computeNStepsRecording(2, new Mass[] {m, gone}, new int[] {0, 0}, new double[4]));
        assertTrue(e.getMessage().contains("no longer part of its model"), e.getMessage());
        assertEquals(0, pm.getStepCount());
        assertEquals(before.y, m.getPosition().y, 0);
    }

    @Test
    void aThreadThatDoesNotOwnTheRealtimeModelStepsNothing() throws Exception {
        PhysicalModel pm = chain();
        pm.beginRealtimeStepping();
        pm.computeStep();   // this thread owns the model now
        CountDownLatch done = new CountDownLatch(1);
        int[] ran = {-1};
        Thread t = new Thread(() -> {
            ran[0] = pm.computeNStepsRecording(10, new Mass[] {pm.getMass("m1")}, new int[] {1}, new double[10]);
            done.countDown();
        });
        t.start();
        assertTrue(done.await(20, TimeUnit.SECONDS));
        assertEquals(0, ran[0], "refused: another thread owns the model");
        assertEquals(1, pm.getStepCount());
    }
}
