package tactus.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.management.ManagementFactory;

import org.junit.jupiter.api.Test;

import processing.awt.PGraphicsJava2D;
import processing.core.PApplet;
import processing.core.PGraphics;
import tactus.ModelRenderer;
import tactus.ModelSnapshot;
import tactus.PhysicalModel;
import tactus.Vect3D;
import tactus.linkModuleType;
import tactus.matModuleType;

/**
 * Drawing allocates nothing per element per frame. The renderer draws a stepped model, with every link type
 * visible and strain shading on (so colours change from link to link), while the JVM's per-thread allocation
 * counter is read around 200 frames.
 *
 * <p>A JAVA2D target allocates by itself in Processing and Java2D ({@code fill()} and {@code stroke()} make a
 * {@code java.awt.Color}, {@code strokeWeight()} a {@code BasicStroke}, and Java2D's rasteriser its path
 * iterators), so the renderer's own allocation is measured with a JAVA2D target whose primitives are counted but
 * not rasterised ({@link CountingJava2D}): there it must be exactly 0 bytes. With a real JAVA2D target the
 * renderer must allocate no more per element than the Processing calls it makes, measured by drawing the same
 * primitives directly.
 */
class RenderAllocationTest {

    /** A JAVA2D target that counts the drawing calls and does nothing else. */
    static final class CountingJava2D extends PGraphicsJava2D {
        long lines;
        long discs;
        long fills;
        long strokes;

        CountingJava2D() {
            setPrimary(false);
            setSize(200, 200);
        }

        @Override public void line(float x1, float y1, float x2, float y2) { lines++; }
        @Override public void ellipse(float a, float b, float c, float d) { discs++; }
        @Override public void fill(int argb) { fills++; }
        @Override public void stroke(int argb) { strokes++; }
        @Override public void strokeWeight(float w) { }
        @Override public void noStroke() { }
        @Override public void noFill() { }
        @Override public void ellipseMode(int mode) { }
        @Override public void colorMode(int mode, float max) { }
        @Override public void pushStyle() { }
        @Override public void popStyle() { }
    }

    /** A chain of masses with springs, ropes, contacts, bubbles, an attractor and a floor, stepped a little. */
    static PhysicalModel model(int n) {
        PhysicalModel m = new PhysicalModel(1000, 50);
        m.addGround3D("g", new Vect3D(0, 0, 0));
        for (int i = 1; i <= n; i++) {
            m.addMass3D("m" + i, 1 + i % 3, new Vect3D(5 * i, 3 * (i % 4), 0), new Vect3D(0, 0.5 * (i % 5 - 2), 0));
            String prev = i == 1 ? "g" : "m" + (i - 1);
            switch (i % 4) {
                case 0:
                    m.addSpringDamper3D("l" + i, 4, 0.05, 0.001, prev, "m" + i);
                    break;
                case 1:
                    m.addRope3D("l" + i, 6, 0.05, 0.001, prev, "m" + i);
                    break;
                case 2:
                    m.addSpring3D("l" + i, 5, 0.05, prev, "m" + i);
                    break;
                default:
                    m.addContact3D("l" + i, 8, 0.05, 0.001, prev, "m" + i);
                    break;
            }
        }
        m.addBubble3D("bubble", 1000, 0.01, 0.001, "g", "m1");
        m.addAttractor3D("pull", 1, 0.001, "m1", "m2");
        m.addPlaneContact("floor", 0, 0.05, 0.001, 1, 100, "m3");
        m.init();
        m.computeNSteps(100);
        return m;
    }

    static ModelRenderer everythingVisible() {
        ModelRenderer r = new ModelRenderer(new PApplet());
        for (linkModuleType t : linkModuleType.values()) {
            if (t != linkModuleType.UNDEFINED) {
                assertTrue(r.setColor(t, 10, 20, 30, 255));
                assertTrue(r.setStrainColor(t, 250, 0, 0, 255));
                assertTrue(r.setStrainGradient(t, true, 0.5f));
            }
        }
        for (matModuleType t : matModuleType.values()) {
            if (t != matModuleType.UNDEFINED) {
                assertTrue(r.setScaling(t, 0.5f));
            }
        }
        return r;
    }

    private static long allocatedBy(Runnable frames) {
        com.sun.management.ThreadMXBean mx = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        assertTrue(mx.isThreadAllocatedMemorySupported() && mx.isThreadAllocatedMemoryEnabled());
        long tid = Thread.currentThread().getId();
        long b0 = mx.getThreadAllocatedBytes(tid);
        long b1 = mx.getThreadAllocatedBytes(tid);
        long a0 = mx.getThreadAllocatedBytes(tid);
        frames.run();
        long a1 = mx.getThreadAllocatedBytes(tid);
        return (a1 - a0) - (b1 - b0);
    }

    @Test
    void theRendererItselfAllocatesNothingPerFrame() {
        PhysicalModel m = model(400);
        ModelRenderer r = everythingVisible();
        CountingJava2D g = new CountingJava2D();
        for (int f = 0; f < 2000; f++) {   // warm-up: JIT, and the topology cache filled once
            r.renderModel(m, g);
        }
        long discs = g.discs;
        long lines = g.lines;
        r.renderModel(m, g);
        assertEquals(401, g.discs - discs, "every mass drawn");
        assertEquals(403, g.lines - lines, "every link drawn");
        assertTrue(g.strokes > 2000, "strain shading changes the stroke colour from link to link: " + g.strokes);
        long[] measured = {-1, -1, -1};
        long last = -1;
        for (int attempt = 0; attempt < 3 && last != 0; attempt++) {
            last = allocatedBy(() -> {
                for (int f = 0; f < 200; f++) {
                    r.renderModel(m, g);
                }
            });
            measured[attempt] = last;
        }
        assertEquals(0, last, "bytes allocated by 200 frames of 804 elements: " + measured[0] + ", " + measured[1]
                + ", " + measured[2]);
    }

    @Test
    void colouringBySpeedForceOrStrainAndForceArrowsAllocateNothingEither() {
        PhysicalModel m = model(400);
        m.addHapticInput3D("hand", new Vect3D(-10, 0, 0), 1);
        m.addSpringDamper3D("grip", 1, 0.01, 0.001, "hand", "m1");
        m.getSnapshot().requestMotion(true);
        m.computeNSteps(20);
        ModelRenderer r = everythingVisible();
        r.setForceArrowScale(50);
        CountingJava2D g = new CountingJava2D();
        for (ColorBy by : new ColorBy[] {ColorBy.SPEED, ColorBy.FORCE, ColorBy.STRAIN}) {
            r.colorBy(by, 0, 1);
            for (int f = 0; f < 2000; f++) {
                r.renderModel(m, g);
            }
            long lines = g.lines;
            r.renderModel(m, g);
            assertEquals(404 + 3, g.lines - lines, by + ": every link and the avatar's arrow (3 strokes)");
            long last = -1;
            for (int attempt = 0; attempt < 3 && last != 0; attempt++) {
                last = allocatedBy(() -> {
                    for (int f = 0; f < 200; f++) {
                        r.renderModel(m, g);
                    }
                });
            }
            assertEquals(0, last, by + ": bytes allocated by 200 frames");
        }
    }

    /** Bytes per frame of the renderer and of the bare Processing calls, for a model of n masses, in JAVA2D. */
    private static long[] java2dBytesPerFrame(int n) {
        PhysicalModel m = model(n);
        ModelRenderer r = everythingVisible();
        Canvas c = new Canvas(400, 400);
        PGraphics g = c.begin();
        ModelSnapshot s = m.getSnapshot();
        // The same primitives drawn directly: one colour change and one shape per element.
        Runnable bare = () -> {
            g.pushStyle();
            for (int l = 0; l < s.getNumberOfLinks(); l++) {
                int a = s.getLinkMat1Idx(l);
                int b = s.getLinkMat2Idx(l);
                g.stroke(0xFF000000 | l);
                g.line((float) s.x(a), (float) s.y(a), (float) s.x(b), (float) s.y(b));
            }
            g.noStroke();
            for (int i = 0; i < s.getNumberOfMats(); i++) {
                g.fill(0xFF000000 | i);
                g.ellipse((float) s.x(i), (float) s.y(i), 20, 20);
            }
            g.popStyle();
        };
        for (int f = 0; f < 300; f++) {
            r.renderModel(m, g);
            bare.run();
        }
        long ours = allocatedBy(() -> {
            for (int f = 0; f < 100; f++) {
                r.renderModel(m, g);
            }
        });
        long direct = allocatedBy(() -> {
            for (int f = 0; f < 100; f++) {
                bare.run();
            }
        });
        c.end();
        return new long[] {ours / 100, direct / 100};
    }

    @Test
    void inARealJava2dTargetTheRendererAllocatesNoMorePerElementThanTheCallsItMakes() {
        long[] small = java2dBytesPerFrame(100);
        long[] large = java2dBytesPerFrame(400);
        double oursPerElement = (large[0] - small[0]) / 603.0;     // 300 more masses and 300 more links
        double directPerElement = (large[1] - small[1]) / 603.0;
        assertTrue(directPerElement > 0, "Java2D allocates per shape: " + directPerElement);
        assertTrue(oursPerElement <= directPerElement, "bytes per element per frame: renderer "
                + oursPerElement + ", bare Processing calls " + directPerElement);
    }
}
