package tactus.hapticstability;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import org.junit.jupiter.api.Test;
import tactus.report.LineChart;

/**
 * The Z-width plot's data step ({@link ZWidthPoints}) and its marks ({@link LineChart#lowerBounds}): the plotted value
 * is the felt stiffness, not the wall's; a wall stable at the scan's top is a lower bound (an arrow), never dropped; a
 * damping with no stable wall has no point; a kind of series with no point has no legend entry.
 */
class ZWidthPointsTest {
    @Test
    void theFeltStiffnessIsPlottedAndTheScansTopBecomesALowerBound() {
        double top = 16_000;
        double[] b = {0, 0.1, 0.2, 0.3};
        double[] lastStable = {814, top, 0, top};
        double[] felt = {820, 1390, Double.NaN, 800};
        ZWidthPoints z = ZWidthPoints.of(b, lastStable, felt, top);
        assertArrayEquals(new double[] {0}, z.edgeB);
        assertArrayEquals(new double[] {820}, z.edgeFelt, "the felt stiffness, not the wall's K");
        assertArrayEquals(new double[] {0.1, 0.3}, z.boundB, "stable at the scan's top: lower bounds, kept");
        assertArrayEquals(new double[] {1390, 800}, z.boundFelt);
    }

    @Test
    void lowerBoundsAreArrowsWithoutLinesAndAnEmptyKindHasNoLegendEntry() {
        ZWidthPoints z = ZWidthPoints.of(new double[] {0, 0.1}, new double[] {400, 600}, new double[] {390, 580}, 16_000);
        assertEquals(0, z.boundB.length);
        LineChart chart = new LineChart("t", "x", "y").logY(true).markers(true)
                .series("edges", z.edgeB, z.edgeFelt)
                .lowerBounds("at least", z.boundB, z.boundFelt)
                .lowerBounds("some", new double[] {0.2}, new double[] {2000})
                .note("assumed plant");
        assertEquals(2, chart.seriesCount(), "the empty lower-bound series adds no legend entry");
        assertFalse(chart.isLowerBounds(0));
        assertTrue(chart.isLowerBounds(1));
        BufferedImage img = chart.render(600, 420);
        assertEquals(600, img.getWidth());
    }
}
