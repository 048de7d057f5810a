package tactus.render;

import processing.core.PConstants;
import processing.core.PGraphics;

/**
 * A colour scale for {@link ColorBy}: a value in [min, max] is mapped linearly onto evenly spaced colour stops,
 * blended channel by channel between neighbouring stops; values below min take the first colour, values above
 * max (and +Infinity) the last, NaN the first. Everything a legend needs is public: the range, the stops, the
 * value at any fraction, and {@link #drawLegend} draws one.
 */
public final class ColorScale {
    private final int[] stops;
    private double min;
    private double max;

    /**
     * Creates a scale.
     *
     * @param min the value of the first colour, finite
     * @param max the value of the last colour, finite and &gt; min
     * @param argbStops two or more packed {@code 0xAARRGGBB} colours, from min to max
     */
    public ColorScale(double min, double max, int... argbStops) {
        if (argbStops == null || argbStops.length < 2) {
            throw new IllegalArgumentException("ColorScale: at least two colour stops are needed, got "
                    + (argbStops == null ? "null" : argbStops.length));
        }
        stops = argbStops.clone();
        setRange(min, max);
    }

    /**
     * A blue-to-red scale of five stops (blue, light blue, pale yellow, orange, red), readable on white and on
     * black and in print.
     */
    public static ColorScale heat(double min, double max) {
        return new ColorScale(min, max, 0xFF2C7BB6, 0xFFABD9E9, 0xFFFFFFBF, 0xFFFDAE61, 0xFFD7191C);
    }

    /** Sets the range; both finite, max &gt; min. */
    public void setRange(double min, double max) {
        if (!Double.isFinite(min) || !Double.isFinite(max) || !(max > min)) {
            throw new IllegalArgumentException("ColorScale.setRange: need finite min < max, got [" + min + ", "
                    + max + "]");
        }
        this.min = min;
        this.max = max;
    }

    /** {@return the value of the first colour} */
    public double getMin() {
        return min;
    }

    /** {@return the value of the last colour} */
    public double getMax() {
        return max;
    }

    /** {@return the number of colour stops} */
    public int stopCount() {
        return stops.length;
    }

    /** {@return colour stop {@code k} (0 at min), packed ARGB} */
    public int stop(int k) {
        if (k < 0 || k >= stops.length) {
            throw new IndexOutOfBoundsException("ColorScale.stop: " + k + " out of range 0.." + (stops.length - 1));
        }
        return stops[k];
    }

    /** {@return where a value sits on the scale, 0 at min to 1 at max, clamped; 0 for NaN} */
    public double fraction(double value) {
        if (!(value > min)) {
            return 0;
        }
        if (value >= max) {
            return 1;
        }
        return (value - min) / (max - min);
    }

    /** {@return the value at a fraction 0..1 of the scale (for legend ticks)} */
    public double valueAt(double fraction) {
        return min + fraction * (max - min);
    }

    /** {@return the colour of a value, packed ARGB (the stops' alpha)} */
    public int colorAt(double value) {
        double f = fraction(value) * (stops.length - 1);
        int k = (int) f;
        if (k >= stops.length - 1) {
            return stops[stops.length - 1];
        }
        return Colors.lerp(stops[k], stops[k + 1], (float) (f - k));
    }

    /**
     * Draws a horizontal legend: the colour bar in the rectangle (x, y, w, h), from min on the left to max on the
     * right, framed in black, with min, max and the label written under it in black. Call it after the model, outside any camera transform (for example after
     * {@code hint(DISABLE_DEPTH_TEST)} and {@code camera()} in P3D). It allocates a little (text); draw it once
     * per frame, not per element.
     *
     * @param g the target
     * @param label what the values are, with their unit, e.g. "speed (m/s)"; may be empty
     */
    public void drawLegend(PGraphics g, float x, float y, float w, float h, String label) {
        g.pushStyle();
        try {
            g.colorMode(PConstants.RGB, 255);
            int columns = Math.max(1, (int) w);
            float dw = w / columns;
            g.noStroke();
            for (int c = 0; c < columns; c++) {
                g.fill(colorAt(valueAt((c + 0.5) / columns)));
                g.rect(x + c * dw, y, dw + 0.5f, h);
            }
            g.noFill();
            g.stroke(0xFF000000);
            g.strokeWeight(1);
            g.rect(x, y, w, h);
            g.fill(0xFF000000);
            g.textSize(Math.max(9, h * 0.8f));
            g.textAlign(PConstants.LEFT, PConstants.TOP);
            g.text(format(min), x, y + h + 2);
            g.textAlign(PConstants.RIGHT, PConstants.TOP);
            g.text(format(max), x + w, y + h + 2);
            if (label != null && !label.isEmpty()) {
                g.textAlign(PConstants.CENTER, PConstants.TOP);
                g.text(label, x + w / 2, y + h + 2);
            }
        } finally {
            g.popStyle();
        }
    }

    private static String format(double v) {
        double a = Math.abs(v);
        if (a != 0 && (a < 1e-3 || a >= 1e5)) {
            return String.format(java.util.Locale.ROOT, "%.2e", v);
        }
        return String.format(java.util.Locale.ROOT, "%.4g", v);
    }
}
