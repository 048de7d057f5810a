package tactus.audio;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import tactus.PhysicalModel;
import tactus.Vect3D;

/**
 * {@link PhyUGen#setBlockSize(int)}: a block of samples computed in one pass through the model is bit for bit the
 * per-sample path's when nothing changes (block sizes that divide the run and one that does not, mono and stereo,
 * with and without oversampling, with an avatar pressing on the string and its force handed to the exchange every
 * step); a change lands at the first block boundary after it is made, never inside a block; a diverged model silences
 * the rest of its block.
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class PhyUGenBlockTest {
    private static final int SAMPLES = 3000;

    /** A 30-mass string plucked at mass 7, an avatar resting on mass 20 through a contact. */
    private static PhysicalModel scene() {
        PhysicalModel pm = new PhysicalModel(44100);
        StringModel.build(pm, 7, 0.001);
        Vect3D at = pm.getMass(StringModel.mass(20)).getPosition();
        pm.addHapticInput3D("av", new Vect3D(at.x, at.y + 0.0004, at.z), 10);
        pm.addContact3D("touch", 0.05, 0.001, 0.001, "av", StringModel.mass(20));
        pm.init();
        return pm;
    }

    /**
     * The run's output (left, then right, per sample) for this many samples, then the force the exchange holds at the
     * end (summed over every step).
     */
    private static double[] run(int block, int channels, int oversampling, int changeAt, int samples) {
        PhysicalModel pm = scene();
        PhyUGen u = new PhyUGen(pm);
        u.setBlockSize(block);
        if (oversampling > 1) {
            u.setOversampling(oversampling);
        }
        u.listenToMass(StringModel.mass(5), SteppedModel.Y, 300, -0.5);
        u.listenToElongation("s12", 40, 0.7);
        AvatarExchange ex = new AvatarExchange(AvatarExchange.ForceMode.SUM);
        Vect3D at = pm.getMass(StringModel.mass(20)).getPosition();
        ex.publishPosition(at.x, at.y + 0.0004, at.z);   // published once: nothing changes during the run
        u.attachAvatar("av", ex);
        float[] frame = new float[channels];
        double[] out = new double[2 * samples + 3];
        for (int i = 0; i < samples; i++) {
            if (i == changeAt) {
                pm.setLinkStiffness("s3", 0.3);
            }
            u.tick(frame);
            out[2 * i] = frame[0];
            out[2 * i + 1] = frame[channels - 1];
        }
        double[] f = new double[3];
        ex.takeForce(f);
        System.arraycopy(f, 0, out, 2 * samples, 3);
        return out;
    }

    private static double[] run(int block, int channels, int oversampling, int changeAt) {
        return run(block, channels, oversampling, changeAt, SAMPLES);
    }

    @Test
    void aBlockIsBitForBitThePerSamplePathWhenNothingChanges() {
        for (int channels : new int[] {1, 2}) {
            for (int oversampling : new int[] {1, 3}) {
                for (int block : new int[] {2, 7, 64, 1000, 1024}) {
                    int samples = (SAMPLES + block - 1) / block * block;   // whole blocks: the same steps were taken
                    double[] want = run(1, channels, oversampling, -1, samples);
                    double sound = 0;
                    for (int i = 0; i < 2 * samples; i++) {
                        sound += Math.abs(want[i]);
                    }
                    assertTrue(sound > 1e-3, "the reference sounds: " + sound);
                    assertTrue(want[2 * samples + 1] != 0, "the avatar feels the string");
                    double[] got = run(block, channels, oversampling, -1, samples);
                    for (int i = 0; i < want.length; i++) {
                        int s = i;
                        String where = s < 2 * samples ? "sample " + s / 2
                                : "the avatar's force, axis " + (s - 2 * samples);
                        assertEquals(Double.doubleToLongBits(want[i]), Double.doubleToLongBits(got[i]), () -> "block "
                                + block + ", " + channels + " channels, oversampling " + oversampling + ", " + where
                                + ": " + want[s] + " vs " + got[s]);
                    }
                }
            }
        }
    }

    /** The first sample at which the run with the change differs from the run without. */
    private static int firstDifference(int block, int changeAt) {
        double[] plain = run(block, 1, 1, -1);
        double[] changed = run(block, 1, 1, changeAt);
        for (int i = 0; i < SAMPLES; i++) {
            if (plain[2 * i] != changed[2 * i]) {
                return i;
            }
        }
        return -1;
    }

    @Test
    void aChangeLandsAtTheFirstBlockBoundaryAfterIt() {
        int perSample = firstDifference(1, 1000);   // two springs from the listened mass: heard two steps later
        assertTrue(perSample >= 1000 && perSample <= 1003, "per sample: the change is heard at once, at " + perSample);
        for (int block : new int[] {64, 100, 1000}) {
            for (int changeAt : new int[] {1000, 1001, 1063}) {
                int boundary = (changeAt + block - 1) / block * block;   // the first block start at or after it
                int heard = firstDifference(block, changeAt);
                assertEquals(boundary + (perSample - 1000), heard, "block " + block + ", change before sample "
                        + changeAt + ": heard from the block starting at " + boundary);
            }
        }
    }

    @Test
    void aDivergedModelSilencesTheRestOfItsBlockAndTheOutputIsNeverNaN() {
        PhysicalModel pm = scene();
        PhyUGen u = new PhyUGen(pm);
        u.setBlockSize(64);
        u.listenToMass(StringModel.mass(5), SteppedModel.Y, 300, 0);
        float[] frame = new float[1];
        for (int i = 0; i < 100; i++) {
            u.tick(frame);
        }
        assertTrue(frame[0] != 0, "it sounds before");
        pm.setLinkStiffness("s3", 1e9);   // explodes within a few steps: the next block begins with it
        int silentFrom = -1;
        for (int i = 100; i < 400; i++) {
            u.tick(frame);
            assertTrue(Float.isFinite(frame[0]), "sample " + i + " is finite");
            if (frame[0] == 0 && silentFrom < 0) {
                silentFrom = i;
            }
            if (silentFrom >= 0) {
                assertEquals(0, frame[0], 0, "silent after the divergence, sample " + i);
            }
        }
        assertTrue(silentFrom >= 128 && silentFrom < 128 + 64, "silent within the block the change landed in, from "
                + silentFrom);
        assertTrue(u.isSilenced());
    }

    @Test
    void aBlockSizeOutOfRangeIsRefusedNamingTheValueAndChangesNothing() {
        PhyUGen u = new PhyUGen(scene());
        u.setBlockSize(32);
        for (int bad : new int[] {0, -5, PhyUGen.MAX_BLOCK_SIZE + 1}) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> u.setBlockSize(bad));
            assertTrue(e.getMessage().contains(Integer.toString(bad)), e.getMessage());
            assertEquals(32, u.blockSize());
        }
    }
}
