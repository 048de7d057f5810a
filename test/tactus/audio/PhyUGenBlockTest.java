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

    /**
     * A run through the recorded path (no avatar, listening points that all read masses): {@code points} points on
     * masses 5, 9 and 26 along y, panned apart; a ramp on s3 from {@code rampAt} on, and mass 9 removed before sample
     * {@code removeAt} (-1: never).
     */
    private static double[] recorded(int block, int channels, int points, int rampAt, int removeAt, int samples) {
        PhysicalModel pm = new PhysicalModel(44100);
        StringModel.build(pm, 7, 0.001);
        pm.init();
        PhyUGen u = new PhyUGen(pm);
        u.setBlockSize(block);
        int[] listened = {5, 26, 9};
        for (int i = 0; i < points; i++) {
            u.listenToMass(StringModel.mass(listened[i]), SteppedModel.Y, 300 - 50 * i, -0.8 + 0.7 * i);
        }
        pm.createLinkSubset("ramped");
        pm.addLinkToSubset("s3", "ramped");
        pm.addParamController("k3", "ramped", "stiffness", 0.01f);   // 441 steps
        tactus.ParamController ramp = pm.getParamController("k3");
        ramp.init(0.2f);
        float[] frame = new float[channels];
        double[] out = new double[2 * samples];
        for (int i = 0; i < samples; i++) {
            if (i == rampAt) {
                ramp.triggerRamp(0.9f);
            }
            if (i == removeAt) {
                pm.removeMatAndConnectedLinks(StringModel.mass(9));
            }
            u.tick(frame);
            out[2 * i] = frame[0];
            out[2 * i + 1] = frame[channels - 1];
        }
        return out;
    }

    @Test
    void aRecordedBlockIsBitForBitThePerSamplePath() {
        for (int channels : new int[] {1, 2}) {
            for (int points : new int[] {1, 3}) {
                for (int block : new int[] {2, 7, 64, 1000}) {
                    int samples = (SAMPLES + block - 1) / block * block;
                    double[] want = recorded(1, channels, points, -1, -1, samples);
                    double[] got = recorded(block, channels, points, -1, -1, samples);
                    double sound = 0;
                    for (int i = 0; i < want.length; i++) {
                        sound += Math.abs(want[i]);
                        int at = i;
                        assertEquals(Double.doubleToLongBits(want[i]), Double.doubleToLongBits(got[i]), () -> "block "
                                + block + ", " + channels + " channels, " + points + " points, sample " + at / 2
                                + ": " + want[at] + " vs " + got[at]);
                    }
                    assertTrue(sound > 1e-3, "the reference sounds: " + sound);
                }
            }
        }
    }

    @Test
    void aRampAndARemovedMassLandAtBlockBoundariesOnTheRecordedPath() {
        int block = 64;
        double[] plain = recorded(block, 2, 3, -1, -1, SAMPLES);
        // a ramp begun before sample 1001 steps from the block boundary at 1024 on: the per-sample run with the ramp
        // begun before sample 1024, bit for bit
        double[] ramped = recorded(block, 2, 3, 1001, -1, SAMPLES);
        double[] rampedPerSample = recorded(1, 2, 3, 1024, -1, SAMPLES);
        int heard = firstDifference(plain, ramped);
        assertTrue(heard > 1024 && heard < 1024 + 8, "the ramp is heard just after the boundary, at " + heard);
        for (int i = 0; i < ramped.length; i++) {
            assertEquals(Double.doubleToLongBits(rampedPerSample[i]), Double.doubleToLongBits(ramped[i]),
                    "sample " + i / 2);
        }
        // mass 9 removed before sample 1001: its point goes silent, the others go on sounding
        double[] removed = recorded(block, 2, 3, -1, 1001, SAMPLES);
        int from = firstDifference(plain, removed);
        assertTrue(from >= 1024 && from < 1024 + block, "the removal lands in the block from 1024, heard at " + from);
        double after = 0;
        for (int i = 2 * (1024 + block); i < removed.length; i++) {
            assertTrue(Double.isFinite(removed[i]));
            after += Math.abs(removed[i]);
        }
        assertTrue(after > 1e-3, "the other points sound on: " + after);
    }

    @Test
    void byDefaultABlockOfMassPointsEntersTheModelOnceAndOtherPointsSampleBySample() {
        for (boolean elongation : new boolean[] {false, true}) {
            PhysicalModel pm = new PhysicalModel(44100);
            StringModel.build(pm, 7, 0.001);
            pm.init();
            CountingSteppedModel counting = new CountingSteppedModel(new PhysicalModelStepper(pm));
            PhyUGen u = new PhyUGen(counting);
            assertEquals(64, u.blockSize(), "the default block");
            u.listenToMass(StringModel.mass(5), SteppedModel.Y, 300, 0);
            if (elongation) {
                u.listenToElongation("s12", 40, 0);
            }
            float[] frame = new float[1];
            double sound = 0;
            for (int i = 0; i < 64 * 20; i++) {
                u.tick(frame);
                sound += Math.abs(frame[0]);
            }
            assertTrue(sound > 1e-3, "it sounds: " + sound);
            if (elongation) {
                assertEquals(0, counting.recordings, "an elongation is read per sample");
                assertEquals(64 * 20, counting.steps);
            } else {
                assertEquals(20, counting.recordings, "one call per block");
                assertEquals(64 * 20, counting.recordedSteps);
                assertEquals(0, counting.steps);
                assertEquals(20, counting.samplesBegun, "the model entered once per block");
            }
        }
    }

    /**
     * A model that does not record a block itself gets {@link SteppedModel#stepRecording}'s default (a step and reads
     * per sample, through its own calls): the same samples, bit for bit, as the facade's one call per block and as
     * the per-sample path.
     */
    @Test
    void theInterfacesDefaultRecordingGivesTheSameSamples() {
        double[][] runs = new double[3][];
        for (int variant = 0; variant < 3; variant++) {
            PhysicalModel pm = new PhysicalModel(44100);
            StringModel.build(pm, 7, 0.001);
            pm.init();
            CountingSteppedModel counting = new CountingSteppedModel(new PhysicalModelStepper(pm), variant == 2);
            PhyUGen u = new PhyUGen(counting);
            u.setBlockSize(variant == 0 ? 1 : 64);
            u.listenToMass(StringModel.mass(5), SteppedModel.Y, 300, -0.5);
            u.listenToMass(StringModel.mass(22), SteppedModel.Y, 200, 0.5);
            u.setChannelCount(2);
            float[] frame = new float[2];
            runs[variant] = new double[2 * 64 * 30];
            for (int i = 0; i < 64 * 30; i++) {
                u.tick(frame);
                runs[variant][2 * i] = frame[0];
                runs[variant][2 * i + 1] = frame[1];
            }
            if (variant == 2) {
                assertEquals(30, counting.recordings, "one recording per block");
                assertEquals(64 * 30, counting.steps, "the default steps one sample at a time, through step()");
            }
        }
        for (int variant = 1; variant < 3; variant++) {
            for (int i = 0; i < runs[0].length; i++) {
                assertEquals(Double.doubleToLongBits(runs[0][i]), Double.doubleToLongBits(runs[variant][i]),
                        "variant " + variant + ", value " + i);
            }
        }
        double sound = 0;
        for (double v : runs[0]) {
            sound += Math.abs(v);
        }
        assertTrue(sound > 1e-3, "it sounds: " + sound);
    }

    /** The first sample (by its left channel) where b differs from a, -1 if none. */
    private static int firstDifference(double[] a, double[] b) {
        for (int i = 0; i < a.length / 2; i++) {
            if (a[2 * i] != b[2 * i]) {
                return i;
            }
        }
        return -1;
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
