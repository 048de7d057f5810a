package tactus.audio;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import org.junit.jupiter.api.Test;
import tactus.PhysicalModel;
import tactus.Vect3D;

/**
 * On the per-sample path ({@code setBlockSize(1)}; blocks are {@link PhyUGenBlockTest}'s), a PhyUGen's sample enters
 * the model once ({@link SteppedModel#beginSample()}); its output stays bit for bit that of
 * stepping the same model one sample at a time in locked mode with one facade call per step and per read, also when
 * the ticking thread changes a parameter between two samples, listens to an elongation beside a mass, or
 * oversamples.
 */
class PhyUGenSampleRunTest {
    private static final int RATE = 44100;
    private static final int SAMPLES = 3000;
    private static final double GAIN_MASS = 300;
    private static final double GAIN_LINK = 40;

    private static PhysicalModel string() {
        PhysicalModel pm = new PhysicalModel(RATE);
        StringModel.build(pm, 7, 0.001);
        pm.init();
        return pm;
    }

    /** The reference: locked mode, computeStep() then one read per listening point, mixed as PhyUGen mixes. */
    private static float[] reference(int changeAt) {
        PhysicalModel pm = string();
        String mass = StringModel.mass(5);
        double origin = pm.getMass(mass).getPosition().y;
        float[] out = new float[SAMPLES];
        for (int i = 0; i < SAMPLES; i++) {
            if (i == changeAt) {
                pm.setLinkStiffness("s3", 0.3);
            }
            pm.computeStep();
            double mono = 0;
            mono += GAIN_MASS * (pm.getMass(mass).getPosition().y - origin);
            mono += GAIN_LINK * pm.getLinkElongation("s9");
            out[i] = (float) mono;
        }
        return out;
    }

    private static float[] played(int changeAt) {
        PhysicalModel pm = string();
        PhyUGen u = new PhyUGen(pm);
        u.setBlockSize(1);
        u.setDcBlockerEnabled(false);
        u.listenToMass(StringModel.mass(5), SteppedModel.Y, GAIN_MASS, 0);
        u.listenToElongation("s9", GAIN_LINK, 0);
        float[] frame = new float[1];
        float[] out = new float[SAMPLES];
        for (int i = 0; i < SAMPLES; i++) {
            if (i == changeAt) {
                pm.setLinkStiffness("s3", 0.3); // the ticking thread is the owner: applied at once
            }
            u.tick(frame);
            out[i] = frame[0];
        }
        assertTrue(pm.isRealtimeStepping(), "played in realtime");
        assertEquals(Thread.currentThread(), pm.getRealtimeOwner());
        return out;
    }

    @Test
    void outputIsBitForBitThatOfOneFacadeCallPerStepAndRead() {
        assertTimeoutPreemptively(Duration.ofSeconds(30), () -> {
            for (int changeAt : new int[] {-1, 1, 1234}) {
                float[] want = reference(changeAt);
                float[] got = played(changeAt);
                double energy = 0;
                for (int i = 0; i < SAMPLES; i++) {
                    int k = i;
                    assertEquals(Float.floatToIntBits(want[i]), Float.floatToIntBits(got[i]),
                            () -> "change at " + changeAt + ", sample " + k + ": " + want[k] + " vs " + got[k]);
                    energy += got[i] * got[i];
                }
                assertTrue(energy > 1e-3, "it sounds");
            }
        });
    }

    /** With oversampling (k steps per sample, all inside one sample's run) the steps are those of k computeStep(). */
    @Test
    void oversampledStepsAreThoseOfOneStepPerCall() {
        assertTimeoutPreemptively(Duration.ofSeconds(30), () -> {
            PhysicalModel ref = string();
            PhysicalModel pm = string();
            PhyUGen u = new PhyUGen(pm);
            u.setBlockSize(1);
            u.listenToMass(StringModel.mass(5), SteppedModel.Y, GAIN_MASS, 0);
            u.setOversampling(3);
            ref.setSimRate(pm.getSimRate());
            float[] frame = new float[1];
            Vect3D a = new Vect3D();
            Vect3D b = new Vect3D();
            for (int i = 0; i < 500; i++) {
                u.tick(frame);
                ref.computeNSteps(1);
                ref.computeStep();
                ref.computeStep();
                for (int n = 1; n <= StringModel.N; n++) {
                    String name = StringModel.mass(n);
                    assertEquals(ref.getMass(name).getPosition(a).y, pm.getMass(name).getPosition(b).y, 0.0,
                            "sample " + i + ", " + name);
                }
            }
            assertEquals(ref.getStepCount(), pm.getStepCount());
        });
    }
}
