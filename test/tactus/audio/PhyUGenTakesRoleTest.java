package tactus.audio;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicReference;
import java.util.concurrent.locks.LockSupport;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import tactus.PhysicalModel;
import tactus.StabilityPolicy;
import tactus.Vect3D;

/**
 * A PhyUGen's audio thread takes the model's stepping role explicitly: a sketch that stepped the model first, and
 * keeps calling draw_physics() at its frame rate (so it never looks idle), cannot keep the sound silent. From the
 * audio thread's first sample on, the model advances by exactly one step per sample and the sketch's stepping calls
 * do nothing.
 */
class PhyUGenTakesRoleTest {
    private static final Duration BOUND = Duration.ofSeconds(30);

    private static PhysicalModel oscillator() {
        PhysicalModel pm = new PhysicalModel(44100, 60);
        pm.setStabilityPolicy(StabilityPolicy.OFF);
        pm.addGround3D("g", new Vect3D(0, 0, 0));
        pm.addMass3D("m", 1, new Vect3D(1, 0.1, 0), new Vect3D());
        pm.addSpringDamper3D("s", 1, 0.01, 0.0001, "g", "m");
        pm.init();
        return pm;
    }

    /**
     * @param framePauseMicros how long the sketch's thread rests between two draw_physics() calls (a frame of
     *     735 steps each): from back to back to 60 fps
     */
    @ParameterizedTest
    @ValueSource(ints = {0, 2_000, 16_000})
    void theAudioThreadTakesTheModelFromASketchThatSteppedItFirst(int framePauseMicros) {
        assertTimeoutPreemptively(BOUND, () -> {
            PhysicalModel pm = oscillator();
            PhyUGen u = new PhyUGen(pm);
            u.setSampleRate(44100);
            u.setChannelCount(1);
            u.listenToMass("m", SteppedModel.Y, 1, 0);
            assertNull(pm.getRealtimeOwner(), "nobody has stepped yet");

            AtomicBoolean stop = new AtomicBoolean();
            AtomicReference<Throwable> sketchError = new AtomicReference<>();
            Thread sketch = new Thread(() -> {
                try {
                    while (!stop.get()) {
                        pm.draw_physics();
                        if (framePauseMicros > 0) {
                            LockSupport.parkNanos(framePauseMicros * 1000L);
                        }
                    }
                } catch (Throwable t) {
                    sketchError.set(t);
                }
            }, "sketch draw()");
            sketch.start();
            long deadline = System.nanoTime() + 10_000_000_000L;
            while (pm.getRealtimeOwner() != sketch && System.nanoTime() < deadline) {
                Thread.sleep(1);
            }
            assertSame(sketch, pm.getRealtimeOwner(), "the sketch stepped first and owns the model");

            int samples = 138 * PhyUGen.DEFAULT_BLOCK_SIZE;   // whole blocks: 8,832 samples
            long[] counts = new long[2];
            float[] peak = new float[1];
            AtomicReference<Throwable> audioError = new AtomicReference<>();
            // read by the audio thread while it is alive: once it ends, a sketch that keeps stepping may rightly
            // free the dead owner's role (the hand-over rule), so the owner is not checked after join()
            AtomicReference<Thread> ownerAtEnd = new AtomicReference<>();
            Thread audio = new Thread(() -> {
                try {
                    float[] frame = new float[1];
                    u.tick(frame); // the first sample takes the role (and steps its block)
                    counts[0] = pm.getStepCount();
                    for (int i = 1; i < samples; i++) {
                        u.tick(frame);
                        peak[0] = Math.max(peak[0], Math.abs(frame[0]));
                    }
                    counts[1] = pm.getStepCount();
                    ownerAtEnd.set(pm.getRealtimeOwner());
                } catch (Throwable t) {
                    audioError.set(t);
                }
            }, "audio");
            audio.start();
            audio.join();
            stop.set(true);
            sketch.join();
            assertNull(audioError.get(), () -> "the audio thread failed: " + audioError.get());
            assertNull(sketchError.get(), () -> "the sketch thread failed: " + sketchError.get());
            assertSame(audio, ownerAtEnd.get(), "the audio thread owns the model after its samples");
            assertEquals(samples - u.blockSize(), counts[1] - counts[0],
                    "one step per sample after the first block, and none from the sketch's draw_physics()");
            assertTrue(peak[0] > 0, "the model sounds");
        });
    }
}
