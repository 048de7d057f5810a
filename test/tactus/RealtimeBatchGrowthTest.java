package tactus;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicReference;
import org.junit.jupiter.api.Test;

/**
 * A change prepared while another thread steps the model in realtime is recorded in a write batch that grows as it
 * goes (4 writes at first). The batch used to store its fifth write into the array it had just replaced (Java takes
 * the array before it evaluates the index, and the index grew the array), so any such change of five writes or more,
 * a subset of five masses for instance, threw ArrayIndexOutOfBoundsException: the HeavyMassChain example's M key did
 * once its haptic loop stepped the model in realtime. Batches of 1 to 40 writes must apply whole.
 */
class RealtimeBatchGrowthTest {

    @Test
    void changesOfAnySizeMadeWhileAnotherThreadStepsApplyWhole() throws Exception {
        for (int size : new int[] {1, 4, 5, 8, 9, 17, 40}) {
            PhysicalModel pm = new PhysicalModel(1000);
            pm.createMatSubset("all");
            for (int i = 0; i < size; i++) {
                pm.addMass3D("m" + i, 1, new Vect3D(i, 0, 0), new Vect3D());
                pm.addMatToSubset("m" + i, "all");
            }
            pm.init();
            pm.beginRealtimeStepping();
            AtomicBoolean run = new AtomicBoolean(true);
            AtomicReference<Throwable> failed = new AtomicReference<>();
            Thread owner = new Thread(() -> {
                try {
                    while (run.get()) {
                        pm.computeStep();
                    }
                } catch (Throwable t) {
                    failed.set(t);
                }
            }, "owner");
            owner.start();
            long deadline = System.nanoTime() + 10_000_000_000L;
            while (pm.getRealtimeOwner() != owner && System.nanoTime() < deadline) {
                Thread.onSpinWait();
            }
            assertEquals(owner, pm.getRealtimeOwner(), "the stepping thread owns the model");
            pm.changeMassParamOfSubset(2.5, "all");          // queued: applied by the owner between two steps
            for (int i = 0; i < size; i++) {
                assertEquals(2.5, pm.getMatMass("m" + i), 1e-12, size + " masses: m" + i);
            }
            run.set(false);
            owner.join(10_000);
            assertTrue(!owner.isAlive(), "the owner ends");
            assertEquals(null, failed.get(), "the owner's stepping");
            pm.endRealtimeStepping();
        }
    }
}
