package tactus.report;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Color;
import java.awt.GraphicsEnvironment;
import java.awt.image.BufferedImage;
import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

import javax.imageio.ImageIO;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Checks the charts of the demo and the reports: a PNG of the asked size is written headless, it shows each
 * series in its own colour on a white background, and what cannot be drawn is rejected with a message that
 * names the series and the point.
 */
class LineChartTest {

    @TempDir
    Path tmp;

    private static double[] ramp(int n, double from, double step) {
        double[] a = new double[n];
        for (int i = 0; i < n; i++) {
            a[i] = from + i * step;
        }
        return a;
    }

    /** Counts the pixels within a small distance of a colour. */
    private static int pixelsNear(BufferedImage img, Color c) {
        int count = 0;
        for (int y = 0; y < img.getHeight(); y++) {
            for (int x = 0; x < img.getWidth(); x++) {
                int rgb = img.getRGB(x, y);
                int dr = ((rgb >> 16) & 0xFF) - c.getRed();
                int dg = ((rgb >> 8) & 0xFF) - c.getGreen();
                int db = (rgb & 0xFF) - c.getBlue();
                if (dr * dr + dg * dg + db * db < 30 * 30) {
                    count++;
                }
            }
        }
        return count;
    }

    @Test
    void runsHeadless() {
        assertTrue(GraphicsEnvironment.isHeadless(), "gradle test runs with java.awt.headless=true");
    }

    @Test
    void savesAPngOfTheAskedSizeShowingEverySeries() throws IOException {
        double[] t = ramp(200, 0, 0.01);
        double[] sin = new double[t.length];
        double[] cos = new double[t.length];
        for (int i = 0; i < t.length; i++) {
            sin[i] = Math.sin(2 * Math.PI * t[i]);
            cos[i] = Math.cos(2 * Math.PI * t[i]);
        }
        File f = tmp.resolve("sub folder/chart.png").toFile();
        File written = new LineChart("Two waves", "time (s)", "value").series("sin", t, sin).series("cos", t, cos)
                .save(f, 640, 360);
        assertEquals(f, written);
        assertTrue(f.isFile(), "missing " + f);
        byte[] head = Files.readAllBytes(f.toPath());
        assertEquals((byte) 0x89, head[0]);
        assertEquals("PNG", new String(head, 1, 3, java.nio.charset.StandardCharsets.US_ASCII));

        BufferedImage img = ImageIO.read(f);
        assertEquals(640, img.getWidth());
        assertEquals(360, img.getHeight());
        int white = pixelsNear(img, Color.WHITE);
        assertTrue(white > img.getWidth() * img.getHeight() / 2, "mostly white background: " + white);
        // Each line is ~1.6 px wide over a plot several hundred px wide: both colours cover hundreds of pixels.
        assertTrue(pixelsNear(img, LineChart.color(0)) > 300, "first series drawn");
        assertTrue(pixelsNear(img, LineChart.color(1)) > 300, "second series drawn");
        // No third series: its colour is (almost) absent.
        assertTrue(pixelsNear(img, LineChart.color(2)) < 20, "no third series");
    }

    @Test
    void anEmptyChartIsBlankInsideThePlotArea() {
        BufferedImage empty = new LineChart("", "", "").render(300, 200);
        BufferedImage full = new LineChart("", "", "").series("line", new double[] {0, 1}, new double[] {0, 1})
                .render(300, 200);
        assertEquals(0, pixelsNear(empty, LineChart.color(0)));
        assertTrue(pixelsNear(full, LineChart.color(0)) > 50);
    }

    @Test
    void logAxesDrawPositiveDataOverManyDecades() {
        double[] x = {1e2, 1e4, 1e6, 1e8};
        double[] y = {1e-9, 1e-5, 1e-2, 10};
        BufferedImage img = new LineChart("log", "x", "y").logX(true).logY(true).markers(true).series("s", x, y)
                .render(500, 400);
        assertTrue(pixelsNear(img, LineChart.color(0)) > 100);
    }

    @Test
    void nonFinitePointsAreSkippedNotRejected() {
        double[] x = {0, 1, 2, 3, 4};
        double[] y = {0, 1, Double.NaN, 3, Double.POSITIVE_INFINITY};
        BufferedImage img = new LineChart("gap", "x", "y").series("s", x, y).render(400, 300);
        assertTrue(pixelsNear(img, LineChart.color(0)) > 20);
    }

    @Test
    void rejectsWhatCannotBeDrawn() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new LineChart("", "", "").series("a", new double[3], new double[2]));
        assertTrue(e.getMessage().contains("\"a\"") && e.getMessage().contains("3") && e.getMessage().contains("2"),
                e.getMessage());

        e = assertThrows(IllegalArgumentException.class,
                () -> new LineChart("", "", "").logY(true).series("b", new double[] {1, 2}, new double[] {1, 0}));
        assertTrue(e.getMessage().contains("\"b\"") && e.getMessage().contains("point 1"), e.getMessage());

        LineChart c = new LineChart("", "", "").series("c", new double[] {-1, 2}, new double[] {1, 1});
        e = assertThrows(IllegalArgumentException.class, () -> c.logX(true));
        assertTrue(e.getMessage().contains("\"c\"") && e.getMessage().contains("point 0"), e.getMessage());
        assertEquals(1, c.seriesCount(), "a rejected call leaves the chart unchanged");

        assertThrows(IllegalArgumentException.class, () -> c.render(0, 10));
        assertThrows(IllegalArgumentException.class, () -> c.save(tmp.resolve("chart.jpg").toFile(), 10, 10));
    }
}
