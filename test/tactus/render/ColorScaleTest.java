package tactus.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

/** The value-to-colour map: ends, clamping, linear blends between evenly spaced stops, argument checks. */
class ColorScaleTest {
    private static final int A = 0xFF000000;
    private static final int B = 0xFF0000FF;
    private static final int C = 0xFFFF0000;

    @Test
    void theEndsClampAndNaNTakesTheFirstColour() {
        ColorScale s = new ColorScale(-2, 6, A, B, C);
        assertEquals(A, s.colorAt(-2));
        assertEquals(A, s.colorAt(-100));
        assertEquals(A, s.colorAt(Double.NaN));
        assertEquals(A, s.colorAt(Double.NEGATIVE_INFINITY));
        assertEquals(C, s.colorAt(6));
        assertEquals(C, s.colorAt(1e9));
        assertEquals(C, s.colorAt(Double.POSITIVE_INFINITY));
        assertEquals(B, s.colorAt(2), "the middle stop sits at the middle of the range");
    }

    @Test
    void betweenStopsEachChannelIsBlendedLinearly() {
        ColorScale s = new ColorScale(0, 10, A, B, C);
        // a quarter of the way: halfway from A to B, blue 255 / 2 rounded
        assertEquals(0xFF000000 | Math.round(255 * 0.5f), s.colorAt(2.5));
        // 90 %: 80 % of the way from B to C
        int red = Math.round(255 * 0.8f);
        int blue = Math.round(255 * 0.2f);
        assertEquals(0xFF000000 | red << 16 | blue, s.colorAt(9));
        assertEquals(0.9, s.fraction(9), 1e-15);
        assertEquals(7.5, s.valueAt(0.75), 1e-15);
    }

    @Test
    void theHeatScaleGoesFromBlueToRed() {
        ColorScale s = ColorScale.heat(0, 1);
        assertEquals(5, s.stopCount());
        assertEquals(0xFF2C7BB6, s.colorAt(0));
        assertEquals(0xFFD7191C, s.colorAt(1));
        assertEquals(0xFFFFFFBF, s.colorAt(0.5));
    }

    @Test
    void badArgumentsAreRejectedAndLeaveTheScaleUnchanged() {
        ColorScale s = new ColorScale(0, 1, A, C);
        assertThrows(IllegalArgumentException.class, () -> s.setRange(1, 1));
        assertThrows(IllegalArgumentException.class, () -> s.setRange(0, Double.NaN));
        assertThrows(IllegalArgumentException.class, () -> new ColorScale(0, 1, A));
        assertThrows(IndexOutOfBoundsException.class, () -> s.stop(2));
        assertEquals(0, s.getMin());
        assertEquals(1, s.getMax());
    }
}
