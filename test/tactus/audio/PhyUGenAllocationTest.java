package tactus.audio;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.management.ManagementFactory;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import tactus.PhysicalModel;
import tactus.Vect3D;

/**
 * Generating audio allocates nothing per sample: a PhyUGen over the plucked string with an avatar coupled
 * through an AvatarExchange, contacts from the avatar to every mass, and every kind of listening point
 * (displacement, elongation, tension), in stereo, with and without oversampling. The UGen is ticked the
 * way Minim ticks it (UGen.tick) while the JVM's per-thread allocation counter is read around the loop;
 * the counter's own cost is measured and subtracted, and a one-off JIT event is forgiven by repeating
 * the measurement up to three times (a real per-sample allocation shows in every repetition).
 *
 * <p>The avatar force is read with the model's non-allocating getHapticForce(String, Vect3D).
 */
class PhyUGenAllocationTest {

    private static PhysicalModel stringWithAvatar() {
        PhysicalModel pm = new PhysicalModel(44100);
        StringModel.build(pm, 7, 0.001);
        pm.addHapticInput3D("avatar", new Vect3D(1.5, 0.5, 0), 30);
        for (int i = 1; i <= StringModel.N; i++) {
            pm.addContact3D("c" + i, 0.05, 0.01, 0.001, "avatar", StringModel.mass(i));
        }
        pm.init();
        return pm;
    }

    @ParameterizedTest
    @ValueSource(ints = {1, 2})
    void tickAllocatesNothing(int oversampling) {
        PhyUGen u = new PhyUGen(stringWithAvatar());
        assertEquals(0, measure(u, oversampling));
    }

    @ParameterizedTest
    @ValueSource(ints = {7, 64})
    void tickInBlocksAllocatesNothing(int block) {
        PhyUGen u = new PhyUGen(stringWithAvatar());
        u.setBlockSize(block);
        assertEquals(0, measure(u, 2));
    }

    /**
     * The recorded block path (listening points that all read masses, no avatar): blocks of several sizes, mono and
     * stereo.
     */
    @ParameterizedTest
    @ValueSource(ints = {2, 64, 512})
    void aRecordedBlockAllocatesNothing(int block) {
        PhysicalModel pm = new PhysicalModel(44100);
        StringModel.build(pm, 7, 0.001);
        pm.init();
        PhyUGen u = new PhyUGen(pm);
        u.setBlockSize(block);
        ListeningPoint a = u.listenToMass(StringModel.mass(3), SteppedModel.Y, 100, -0.5);
        u.listenToMass(StringModel.mass(17), SteppedModel.Y, 100, 0.5);
        for (int channels : new int[] {1, 2}) {
            u.setChannelCount(channels);
            float[] frame = new float[channels];
            for (int i = 0; i < 100_000; i++) {
                u.tick(frame);
            }
            long[] measured = allocatedBy(() -> {
                for (int i = 0; i < 100_000; i++) {
                    u.tick(frame);
                }
            });
            long last = lastMeasured(measured);
            assertTrue(Float.isFinite(frame[0]) && a.gain() == 100);
            assertEquals(0, last, "block " + block + ", " + channels + " channels: bytes allocated by 10^5 samples: "
                    + java.util.Arrays.toString(measured));
        }
    }

    /** @return the bytes allocated by 10^5 samples (the last of up to six measurements: JIT
     * recompilations settle in the first ones; a real per-sample allocation shows in every one). */
    private static long measure(PhyUGen u, int oversampling) {
        u.listenToMass(StringModel.mass(3), SteppedModel.Y, 100, -0.5);
        u.listenToElongation("s5", 10, 0.5);
        u.listenToTension("s9", 10, 0);
        u.listenToTension("c10", 10, 0);
        AvatarExchange ex = new AvatarExchange();
        u.attachAvatar("avatar", ex);
        u.setOversampling(oversampling);
        u.setSampleRate(44100);
        u.setChannelCount(2);
        float[] frame = new float[2];
        double[] force = new double[3];
        // warm-up; the avatar sweeps through the string so contacts engage and release
        for (int i = 0; i < 200_000; i++) {
            if (i % 44 == 0) {
                ex.publishPosition(1.5, 0.5 - i * 1e-5, 0);
                ex.takeForce(force);
            }
            u.tick(frame);
        }
        long[] measured = allocatedBy(() -> {
            for (int i = 0; i < 100_000; i++) {
                if (i % 44 == 0) {
                    ex.publishPosition(1.5, -1.5 + i * 2e-5, 0);
                    ex.takeForce(force);
                }
                u.tick(frame);
            }
        });
        long last = lastMeasured(measured);
        assertTrue(Float.isFinite(frame[0]) && Float.isFinite(frame[1]));
        assertEquals(0, last, "bytes allocated by 10^5 samples: " + java.util.Arrays.toString(measured));
        return last;
    }

    /**
     * @return the bytes the calling thread allocates in each of up to six runs of {@code work} (the counter's own
     *     cost subtracted), stopping at the first run that allocates nothing: JIT recompilations settle in the first
     *     runs, a real per-sample allocation shows in every one; runs not made are -1
     */
    private static long[] allocatedBy(Runnable work) {
        com.sun.management.ThreadMXBean mx = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        assertTrue(mx.isThreadAllocatedMemorySupported() && mx.isThreadAllocatedMemoryEnabled());
        long tid = Thread.currentThread().getId();
        long[] measured = {-1, -1, -1, -1, -1, -1};
        for (int attempt = 0; attempt < measured.length; attempt++) {
            long b0 = mx.getThreadAllocatedBytes(tid);
            long b1 = mx.getThreadAllocatedBytes(tid);
            long a0 = mx.getThreadAllocatedBytes(tid);
            work.run();
            measured[attempt] = mx.getThreadAllocatedBytes(tid) - a0 - (b1 - b0);
            if (measured[attempt] == 0) {
                break;
            }
        }
        return measured;
    }

    /** @return the last run's bytes of {@link #allocatedBy}. */
    private static long lastMeasured(long[] measured) {
        long last = -1;
        for (long m : measured) {
            if (m >= 0) {
                last = m;
            }
        }
        return last;
    }
}
