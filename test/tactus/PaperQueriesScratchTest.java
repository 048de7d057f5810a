package tactus;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicReference;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * The paper engine's index queries (link ends, delayed positions) read through a scratch vector. The realtime owner
 * takes no lock, so its reads (a paper-style uGenerate reading {@code getLinkPos1At}) can run beside a lock holder's
 * (a draw() reading another link): with one shared scratch vector each could return the other's coordinates. Here
 * every queried mass is a fixed point, so every read must give exactly its own position. The race is a window of a
 * few nanoseconds: each round runs until the first wrong read or for 1.5 s.
 */
class PaperQueriesScratchTest {

    @ParameterizedTest(name = "owner batch {0}")
    @ValueSource(ints = {1, 16})
    @Timeout(value = 30, unit = TimeUnit.SECONDS)
    void theOwnerAndALockHolderReadOnlyTheirOwnLinks(int batch) throws Exception {
        PhysicalModel m = new PhysicalModel(44100, 60);
        m.setStabilityPolicy(StabilityPolicy.OFF);
        m.addGround3D("a1", new Vect3D(1, 2, 3));
        m.addGround3D("a2", new Vect3D(4, 5, 6));
        m.addGround3D("b1", new Vect3D(10, 20, 30));
        m.addGround3D("b2", new Vect3D(40, 50, 60));
        m.addSpringDamper3D("la", 1, 0.01, 0.001, "a1", "a2");
        m.addSpringDamper3D("lb", 1, 0.01, 0.001, "b1", "b2");
        m.init();
        m.beginRealtimeStepping();
        AtomicBoolean stop = new AtomicBoolean();
        AtomicLong wrong = new AtomicLong();
        AtomicReference<String> example = new AtomicReference<>();
        AtomicReference<Throwable> ownerError = new AtomicReference<>();
        Thread owner = new Thread(() -> {
            try {
                while (!stop.get()) {
                    m.computeNSteps(batch);
                    check(m.getLinkPos1At(0), 1, 2, 3, "owner getLinkPos1At(0)", wrong, example);
                    check(m.getMatDelayedPosAt(1), 4, 5, 6, "owner getMatDelayedPosAt(1)", wrong, example);
                }
            } catch (Throwable t) {
                ownerError.set(t);
            }
        }, "owner");
        owner.start();
        long end = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(1500);
        long reads = 0;
        try {
            while (System.nanoTime() < end && wrong.get() == 0) {
                check(m.getLinkPos2At(1), 40, 50, 60, "draw getLinkPos2At(1)", wrong, example);
                check(m.getMatDelayedPosAt(2), 10, 20, 30, "draw getMatDelayedPosAt(2)", wrong, example);
                reads++;
            }
        } finally {
            stop.set(true);
            owner.join(10_000);
        }
        assertNull(ownerError.get(), () -> "the owner failed: " + ownerError.get());
        assertTrue(reads > 0, "the lock holder read");
        assertEquals(0, wrong.get(), () -> "wrong reads, e.g. " + example.get());
    }

    private static void check(Vect3D v, double x, double y, double z, String what, AtomicLong wrong,
            AtomicReference<String> example) {
        if (v.x != x || v.y != y || v.z != z) {
            wrong.incrementAndGet();
            example.compareAndSet(null, what + " gave (" + v.x + ", " + v.y + ", " + v.z + ")");
        }
    }
}
