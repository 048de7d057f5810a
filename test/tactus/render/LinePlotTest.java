package tactus.render;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

import javax.imageio.ImageIO;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import processing.core.PImage;

class LinePlotTest {

    private static final int W = 640;
    private static final int H = 400;
    private static final int RED = 0xFFD01010;

    @TempDir
    Path tmp;

    /** A plot with one horizontal red line at y = 5 over x = 0..10. */
    private static LinePlot flatLine() {
        double[] xs = {0, 2, 4, 6, 8, 10};
        double[] ys = {5, 5, 5, 5, 5, 5};
        return new LinePlot("Flat", "x", "y").series("level", xs, ys, RED);
    }

    private static double[] range(int n, double from, double step) {
        double[] a = new double[n];
        for (int i = 0; i < n; i++) {
            a[i] = from + i * step;
        }
        return a;
    }

    /** True if some pixel within +-radius rows of (x, y) has exactly the colour. */
    private static boolean colourNear(PImage img, int x, int y, int radius, int argb) {
        for (int dy = -radius; dy <= radius; dy++) {
            if (img.get(x, y + dy) == argb) {
                return true;
            }
        }
        return false;
    }

    // ----------------------------------------------------------------------------------------------------------
    // Files and pixels
    // ----------------------------------------------------------------------------------------------------------

    @Test
    void savesPngOfRequestedSize() throws IOException {
        File file = tmp.resolve("sub/dir/plot.png").toFile();
        File written = flatLine().save(file, W, H);

        assertEquals(file.getAbsoluteFile(), written);
        assertTrue(written.isFile(), "the PNG was not written");
        byte[] head = Files.readAllBytes(written.toPath());
        assertEquals((byte) 0x89, head[0]);
        assertEquals('P', head[1]);
        assertEquals('N', head[2]);
        assertEquals('G', head[3]);
        BufferedImage img = ImageIO.read(written);
        assertEquals(W, img.getWidth());
        assertEquals(H, img.getHeight());
    }

    @Test
    void savedFileHasSamePixelsAsRenderedImage() throws IOException {
        LinePlot plot = flatLine();
        PImage rendered = plot.render(W, H);
        BufferedImage saved = ImageIO.read(plot.save(tmp.resolve("same.png").toFile(), W, H));
        LinePlot.Layout l = plot.layout(W, H);
        int x = Math.round((l.left() + l.right()) / 2);
        int y = Math.round(l.screenY(5));
        for (int dy = -3; dy <= 3; dy++) {
            assertEquals(rendered.get(x, y + dy), saved.getRGB(x, y + dy) | 0xFF000000, "pixel at dy=" + dy);
        }
    }

    @Test
    void seriesLineHasSeriesColourAndBackgroundElsewhere() {
        LinePlot plot = flatLine();
        LinePlot.Layout l = plot.layout(W, H);
        PImage img = plot.render(W, H);

        assertEquals(W, img.width);
        assertEquals(H, img.height);
        int y = Math.round(l.screenY(5));
        for (float fx : new float[] {0.1f, 0.37f, 0.5f, 0.81f}) {
            int x = Math.round(l.left() + fx * (l.right() - l.left()));
            assertTrue(colourNear(img, x, y, 2, RED),
                    String.format("no pixel of the series colour near (%d, %d): %08X", x, y, img.get(x, y)));
        }

        // Well below the line, half-way between two grid lines: plain background.
        double[] xt = l.xTicks();
        double[] yt = l.yTicks();
        int bx = Math.round((l.screenX(xt[0]) + l.screenX(xt[1])) / 2);
        int by = Math.round((l.screenY(yt[0]) + l.screenY(yt[1])) / 2);
        assertTrue(Math.abs(by - y) > 10, "test setup: the probe is too close to the line");
        assertEquals(LinePlot.BACKGROUND, img.get(bx, by), "chart background");
        assertEquals(LinePlot.BACKGROUND, img.get(1, 1), "image corner");
        assertEquals(LinePlot.BACKGROUND, img.get(W - 2, H - 2), "image corner");
    }

    @Test
    void lineIsCutAtFixedRange() {
        // The line runs from y = -100 to y = 100; with y fixed to [-1, 1] it must stay inside the chart area.
        LinePlot plot = new LinePlot("", "", "")
                .series("steep", new double[] {0, 1}, new double[] {-100, 100}, RED)
                .yRange(-1, 1);
        LinePlot.Layout l = plot.layout(W, H);
        PImage img = plot.render(W, H);
        int x = Math.round(l.screenX(0.5));
        assertTrue(colourNear(img, x, Math.round(l.screenY(0)), 2, RED), "the line crosses the middle");
        for (int yy = 0; yy < Math.floor(l.top()) - 1; yy++) {
            assertNotEquals(RED, img.get(x, yy), "the line leaks above the chart at y=" + yy);
        }
    }

    @Test
    void titleAndLabelsAreDrawn() {
        LinePlot plot = flatLine();
        LinePlot.Layout l = plot.layout(W, H);
        PImage img = plot.render(W, H);
        int dark = 0;
        for (int y = 0; y < (int) l.top() - 1; y++) {
            for (int x = 0; x < W; x++) {
                int c = img.get(x, y);
                if (((c >> 16) & 0xFF) < 100 && ((c >> 8) & 0xFF) < 100 && (c & 0xFF) < 100) {
                    dark++;
                }
            }
        }
        assertTrue(dark > 20, "the title should leave dark pixels above the chart, found " + dark);
    }

    @Test
    void logLogPlotWithMarkersRenders() {
        double[] ns = {10, 100, 1_000, 10_000, 100_000};
        double[] euler = {1e-2, 1e-3, 1e-4, 1e-5, 1e-6};
        double[] verlet = {1e-4, 1e-6, 1e-8, 1e-10, 1e-12};
        LinePlot plot = new LinePlot("Error", "time step (ns)", "error")
                .logX(true).logY(true).markers(true)
                .series("Euler", ns, euler)
                .series("Verlet", ns, verlet);
        LinePlot.Layout l = plot.layout(W, H);
        PImage img = plot.render(W, H);

        int x = Math.round(l.screenX(1_000));
        assertTrue(colourNear(img, x, Math.round(l.screenY(1e-4)), 2, plot.seriesColor(0)), "Euler marker");
        assertTrue(colourNear(img, x, Math.round(l.screenY(1e-8)), 2, plot.seriesColor(1)), "Verlet marker");
        assertNotEquals(plot.seriesColor(0), plot.seriesColor(1));
        // Decades are evenly spaced.
        assertEquals(l.screenX(100) - l.screenX(10), l.screenX(10_000) - l.screenX(1_000), 1e-3);
        assertEquals(l.screenY(1e-6) - l.screenY(1e-5), l.screenY(1e-10) - l.screenY(1e-9), 1e-3);
    }

    // ----------------------------------------------------------------------------------------------------------
    // Ranges and layout
    // ----------------------------------------------------------------------------------------------------------

    @Test
    void autoRangeIsPaddedAndContainsData() {
        LinePlot.Layout l = new LinePlot("t", "x", "y")
                .series("a", new double[] {0, 10}, new double[] {-2, 3}).layout(W, H);
        assertEquals(-0.5, l.xMin(), 1e-9);
        assertEquals(10.5, l.xMax(), 1e-9);
        assertEquals(-2.25, l.yMin(), 1e-9);
        assertEquals(3.25, l.yMax(), 1e-9);
        assertTrue(l.left() < l.screenX(0) && l.screenX(10) < l.right());
        assertTrue(l.top() < l.screenY(3) && l.screenY(-2) < l.bottom());
        assertTrue(l.right() < W && l.bottom() < H && l.left() > 0 && l.top() > 0);
    }

    @Test
    void constantDataStillGetsARange() {
        LinePlot.Layout l = new LinePlot("", "", "")
                .series("c", new double[] {3, 3}, new double[] {0, 0}).layout(W, H);
        assertTrue(l.xMin() < 3 && l.xMax() > 3);
        assertTrue(l.yMin() < 0 && l.yMax() > 0);
        assertTrue(l.xTicks().length >= 2 && l.yTicks().length >= 2);
    }

    @Test
    void nonFinitePointsAreSkipped() {
        double nan = Double.NaN;
        double inf = Double.POSITIVE_INFINITY;
        LinePlot plot = new LinePlot("gaps", "x", "y")
                .series("g", new double[] {0, 1, 2, inf, 4, 5}, new double[] {1, nan, 2, 3, 4, inf});
        LinePlot.Layout l = plot.layout(W, H);
        assertEquals(0, l.xMin(), 0.5);
        assertEquals(4, l.xMax(), 0.5);
        assertEquals(4, l.yMax(), 0.5);
        assertEquals(W, plot.render(W, H).width);

        // NaN and infinite values are skipped on a log axis too, not rejected.
        new LinePlot("", "", "").logY(true).series("n", new double[] {1, 2, 3}, new double[] {1, nan, -inf});
    }

    @Test
    void ticksStayInsideTheAxisRange() {
        LinePlot.Layout l = new LinePlot("", "", "")
                .series("s", range(50, -3.7, 0.31), range(50, 1000, 17.3)).layout(800, 500);
        for (double t : l.xTicks()) {
            assertTrue(t >= l.xMin() && t <= l.xMax(), "x tick " + t);
        }
        for (double t : l.yTicks()) {
            assertTrue(t >= l.yMin() && t <= l.yMax(), "y tick " + t);
        }
        assertTrue(l.xTicks().length >= 3);
        assertTrue(l.yTicks().length >= 3);
    }

    @Test
    void defaultColoursDifferAndRepeat() {
        LinePlot plot = new LinePlot("", "", "");
        for (int i = 0; i < 9; i++) {
            plot.series("s" + i, new double[] {0, 1}, new double[] {i, i});
        }
        assertEquals(9, plot.seriesCount());
        for (int i = 0; i < 8; i++) {
            for (int j = i + 1; j < 8; j++) {
                assertNotEquals(plot.seriesColor(i), plot.seriesColor(j), "colours " + i + " and " + j);
            }
            assertEquals(0xFF, plot.seriesColor(i) >>> 24, "opaque");
        }
        assertEquals(plot.seriesColor(0), plot.seriesColor(8));
        assertEquals(LinePlot.defaultColor(3), plot.seriesColor(3));
        // An RGB colour without alpha is drawn opaque.
        assertEquals(0xFF123456, new LinePlot("", "", "").series("rgb", new double[] {0}, new double[] {0}, 0x123456)
                .seriesColor(0));
    }

    // ----------------------------------------------------------------------------------------------------------
    // Ticks
    // ----------------------------------------------------------------------------------------------------------

    @Test
    void niceTicksUseOneTwoFiveSteps() {
        assertArrayEquals(new double[] {0, 2, 4, 6, 8, 10}, LinePlot.niceTicks(0, 10, 6));
        assertArrayEquals(new double[] {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10}, LinePlot.niceTicks(0, 10, 11));
        assertArrayEquals(new double[] {0, 5, 10}, LinePlot.niceTicks(0, 10, 3));
        assertArrayEquals(new double[] {-0.3, -0.2, -0.1, 0, 0.1, 0.2, 0.3}, LinePlot.niceTicks(-0.3, 0.3, 7));
        assertArrayEquals(new double[] {0.96, 0.98, 1.0, 1.02, 1.04}, LinePlot.niceTicks(0.95, 1.05, 5));
        assertArrayEquals(new double[] {2e6, 4e6, 6e6}, LinePlot.niceTicks(1.1e6, 7.3e6, 4));
        assertArrayEquals(new double[] {-40, -20, 0}, LinePlot.niceTicks(-47, 3, 4));
    }

    @Test
    void niceTicksRejectBadArguments() {
        assertThrows(IllegalArgumentException.class, () -> LinePlot.niceTicks(1, 1, 5));
        assertThrows(IllegalArgumentException.class, () -> LinePlot.niceTicks(2, 1, 5));
        assertThrows(IllegalArgumentException.class, () -> LinePlot.niceTicks(0, Double.NaN, 5));
        assertThrows(IllegalArgumentException.class, () -> LinePlot.niceTicks(0, 1, 1));
    }

    @Test
    void logTicksUseDecades() {
        assertArrayEquals(new double[] {1e-9, 1e-8, 1e-7, 1e-6, 1e-5, 1e-4, 1e-3}, LinePlot.logTicks(1e-9, 1e-3, 10));
        assertArrayEquals(new double[] {1, 1e3, 1e6, 1e9, 1e12}, LinePlot.logTicks(1, 1e12, 5));
        assertArrayEquals(new double[] {2, 5, 10, 20}, LinePlot.logTicks(2, 30, 5));
        assertThrows(IllegalArgumentException.class, () -> LinePlot.logTicks(0, 10, 5));
        assertThrows(IllegalArgumentException.class, () -> LinePlot.logTicks(-1, 10, 5));
    }

    @Test
    void tickLabelsAreTidy() {
        assertArrayEquals(new String[] {"0.0", "0.5", "1.0", "1.5"},
                LinePlot.tickLabels(new double[] {0, 0.5, 1, 1.5}, false));
        assertArrayEquals(new String[] {"-20", "0", "20"}, LinePlot.tickLabels(new double[] {-20, 0, 20}, false));
        assertArrayEquals(new String[] {"0", "2e6", "4e6"}, LinePlot.tickLabels(new double[] {0, 2e6, 4e6}, false));
        assertArrayEquals(new String[] {"1e-9", "1e-6", "1e-3"},
                LinePlot.tickLabels(new double[] {1e-9, 1e-6, 1e-3}, true));
        assertArrayEquals(new String[] {"2", "5", "10", "20"}, LinePlot.tickLabels(new double[] {2, 5, 10, 20}, true));
    }

    // ----------------------------------------------------------------------------------------------------------
    // Bad input
    // ----------------------------------------------------------------------------------------------------------

    @Test
    void logAxesRejectNonPositiveData() {
        double[] xs = {0, 1, 2};
        double[] ys = {1, 2, 3};
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new LinePlot("", "", "").logX(true).series("zero", xs, ys));
        assertTrue(e.getMessage().contains("zero") && e.getMessage().contains("x[0]"), e.getMessage());

        LinePlot plot = new LinePlot("", "", "").series("neg", ys, new double[] {1, -2, 3});
        e = assertThrows(IllegalArgumentException.class, () -> plot.logY(true));
        assertTrue(e.getMessage().contains("y[1]"), e.getMessage());
        plot.logX(true); // x values are positive: fine

        assertThrows(IllegalArgumentException.class, () -> new LinePlot("", "", "").logY(true).yRange(0, 1));
        assertThrows(IllegalArgumentException.class, () -> new LinePlot("", "", "").xRange(-1, 1).logX(true));
    }

    @Test
    void badSeriesAreRejected() {
        LinePlot plot = new LinePlot("", "", "");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> plot.series("short", new double[] {1, 2, 3}, new double[] {1, 2}));
        assertTrue(e.getMessage().contains("short") && e.getMessage().contains("3") && e.getMessage().contains("2"),
                e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> plot.series(null, new double[0], new double[0]));
        assertThrows(IllegalArgumentException.class, () -> plot.series("n", null, new double[0]));
        assertThrows(IllegalArgumentException.class, () -> plot.series("n", new double[0], null));
        assertEquals(0, plot.seriesCount());
    }

    @Test
    void emptyPlotsAreRejected() {
        assertThrows(IllegalArgumentException.class, () -> new LinePlot("", "", "").render(W, H));
        assertThrows(IllegalArgumentException.class, () -> new LinePlot("", "", "")
                .series("nan", new double[] {Double.NaN, 1}, new double[] {1, Double.NaN}).render(W, H));
        assertThrows(IllegalArgumentException.class, () -> new LinePlot("", "", "")
                .series("empty", new double[0], new double[0]).layout(W, H));
    }

    @Test
    void badSizesRangesAndFilesAreRejected() {
        assertThrows(IllegalArgumentException.class, () -> flatLine().render(0, H));
        assertThrows(IllegalArgumentException.class, () -> flatLine().render(W, -1));
        assertThrows(IllegalArgumentException.class, () -> flatLine().render(30, 20));
        assertThrows(IllegalArgumentException.class, () -> flatLine().xRange(1, 1));
        assertThrows(IllegalArgumentException.class, () -> flatLine().yRange(0, Double.POSITIVE_INFINITY));
        assertThrows(IllegalArgumentException.class, () -> flatLine().save(null, W, H));
        assertThrows(IllegalArgumentException.class, () -> flatLine().save(tmp.resolve("plot.svg").toFile(), W, H));
        assertThrows(IllegalArgumentException.class, () -> flatLine().save(tmp.resolve("plot").toFile(), W, H));
    }

    @Test
    void arraysAreCopied() {
        double[] xs = {0, 1};
        double[] ys = {0, 1};
        LinePlot plot = new LinePlot("", "", "").series("copy", xs, ys);
        xs[1] = 1000;
        assertTrue(plot.layout(W, H).xMax() < 2);
    }
}
