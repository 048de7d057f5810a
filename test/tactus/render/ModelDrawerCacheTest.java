package tactus.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;

import processing.core.PGraphics;
import tactus.PhysicalModel;
import tactus.Vect3D;
import tactus.linkModuleType;
import tactus.matModuleType;

/**
 * What the renderer reads besides the snapshot (inertias, length parameters, planes) is read under the model's
 * lock once per topology, and the steady-state frame takes no lock at all.
 */
class ModelDrawerCacheTest {

    /** Records the last radius drawn for each mass index and the last colour for each link index. */
    static final class Recorder implements MassPainter, LinkPainter {
        final float[] radius = new float[64];
        final int[] linkColor = new int[64];
        int massCount;
        int linkCount;

        @Override
        public void begin(PGraphics g, int count) {
        }

        @Override
        public void end(PGraphics g) {
        }

        @Override
        public void mass(PGraphics g, int index, matModuleType type, float x, float y, float z, float r, int argb) {
            radius[index] = r;
            massCount++;
        }

        @Override
        public void link(PGraphics g, int index, linkModuleType type, float x1, float y1, float z1, float x2,
                         float y2, float z2, float weight, int argb) {
            linkColor[index] = argb;
            linkCount++;
        }
    }

    private static PhysicalModel pair() {
        PhysicalModel m = new PhysicalModel(1000, 50);
        m.addMass3D("a", 2, new Vect3D(0, 0, 0), new Vect3D(0, 0, 0));
        m.addMass3D("b", 3, new Vect3D(10, 0, 0), new Vect3D(0, 0, 0));
        m.addSpring3D("s", 10, 0.01, "a", "b");
        m.init();
        return m;
    }

    private static ModelDrawer drawer(Recorder rec) {
        ModelDrawer d = new ModelDrawer();
        d.style().mass(matModuleType.Mass3D).setSize(1);
        d.style().mass(matModuleType.Mass3D).setScaling(2);
        d.setMassPainter(rec);
        d.setLinkPainter(rec);
        return d;
    }

    @Test
    void inertiasAreReadOncePerTopology() {
        PhysicalModel m = pair();
        Recorder rec = new Recorder();
        ModelDrawer d = drawer(rec);
        Canvas c = new Canvas(50, 50);
        PGraphics g = c.begin();
        for (int f = 0; f < 20; f++) {
            m.draw_physics();
            d.draw(m, g);
        }
        assertEquals(1, d.cacheRefreshes(), "20 frames of one topology");
        assertEquals(1 + 2 * 2, rec.radius[0], 1e-6);
        assertEquals(1 + 2 * 3, rec.radius[1], 1e-6);

        // a new mass and link: a new topology, read once more
        m.addMass3D("c", 5, new Vect3D(20, 0, 0), new Vect3D(0, 0, 0));
        m.addSpring3D("t", 10, 0.01, "b", "c");
        d.draw(m, g);
        d.draw(m, g);
        assertEquals(2, d.cacheRefreshes());
        assertEquals(1 + 2 * 5, rec.radius[2], 1e-6);

        // a removal shifts indices: read again, the radii follow the masses
        m.removeMatAndConnectedLinks("a");
        rec.massCount = 0;
        d.draw(m, g);
        assertEquals(3, d.cacheRefreshes());
        assertEquals(2, rec.massCount);
        assertEquals(1 + 2 * 3, rec.radius[0], 1e-6);
        assertEquals(1 + 2 * 5, rec.radius[1], 1e-6);

        // a parameter change keeps the topology: seen after refresh()
        m.setMatMass("b", 7);
        d.draw(m, g);
        assertEquals(1 + 2 * 3, rec.radius[0], 1e-6, "cached until refresh()");
        d.refresh();
        d.draw(m, g);
        assertEquals(1 + 2 * 7, rec.radius[0], 1e-6);
        assertEquals(4, d.cacheRefreshes());
        c.end();
    }

    @Test
    void aSteadyFrameDrawsWhileAnotherThreadHoldsTheModelLock() throws Exception {
        PhysicalModel m = pair();
        Recorder rec = new Recorder();
        ModelDrawer d = drawer(rec);
        Canvas c = new Canvas(50, 50);
        PGraphics g = c.begin();
        d.draw(m, g);                 // the first frame of a topology reads it under the lock
        CountDownLatch held = new CountDownLatch(1);
        CountDownLatch release = new CountDownLatch(1);
        Thread holder = new Thread(() -> {
            m.getLock().lock();
            try {
                held.countDown();
                release.await(10, TimeUnit.SECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            } finally {
                m.getLock().unlock();
            }
        });
        holder.start();
        try {
            assertTrue(held.await(5, TimeUnit.SECONDS));
            int before = rec.massCount;
            assertTimeoutPreemptively(Duration.ofSeconds(3), () -> {
                for (int f = 0; f < 10; f++) {
                    d.draw(m, g);
                }
            }, "drawing waited for the model's lock");
            assertEquals(before + 20, rec.massCount);
        } finally {
            release.countDown();
            holder.join();
        }
        c.end();
    }

    @Test
    void restLengthsAreCachedForTheStrain() {
        PhysicalModel m = new PhysicalModel(1000, 50);
        m.addGround3D("a", new Vect3D(0, 0, 0));
        m.addGround3D("b", new Vect3D(30, 0, 0));
        m.addSpring3D("s", 20, 0.01, "a", "b");   // strain (30 - 20) / 20 = 0.5
        m.init();
        Recorder rec = new Recorder();
        ModelDrawer d = drawer(rec);
        LinkStyle ls = d.style().link(linkModuleType.Spring3D);
        ls.setColor(0, 0, 0, 255);
        ls.setStrainColor(200, 100, 0, 255);
        ls.setStrainGradient(true, 1);
        Canvas c = new Canvas(50, 50);
        PGraphics g = c.begin();
        d.draw(m, g);
        assertEquals(0xFF643200, rec.linkColor[0], "half way to (200, 100, 0)");
        m.setLinkDRest("s", 10);                  // strain (30 - 10) / 10 = 2: beyond the maximum
        d.refresh();
        d.draw(m, g);
        assertEquals(0xFFC86400, rec.linkColor[0]);
        c.end();
    }
}
