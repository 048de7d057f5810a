package tactus.audio;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ddf.minim.AudioOutput;
import ddf.minim.Minim;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.BooleanSupplier;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import tactus.PhysicalModel;
import tactus.StabilityPolicy;

/**
 * A PhyUGen keeps the model it plays in realtime stepping (issue 27). When the mode ended while Minim kept playing
 * ({@code endRealtimeStepping()} from another thread, or from a DivergenceListener on the audio thread, as the soak's
 * chaos does), the audio thread went on stepping in locked mode for good: it waited for the model's lock behind the
 * sketch's threads and ran the stability analysis itself, which the soak's stall probe found behind most of its late
 * blocks under real-time scheduling. Now the next step asks the audio helper thread to begin the mode again: the
 * output thread owns the model again and the rate is held again. On the code before, {@code isRealtimeStepping()}
 * stayed false.
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class PhyUGenKeepsRealtimeSteppingTest {

    private static void await(BooleanSupplier condition, java.util.function.Supplier<String> what)
            throws InterruptedException {
        long deadline = System.nanoTime() + 20_000_000_000L;
        while (!condition.getAsBoolean() && System.nanoTime() < deadline) {
            Thread.sleep(5);
        }
        assertTrue(condition.getAsBoolean(), what);
    }

    private static String state(PhysicalModel pm) {
        return "realtime " + pm.isRealtimeStepping() + ", owner " + pm.getRealtimeOwner() + ", diverged "
                + pm.isDiverged() + ", steps " + pm.getStepCount();
    }

    private static PhysicalModel string() {
        PhysicalModel pm = new PhysicalModel(44100);
        StringModel.build(pm, 7, 0.001);
        pm.init();
        return pm;
    }

    /** Plays {@code pm} through a PhyUGen on a silent output until it has stepped 0.1 s; the caller closes it. */
    private static AudioOutput play(PhysicalModel pm) throws InterruptedException {
        PhyUGen ugen = new PhyUGen(pm);
        ugen.listenToMass(StringModel.mass(3), SteppedModel.Y, 300, 0);
        AudioOutput out = LineOut.silent(Minim.MONO, 256, 44100f, null);
        ugen.patch(out);
        await(() -> pm.getStepCount() > 4410, () -> "the output plays: " + state(pm));
        return out;
    }

    private static void checkOwnedByTheOutputAgain(PhysicalModel pm) throws InterruptedException {
        await(() -> pm.isRealtimeStepping() && pm.getRealtimeOwner() instanceof SilentAudioOut.OutputThread,
                () -> "the output thread steps the model in realtime again: " + state(pm));
        long steps = pm.getStepCount();
        await(() -> pm.getStepCount() > steps + 4410, () -> "the model steps on: " + state(pm));
        assertThrows(IllegalStateException.class, () -> pm.setSimRate(48000), "the PhyUGen holds the rate again");
        assertEquals(44100, pm.getSimRate());
    }

    @Test
    void endingTheModeFromAnotherThreadWhileItPlaysIsUndone() throws Exception {
        PhysicalModel pm = string();
        AudioOutput out = play(pm);
        try {
            for (int round = 0; round < 3; round++) {
                pm.endRealtimeStepping();
                checkOwnedByTheOutputAgain(pm);
            }
        } finally {
            out.close();
        }
    }

    @Test
    void aDivergenceListenerThatEndsTheModeOnTheAudioThreadIsUndone() throws Exception {
        PhysicalModel pm = string();
        pm.setStabilityPolicy(StabilityPolicy.OFF);
        AtomicInteger told = new AtomicInteger();
        pm.setDivergenceListener(e -> {
            told.incrementAndGet();
            pm.endRealtimeStepping();   // from the stepping call on the audio thread
        });
        AudioOutput out = play(pm);
        try {
            pm.setLinkStiffness("s3", 50);   // far over the limit: diverges within a few hundred steps
            await(() -> told.get() > 0, () -> "the model diverged and the listener ended the mode: " + state(pm));
            pm.setLinkStiffness("s3", StringModel.K);
            for (int i = 1; i <= StringModel.N; i++) {   // back to rest: the blown-up state would diverge again
                pm.setMatPosition(StringModel.mass(i), new tactus.Vect3D(i * StringModel.D, 0, 0));
            }
            pm.clearDivergence();
            checkOwnedByTheOutputAgain(pm);
        } finally {
            out.close();
        }
    }
}
