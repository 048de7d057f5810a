package tactus;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * Removing k of N modules costs O(k + N): one plan compile, one compaction of each name registry and one index
 * of the links of each mass for the whole batch of removals (counted, not timed), with the same results, bit for
 * bit, as compiling after every removal.
 */
@Timeout(value = 120, unit = TimeUnit.SECONDS)
class TopologyEditCostTest {
    private static PhysicalModel chain(int n) {
        PhysicalModel pm = new PhysicalModel(1000);
        for (int i = 0; i < n; i++) {
            pm.addMass3D("m" + i, 1 + (i % 3) * 0.5, new Vect3D(i, 0, 0), new Vect3D(0, i % 7 == 0 ? 0.01 : 0, 0));
        }
        for (int i = 1; i < n; i++) {
            pm.addSpringDamper3D("l" + i, 1, 0.05, 0.001, "m" + (i - 1), "m" + i);
        }
        pm.createMatSubset("every7");
        for (int i = 0; i < n; i += 7) {
            pm.addMatToSubset("m" + i, "every7");
        }
        pm.init();
        return pm;
    }

    private static String removed(int k, int n, int i) {
        return "m" + (1 + i * (n / (k + 1)));
    }

    @Test
    void removingManyMassesGivesTheSameMotionAsCompilingAfterEachRemoval() {
        int n = 3000;
        int k = 40;
        PhysicalModel batched = chain(n);
        PhysicalModel eager = chain(n);
        batched.computeNSteps(50);
        eager.computeNSteps(50);
        for (int i = 0; i < k; i++) {
            batched.removeMatAndConnectedLinks(removed(k, n, i));
            eager.removeMatAndConnectedLinks(removed(k, n, i));
            eager.core.engine.compile();   // what every removal did before
        }
        batched.computeNSteps(300);
        eager.computeNSteps(300);
        assertEquals(eager.getNumberOfMats(), batched.getNumberOfMats());
        assertEquals(n - k, batched.getNumberOfMats());
        assertEquals(n - 1 - 2 * k, batched.getNumberOfLinks());
        int moving = 0;
        for (int i = 0; i < n; i++) {
            String name = "m" + i;
            if (batched.core.dir.mats.id(name) < 0) {
                continue;
            }
            Vect3D a = batched.getMatPosition(name);
            Vect3D b = eager.getMatPosition(name);
            assertEquals(b.x, a.x, 0, name);
            assertEquals(b.y, a.y, 0, name);
            assertEquals(b.z, a.z, 0, name);
            moving += a.y != 0 ? 1 : 0;
        }
        assertTrue(moving > n / 10, "the chain moves (" + moving + " masses off the axis), so the comparison means something");
    }

    @Test
    void aBatchOfRemovalsCompilesOnceCompactsOnceAndIndexesTheLinksOnce() {
        int n = 5000;
        int k = 100;
        PhysicalModel pm = chain(n);
        pm.computeNSteps(1);
        long compiles = pm.core.engine.compiles();
        long mats = pm.core.dir.mats.compactions();
        long links = pm.core.dir.links.compactions();
        long index = pm.core.engine.incidenceBuilds();
        for (int i = 0; i < k; i++) {
            pm.removeMatAndConnectedLinks(removed(k, n, i));
        }
        pm.computeNSteps(10);
        assertEquals(1, pm.core.engine.compiles() - compiles, "plan compiles for " + k + " removals and 10 steps");
        assertTrue(pm.core.dir.mats.compactions() - mats <= 1, "mass registry compactions");
        assertTrue(pm.core.dir.links.compactions() - links <= 1, "link registry compactions");
        assertTrue(pm.core.engine.incidenceBuilds() - index <= 1, "mass-to-links index builds");
        assertEquals(n - k, pm.getNumberOfMats());
        assertEquals("m" + (n - 1), pm.core.dir.mats.name(pm.core.dir.mats.idAt(n - k - 1)), "insertion order kept");
        // a module added after removals, then removed again before any read, leaves the registry consistent
        pm.addMass3D("late", 1, new Vect3D(), new Vect3D());
        pm.removeMatAndConnectedLinks("late");
        assertEquals(n - k, pm.getNumberOfMats());
        assertEquals(-1, pm.core.dir.mats.indexOf(pm.core.dir.mats.id("late")));
    }
}
