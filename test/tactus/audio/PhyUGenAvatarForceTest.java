package tactus.audio;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

import tactus.PhysicalModel;
import tactus.Vect3D;

/**
 * The force on an avatar reaches the haptic side through PhyUGen's exchange even when the avatar's force was first
 * read on another thread than the audio thread (PhyUGen reads it once when the exchange is attached, usually from the
 * sketch's thread): a regression test for a realtime-stepping defect where, after that first read, the audio thread's
 * own reads found the engine's accumulator already moved into the other thread's tap and passed on zero force.
 */
class PhyUGenAvatarForceTest {

    private static PhysicalModel scene() {
        PhysicalModel m = new PhysicalModel(44100, 60);
        m.setGravity(0);
        m.addHapticInput3D("av", new Vect3D(0, 0, 0), 10);
        m.addMass3D("m", 1, new Vect3D(0, 1, 0), new Vect3D());
        m.addContact3D("c", 0.01, 0.001, 0.5, "av", "m");
        m.init();
        return m;
    }

    @Test
    void theContactForceOnTheAvatarReachesTheExchangeWhateverThreadAttachedIt() throws Exception {
        int blocks = 20;
        int perBlock = 7 * PhyUGen.DEFAULT_BLOCK_SIZE;   // whole blocks per burst, as Minim's buffers are (448 samples)
        // reference: the same scene stepped and read on one thread, with no PhyUGen
        PhysicalModel plain = scene();
        double[] expected = new double[blocks];
        Vect3D f = new Vect3D();
        for (int k = 0; k < blocks; k++) {
            plain.setHapticPosition("av", new Vect3D(0, 0.2 * k, 0));
            for (int i = 0; i < perBlock; i++) {
                plain.computeStep();
            }
            expected[k] = plain.getHapticForce("av", f).y;
        }

        for (int attachOnOtherThread = 0; attachOnOtherThread < 2; attachOnOtherThread++) {
            PhysicalModel m = scene();
            PhyUGen u = new PhyUGen(m);
            AvatarExchange ex = new AvatarExchange();
            if (attachOnOtherThread == 1) {
                Thread t = new Thread(() -> u.attachAvatar("av", ex));
                t.start();
                t.join();
            } else {
                u.attachAvatar("av", ex);
            }
            double[] got = new double[3];
            double impulse = 0;
            double expectedImpulse = 0;
            float[] frame = new float[2];
            // the audio thread is this test's thread; the exchange publishes a new position per block, applied at
            // the block's first sample, as setHapticPosition before the block in the reference
            for (int k = 0; k < blocks; k++) {
                ex.publishPosition(0, 0.2 * k, 0);
                for (int i = 0; i < perBlock; i++) {
                    u.tick(frame);
                }
                long n = ex.takeForce(got);
                assertEquals(perBlock, n, "samples spanned by block " + k);
                double sum = got[1] * n;
                assertEquals(expected[k], sum, 1e-12 + 1e-9 * Math.abs(expected[k]),
                        "force summed over block " + k + " (attached on " + (attachOnOtherThread == 1 ? "another" : "the audio")
                                + " thread)");
                impulse += Math.abs(sum);
                expectedImpulse += Math.abs(expected[k]);
            }
            assertTrue(expectedImpulse > 0, "the reference scene has a contact");
            assertTrue(impulse > 0.5 * expectedImpulse, "force reached the exchange: " + impulse);
        }
    }
}
