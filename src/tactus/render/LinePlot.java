package tactus.render;

import java.awt.Font;
import java.awt.font.FontRenderContext;
import java.io.File;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.math.BigDecimal;
import java.math.BigInteger;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;

import processing.awt.PGraphicsJava2D;
import processing.core.PConstants;
import processing.core.PFont;
import processing.core.PImage;

/**
 * A line chart of one or more named data series, drawn off-screen with Processing's Java2D renderer.
 *
 * <p>A plot has a title, a label on each axis, and any number of series. Each series is a list of
 * (x, y) points joined by straight lines, in its own colour, and is listed by name in a legend to the right
 * of the chart. Each axis is either linear or logarithmic (base 10). Tick marks are placed at "nice" values
 * (1, 2 or 5 times a power of ten, or whole decades on a logarithmic axis) and labelled.
 * The range of each axis is found from the data, with 5% padding on each side, unless it is set with
 * {@link #xRange(double, double)} or {@link #yRange(double, double)}.
 *
 * <p>A point whose x or y is {@code NaN} or infinite is skipped, and the line is broken there.
 * Everything else that cannot be drawn is rejected with an {@link IllegalArgumentException} that names
 * the series and the point: arrays of different lengths, and zero or negative values on a logarithmic axis.
 *
 * <p>Drawing needs no running sketch and works in headless mode ({@code -Djava.awt.headless=true}).
 * Methods return the plot itself, so calls can be chained:
 *
 * <pre>{@code
 * new LinePlot("Error of the integrators", "time step (ns)", "max. position error (m)")
 *     .logX(true).logY(true).markers(true)
 *     .series("Euler", steps, eulerError)
 *     .series("Verlet", steps, verletError)
 *     .save(new File("build/report/error.png"), 800, 500);
 * }</pre>
 *
 * <p>A {@code LinePlot} keeps copies of the arrays it is given, so changing an array afterwards does not
 * change the plot. It is not safe to change a plot from one thread while another thread draws it.
 */
public final class LinePlot {

    /** The colour of the image background, opaque white ({@code 0xFFFFFFFF}), as a Processing ARGB colour. */
    public static final int BACKGROUND = 0xFFFFFFFF;

    private static final int TEXT = 0xFF212529;
    private static final int AXIS = 0xFF5F6770;
    private static final int GRID = 0xFFE4E7EB;
    private static final int LEGEND_BORDER = 0xFFCED4DA;

    /** Default series colours, chosen to be told apart easily; used in this order and then repeated. */
    private static final int[] PALETTE = {
        0xFF1F5FBF, // blue
        0xFFD9480F, // vermilion
        0xFF2B8A3E, // green
        0xFF862E9C, // purple
        0xFFC2255C, // crimson
        0xFF0B7285, // teal
        0xFFE67700, // amber
        0xFF495057, // slate
    };

    private static final double PADDING = 0.05;
    private static final int MAX_TICKS = 10;
    private static final FontRenderContext FONT_CONTEXT = new FontRenderContext(null, true, true);
    private static final List<String> IMAGE_TYPES = List.of("png", "jpg", "jpeg", "tif", "tiff", "tga");

    private final String title;
    private final String xLabel;
    private final String yLabel;
    private final List<Series> series = new ArrayList<>();
    private boolean logX;
    private boolean logY;
    private boolean markers;
    private double[] xRange;
    private double[] yRange;

    /**
     * Creates an empty plot.
     *
     * @param title  the title drawn above the chart; {@code null} or empty for none
     * @param xLabel the label of the horizontal axis; {@code null} or empty for none
     * @param yLabel the label of the vertical axis; {@code null} or empty for none
     */
    public LinePlot(String title, String xLabel, String yLabel) {
        this.title = title == null ? "" : title.trim();
        this.xLabel = xLabel == null ? "" : xLabel.trim();
        this.yLabel = yLabel == null ? "" : yLabel.trim();
    }

    /**
     * Makes the horizontal axis logarithmic (base 10) or linear. Linear is the default.
     *
     * @param on {@code true} for a logarithmic axis, {@code false} for a linear one
     * @return this plot
     * @throws IllegalArgumentException if {@code on} is {@code true} and a series already added, or the
     *                                  range set with {@link #xRange(double, double)}, has an x value that is
     *                                  zero or negative
     */
    public LinePlot logX(boolean on) {
        if (on) {
            for (Series s : series) {
                s.checkPositive(true);
            }
            checkRangePositive(xRange, "x");
        }
        logX = on;
        return this;
    }

    /**
     * Makes the vertical axis logarithmic (base 10) or linear. Linear is the default.
     *
     * @param on {@code true} for a logarithmic axis, {@code false} for a linear one
     * @return this plot
     * @throws IllegalArgumentException if {@code on} is {@code true} and a series already added, or the
     *                                  range set with {@link #yRange(double, double)}, has a y value that is
     *                                  zero or negative
     */
    public LinePlot logY(boolean on) {
        if (on) {
            for (Series s : series) {
                s.checkPositive(false);
            }
            checkRangePositive(yRange, "y");
        }
        logY = on;
        return this;
    }

    /**
     * Turns markers at the data points on or off. Off is the default. Each series gets its own marker
     * shape (circle, square, triangle, diamond, then repeated), which is also shown in the legend.
     *
     * @param on {@code true} to draw a marker at every point
     * @return this plot
     */
    public LinePlot markers(boolean on) {
        markers = on;
        return this;
    }

    /**
     * Fixes the range of the horizontal axis instead of finding it from the data. Lines that leave the range
     * are cut at the edge of the chart. Useful for animations, where every frame should use the same axes.
     *
     * @param min the value at the left edge
     * @param max the value at the right edge, greater than {@code min}
     * @return this plot
     * @throws IllegalArgumentException if a bound is not finite, if {@code min >= max}, or if the axis is
     *                                  logarithmic and {@code min} is zero or negative
     */
    public LinePlot xRange(double min, double max) {
        double[] range = checkRange(min, max, "x");
        if (logX) {
            checkRangePositive(range, "x");
        }
        xRange = range;
        return this;
    }

    /**
     * Fixes the range of the vertical axis instead of finding it from the data. Lines that leave the range
     * are cut at the edge of the chart. Useful for animations, where every frame should use the same axes.
     *
     * @param min the value at the bottom edge
     * @param max the value at the top edge, greater than {@code min}
     * @return this plot
     * @throws IllegalArgumentException if a bound is not finite, if {@code min >= max}, or if the axis is
     *                                  logarithmic and {@code min} is zero or negative
     */
    public LinePlot yRange(double min, double max) {
        double[] range = checkRange(min, max, "y");
        if (logY) {
            checkRangePositive(range, "y");
        }
        yRange = range;
        return this;
    }

    /**
     * Adds a series in the next default colour (see {@link #defaultColor(int)}).
     *
     * @param name the name shown in the legend; an empty name leaves the series out of the legend
     * @param xs   the x coordinates of the points
     * @param ys   the y coordinates of the points, as many as {@code xs}
     * @return this plot
     * @throws IllegalArgumentException if an argument is {@code null}, if the arrays differ in length, or if an
     *                                  axis is logarithmic and a point has a zero or negative coordinate on it
     */
    public LinePlot series(String name, double[] xs, double[] ys) {
        return series(name, xs, ys, defaultColor(series.size()));
    }

    /**
     * Adds a series in the given colour.
     *
     * @param name  the name shown in the legend; an empty name leaves the series out of the legend
     * @param xs    the x coordinates of the points
     * @param ys    the y coordinates of the points, as many as {@code xs}
     * @param color the line colour as a Processing ARGB colour, for example {@code color(200, 0, 0)} or
     *              {@code 0xFFC80000}; a colour with an alpha of zero is drawn opaque
     * @return this plot
     * @throws IllegalArgumentException if an argument is {@code null}, if the arrays differ in length, or if an
     *                                  axis is logarithmic and a point has a zero or negative coordinate on it
     */
    public LinePlot series(String name, double[] xs, double[] ys, int color) {
        if (name == null) {
            throw new IllegalArgumentException("series name is null");
        }
        if (xs == null || ys == null) {
            throw new IllegalArgumentException("series \"" + name + "\": " + (xs == null ? "xs" : "ys") + " is null");
        }
        if (xs.length != ys.length) {
            throw new IllegalArgumentException("series \"" + name + "\": xs has " + xs.length
                    + " values but ys has " + ys.length);
        }
        int argb = (color & 0xFF000000) == 0 ? color | 0xFF000000 : color;
        Series s = new Series(name.trim(), xs.clone(), ys.clone(), argb, series.size());
        if (logX) {
            s.checkPositive(true);
        }
        if (logY) {
            s.checkPositive(false);
        }
        series.add(s);
        return this;
    }

    /**
     * Returns the number of series added so far.
     *
     * @return the number of series
     */
    public int seriesCount() {
        return series.size();
    }

    /**
     * Returns the colour of a series.
     *
     * @param index the series index, in the order the series were added, starting at 0
     * @return the colour as an opaque Processing ARGB colour
     * @throws IndexOutOfBoundsException if there is no such series
     */
    public int seriesColor(int index) {
        return series.get(index).color;
    }

    /**
     * Returns the default colour that {@link #series(String, double[], double[])} gives to the series with the
     * given index. There are eight default colours; after the eighth they repeat.
     *
     * @param index the series index, 0 or more
     * @return the colour as an opaque Processing ARGB colour
     * @throws IllegalArgumentException if {@code index} is negative
     */
    public static int defaultColor(int index) {
        if (index < 0) {
            throw new IllegalArgumentException("series index must not be negative: " + index);
        }
        return PALETTE[index % PALETTE.length];
    }

    /**
     * Works out where everything goes in an image of the given size, without drawing: the chart area, the
     * axis ranges and the ticks. The result maps data coordinates to pixel coordinates of the image that
     * {@link #render(int, int)} or {@link #save(File, int, int)} makes at the same size.
     *
     * @param width  the image width in pixels
     * @param height the image height in pixels
     * @return the layout
     * @throws IllegalArgumentException if the plot has no series or no finite point, or if the image is too
     *                                  small for the text around the chart
     */
    public Layout layout(int width, int height) {
        if (width <= 0 || height <= 0) {
            throw new IllegalArgumentException("image size must be positive: " + width + " x " + height);
        }
        double[] data = dataBounds();
        double[] ax = axisRange(xRange, data[0], data[1], logX);
        double[] ay = axisRange(yRange, data[2], data[3], logY);
        return new Layout(this, width, height, ax, ay);
    }

    /**
     * Draws the plot into a new off-screen image. In a sketch, show it with {@code image(img, x, y)}.
     *
     * @param width  the image width in pixels
     * @param height the image height in pixels
     * @return the image, with its {@code pixels} loaded
     * @throws IllegalArgumentException if the plot has no series or no finite point, or if the image is too
     *                                  small for the text around the chart
     */
    public PImage render(int width, int height) {
        Layout layout = layout(width, height);
        PGraphicsJava2D g = new PGraphicsJava2D();
        g.setPrimary(false);
        g.setSize(width, height);
        g.beginDraw();
        try {
            draw(g, layout);
        } finally {
            g.endDraw();
        }
        g.loadPixels();
        return g;
    }

    /**
     * Draws the plot and writes it to an image file. Missing parent folders are created. The format follows
     * the file name's extension: {@code .png} (recommended), {@code .jpg}, {@code .jpeg}, {@code .tif},
     * {@code .tiff} or {@code .tga}.
     *
     * @param file   the file to write; a relative path is taken relative to the current working folder
     * @param width  the image width in pixels
     * @param height the image height in pixels
     * @return the file written, as an absolute path
     * @throws IllegalArgumentException if {@code file} is {@code null} or has an unsupported extension, if the
     *                                  plot has no series or no finite point, or if the image is too small
     * @throws UncheckedIOException     if the folder cannot be created or the file cannot be written
     */
    public File save(File file, int width, int height) {
        if (file == null) {
            throw new IllegalArgumentException("file is null");
        }
        String name = file.getName();
        int dot = name.lastIndexOf('.');
        String extension = dot < 0 ? "" : name.substring(dot + 1).toLowerCase(Locale.ROOT);
        if (!IMAGE_TYPES.contains(extension)) {
            throw new IllegalArgumentException("cannot write \"" + name + "\": the file name must end with one of "
                    + IMAGE_TYPES);
        }
        PImage image = render(width, height);
        File target = file.getAbsoluteFile();
        File folder = target.getParentFile();
        if (folder != null && !folder.isDirectory() && !folder.mkdirs() && !folder.isDirectory()) {
            throw new UncheckedIOException(new IOException("cannot create the folder " + folder));
        }
        // A plain PImage copy saves synchronously; PGraphics.save() would save on a background thread.
        PImage copy = image.get();
        if (!copy.save(target.getPath()) || !target.isFile()) {
            throw new UncheckedIOException(new IOException("could not write " + target));
        }
        return target;
    }

    // -----------------------------------------------------------------------------------------------------------
    // Ticks
    // -----------------------------------------------------------------------------------------------------------

    /**
     * Returns "nice" tick values for a linear axis: every multiple of a step that lies in {@code [min, max]},
     * where the step is 1, 2 or 5 times a power of ten, chosen as the smallest such step that gives at most
     * {@code maxTicks} ticks. The values are the nearest doubles to the exact decimals, so a step of 0.1 gives
     * 0.3, not 0.30000000000000004. For example {@code niceTicks(0, 10, 6)} is {@code {0, 2, 4, 6, 8, 10}}.
     *
     * @param min      the lower end of the axis
     * @param max      the upper end of the axis, greater than {@code min}
     * @param maxTicks the largest number of ticks wanted, 2 or more
     * @return the tick values in ascending order; there is at least one when {@code maxTicks >= 2}
     * @throws IllegalArgumentException if a bound is not finite, if {@code min >= max}, or if
     *                                  {@code maxTicks < 2}
     */
    public static double[] niceTicks(double min, double max, int maxTicks) {
        checkTickArguments(min, max, maxTicks);
        double span = max - min;
        if (!Double.isFinite(span)) {
            throw new IllegalArgumentException("axis range is too large: [" + min + ", " + max + "]");
        }
        int exponent = (int) Math.floor(Math.log10(span / maxTicks));
        int[] mantissas = {1, 2, 5};
        for (int e = exponent; ; e++) {
            for (int m : mantissas) {
                BigDecimal step = BigDecimal.valueOf(m).scaleByPowerOfTen(e);
                double stepValue = step.doubleValue();
                double slack = stepValue * 1e-9;
                long first = (long) Math.ceil((min - slack) / stepValue);
                long last = (long) Math.floor((max + slack) / stepValue);
                if (last - first + 1 <= maxTicks) {
                    double[] ticks = new double[(int) Math.max(0, last - first + 1)];
                    for (int i = 0; i < ticks.length; i++) {
                        ticks[i] = step.multiply(BigDecimal.valueOf(first + i)).doubleValue();
                    }
                    return ticks;
                }
            }
        }
    }

    /**
     * Returns tick values for a logarithmic axis. These are the powers of ten in {@code [min, max]}; if there are
     * more than {@code maxTicks} of them, only every second, third, ... decade is kept, and if there are fewer
     * than two, the values 2 and 5 times a power of ten are added. For a range narrower than that, it falls back
     * to {@link #niceTicks(double, double, int)}. For example {@code logTicks(1e-9, 1e-3, 10)} gives the seven
     * decades from 1e-9 to 1e-3, and {@code logTicks(2, 30, 5)} gives {@code {2, 5, 10, 20}}.
     *
     * @param min      the lower end of the axis, greater than zero
     * @param max      the upper end of the axis, greater than {@code min}
     * @param maxTicks the largest number of ticks wanted, 2 or more
     * @return the tick values in ascending order
     * @throws IllegalArgumentException if a bound is not finite, if {@code min <= 0}, if {@code min >= max}, or
     *                                  if {@code maxTicks < 2}
     */
    public static double[] logTicks(double min, double max, int maxTicks) {
        checkTickArguments(min, max, maxTicks);
        if (min <= 0) {
            throw new IllegalArgumentException("a logarithmic axis needs a positive range: [" + min + ", " + max + "]");
        }
        double lo = Math.log10(min);
        double hi = Math.log10(max);
        double slack = 1e-9;
        int firstDecade = (int) Math.ceil(lo - slack);
        int lastDecade = (int) Math.floor(hi + slack);
        int decades = lastDecade - firstDecade + 1;
        List<Double> ticks = new ArrayList<>();
        if (decades >= 2) {
            int stride = (decades + maxTicks - 1) / maxTicks;
            int start = Math.floorDiv(firstDecade + stride - 1, stride) * stride;
            for (int k = start; k <= lastDecade; k += stride) {
                ticks.add(powerOfTen(1, k));
            }
            if (ticks.size() >= 2) {
                return toArray(ticks);
            }
            ticks.clear();
        }
        for (int k = firstDecade - 1; k <= lastDecade; k++) {
            for (int m : new int[] {1, 2, 5}) {
                double v = powerOfTen(m, k);
                double lv = Math.log10(v);
                if (lv >= lo - slack && lv <= hi + slack) {
                    ticks.add(v);
                }
            }
        }
        if (ticks.size() >= 2 && ticks.size() <= maxTicks) {
            return toArray(ticks);
        }
        if (ticks.size() > maxTicks) {
            List<Double> fewer = new ArrayList<>();
            for (double v : ticks) {
                if (BigDecimal.valueOf(v).stripTrailingZeros().unscaledValue().equals(BigInteger.ONE)) {
                    fewer.add(v);
                }
            }
            if (fewer.size() >= 2 && fewer.size() <= maxTicks) {
                return toArray(fewer);
            }
        }
        return niceTicks(min, max, maxTicks);
    }

    /**
     * Formats tick values as labels. Linear ticks get the same number of decimals (for example "0.0", "0.5",
     * "1.0"); very large or small values and logarithmic ticks outside 0.001 to 10000 use the form "2e-6".
     * The result does not depend on the default locale.
     */
    static String[] tickLabels(double[] ticks, boolean log) {
        String[] labels = new String[ticks.length];
        boolean scientific = false;
        int decimals = 0;
        for (double t : ticks) {
            double a = Math.abs(t);
            if (a != 0 && (log ? (a < 1e-3 || a >= 1e4) : (a < 1e-4 || a >= 1e6))) {
                scientific = true;
            }
            decimals = Math.max(decimals, Math.max(0, BigDecimal.valueOf(t).stripTrailingZeros().scale()));
        }
        for (int i = 0; i < ticks.length; i++) {
            BigDecimal v = BigDecimal.valueOf(ticks[i]).stripTrailingZeros();
            if (v.signum() == 0) {
                labels[i] = scientific || log ? "0" : BigDecimal.ZERO.setScale(decimals).toPlainString();
            } else if (scientific) {
                int exponent = v.precision() - v.scale() - 1;
                String mantissa = v.movePointLeft(exponent).stripTrailingZeros().toPlainString();
                labels[i] = mantissa + "e" + exponent;
            } else if (log) {
                labels[i] = v.toPlainString();
            } else {
                labels[i] = v.setScale(decimals).toPlainString();
            }
        }
        return labels;
    }

    // -----------------------------------------------------------------------------------------------------------
    // Layout
    // -----------------------------------------------------------------------------------------------------------

    /**
     * Where a plot's parts go in an image of a given size, made by {@link LinePlot#layout(int, int)}.
     * Pixel coordinates are measured from the top-left corner of the image, x to the right and y down,
     * as in Processing.
     */
    public static final class Layout {
        private final int width;
        private final int height;
        private final boolean logX;
        private final boolean logY;
        private final double ax0;
        private final double ax1;
        private final double ay0;
        private final double ay1;
        private final double[] xTicks;
        private final double[] yTicks;
        private final String[] xTickLabels;
        private final String[] yTickLabels;
        private final float left;
        private final float top;
        private final float right;
        private final float bottom;
        private final Style style;
        private final float legendWidth;

        private Layout(LinePlot plot, int width, int height, double[] ax, double[] ay) {
            this.width = width;
            this.height = height;
            this.logX = plot.logX;
            this.logY = plot.logY;
            this.ax0 = ax[0];
            this.ax1 = ax[1];
            this.ay0 = ay[0];
            this.ay1 = ay[1];
            Style s = new Style(width, height);
            this.style = s;

            top = s.pad + (plot.title.isEmpty() ? s.base * 0.5f : s.titleSize * 1.7f);
            bottom = height - s.pad - s.tickLength - s.base * 1.5f - (plot.xLabel.isEmpty() ? 0 : s.base * 1.5f);
            if (bottom - top < 2 * s.base) {
                throw tooSmall(width, height);
            }
            int maxY = clamp((int) ((bottom - top) / (s.base * 2.8f)), 2, MAX_TICKS);
            yTicks = ticks(ay0, ay1, logY, maxY);
            yTickLabels = tickLabels(yTicks, logY);
            float yLabelWidth = 0;
            for (String label : yTickLabels) {
                yLabelWidth = Math.max(yLabelWidth, textWidth(s.tickFont, label));
            }
            left = s.pad + (plot.yLabel.isEmpty() ? 0 : s.base * 1.6f) + yLabelWidth + s.tickLength + s.base * 0.4f;

            float nameWidth = 0;
            for (Series series : plot.series) {
                nameWidth = Math.max(nameWidth, textWidth(s.tickFont, series.name));
            }
            legendWidth = nameWidth > 0 ? s.pad + s.base * 0.6f + s.swatch + s.base * 0.5f + nameWidth + s.base * 0.6f : 0;
            // Without a legend, keep room for the half of the last x tick label that sticks out to the right.
            right = width - s.pad - (legendWidth > 0 ? legendWidth : s.base * 1.5f);
            if (right - left < 2 * s.base) {
                throw tooSmall(width, height);
            }

            // As many x ticks as fit without their labels touching.
            double[] xt = null;
            String[] xl = null;
            for (int maxX = clamp((int) ((right - left) / (s.base * 3f)), 2, MAX_TICKS); maxX >= 2; maxX--) {
                xt = ticks(ax0, ax1, logX, maxX);
                xl = tickLabels(xt, logX);
                float used = 0;
                for (String label : xl) {
                    used += textWidth(s.tickFont, label) + s.base * 1.2f;
                }
                if (used <= right - left) {
                    break;
                }
            }
            xTicks = xt;
            xTickLabels = xl;
        }

        private static IllegalArgumentException tooSmall(int width, int height) {
            return new IllegalArgumentException("an image of " + width + " x " + height
                    + " pixels is too small for this plot's text and chart");
        }

        private static double[] ticks(double a0, double a1, boolean log, int max) {
            return log ? logTicks(Math.pow(10, a0), Math.pow(10, a1), max) : niceTicks(a0, a1, max);
        }

        /**
         * Returns the image width.
         *
         * @return the width in pixels
         */
        public int width() {
            return width;
        }

        /**
         * Returns the image height.
         *
         * @return the height in pixels
         */
        public int height() {
            return height;
        }

        /**
         * Returns the x pixel coordinate of the left edge of the chart area (the axis box).
         *
         * @return the left edge in pixels
         */
        public float left() {
            return left;
        }

        /**
         * Returns the y pixel coordinate of the top edge of the chart area.
         *
         * @return the top edge in pixels
         */
        public float top() {
            return top;
        }

        /**
         * Returns the x pixel coordinate of the right edge of the chart area. The legend is to the right of it.
         *
         * @return the right edge in pixels
         */
        public float right() {
            return right;
        }

        /**
         * Returns the y pixel coordinate of the bottom edge of the chart area.
         *
         * @return the bottom edge in pixels
         */
        public float bottom() {
            return bottom;
        }

        /**
         * Returns the data value at the left edge of the chart area.
         *
         * @return the smallest x shown
         */
        public double xMin() {
            return logX ? Math.pow(10, ax0) : ax0;
        }

        /**
         * Returns the data value at the right edge of the chart area.
         *
         * @return the largest x shown
         */
        public double xMax() {
            return logX ? Math.pow(10, ax1) : ax1;
        }

        /**
         * Returns the data value at the bottom edge of the chart area.
         *
         * @return the smallest y shown
         */
        public double yMin() {
            return logY ? Math.pow(10, ay0) : ay0;
        }

        /**
         * Returns the data value at the top edge of the chart area.
         *
         * @return the largest y shown
         */
        public double yMax() {
            return logY ? Math.pow(10, ay1) : ay1;
        }

        /**
         * Returns the values at which the horizontal axis has ticks, in ascending order.
         *
         * @return a new array of tick values
         */
        public double[] xTicks() {
            return xTicks.clone();
        }

        /**
         * Returns the values at which the vertical axis has ticks, in ascending order.
         *
         * @return a new array of tick values
         */
        public double[] yTicks() {
            return yTicks.clone();
        }

        /**
         * Maps an x data value to an x pixel coordinate. Values outside the axis range map outside the chart area.
         *
         * @param x the data value; on a logarithmic axis it must be positive, or the result is {@code NaN} or
         *          infinite
         * @return the pixel coordinate
         */
        public float screenX(double x) {
            return (float) sx(x);
        }

        /**
         * Maps a y data value to a y pixel coordinate. Larger values are higher up, so they have smaller pixel
         * coordinates. Values outside the axis range map outside the chart area.
         *
         * @param y the data value; on a logarithmic axis it must be positive, or the result is {@code NaN} or
         *          infinite
         * @return the pixel coordinate
         */
        public float screenY(double y) {
            return (float) sy(y);
        }

        private double sx(double x) {
            double a = logX ? Math.log10(x) : x;
            return left + (a - ax0) / (ax1 - ax0) * (right - left);
        }

        private double sy(double y) {
            double a = logY ? Math.log10(y) : y;
            return bottom - (a - ay0) / (ay1 - ay0) * (bottom - top);
        }
    }

    /** Sizes of text, lines and spacing for one image size. */
    private static final class Style {
        final float base;
        final float titleSize;
        final float pad;
        final float tickLength;
        final float lineWeight;
        final float markerSize;
        final float swatch;
        final Font tickFont;
        final Font titleFont;

        Style(int width, int height) {
            base = clamp(Math.round(Math.min(width, height) / 40f), 10, 24);
            titleSize = Math.round(base * 1.25f);
            pad = Math.round(base * 0.8f);
            tickLength = Math.max(4, Math.round(base / 3f));
            lineWeight = Math.max(2f, base / 6f);
            markerSize = lineWeight * 3.5f;
            swatch = base * 2.2f;
            tickFont = new Font(Font.DIALOG, Font.PLAIN, Math.round(base));
            titleFont = new Font(Font.DIALOG, Font.BOLD, Math.round(titleSize));
        }
    }

    // -----------------------------------------------------------------------------------------------------------
    // Drawing
    // -----------------------------------------------------------------------------------------------------------

    private void draw(PGraphicsJava2D g, Layout l) {
        Style s = l.style;
        PFont tickFont = new PFont(s.tickFont, true);
        PFont titleFont = new PFont(s.titleFont, true);
        float w = l.right - l.left;
        float h = l.bottom - l.top;

        g.background(BACKGROUND);

        // Grid lines, on pixel centres so that they stay one pixel wide.
        g.strokeWeight(1);
        g.stroke(GRID);
        for (double t : l.xTicks) {
            float x = crisp(l.screenX(t));
            g.line(x, l.top, x, l.bottom);
        }
        for (double t : l.yTicks) {
            float y = crisp(l.screenY(t));
            g.line(l.left, y, l.right, y);
        }

        // The series, clipped to the chart area.
        g.clip(l.left, l.top, w, h);
        for (Series series : this.series) {
            drawLines(g, l, series);
        }
        if (markers) {
            for (Series series : this.series) {
                for (int i = 0; i < series.xs.length; i++) {
                    if (series.finite(i)) {
                        double x = l.sx(series.xs[i]);
                        double y = l.sy(series.ys[i]);
                        if (x > l.left - s.markerSize && x < l.right + s.markerSize
                                && y > l.top - s.markerSize && y < l.bottom + s.markerSize) {
                            drawMarker(g, series, (float) x, (float) y, s.markerSize);
                        }
                    }
                }
            }
        }
        g.noClip();

        // Axis box, ticks and tick labels.
        g.noFill();
        g.stroke(AXIS);
        g.strokeWeight(1);
        g.rect(crisp(l.left), crisp(l.top), Math.round(w), Math.round(h));
        g.textFont(tickFont);
        g.fill(TEXT);
        g.textAlign(PConstants.CENTER, PConstants.TOP);
        for (int i = 0; i < l.xTicks.length; i++) {
            float x = crisp(l.screenX(l.xTicks[i]));
            g.line(x, l.bottom, x, l.bottom + s.tickLength);
            g.text(l.xTickLabels[i], x, l.bottom + s.tickLength + s.base * 0.25f);
        }
        g.textAlign(PConstants.RIGHT, PConstants.CENTER);
        for (int i = 0; i < l.yTicks.length; i++) {
            float y = crisp(l.screenY(l.yTicks[i]));
            g.line(l.left - s.tickLength, y, l.left, y);
            g.text(l.yTickLabels[i], l.left - s.tickLength - s.base * 0.3f, y);
        }

        // Title and axis labels.
        if (!xLabel.isEmpty()) {
            g.textAlign(PConstants.CENTER, PConstants.BOTTOM);
            g.text(xLabel, l.left + w / 2, l.height - s.pad);
        }
        if (!yLabel.isEmpty()) {
            g.pushMatrix();
            g.translate(s.pad + s.base * 0.6f, l.top + h / 2);
            g.rotate(-PConstants.HALF_PI);
            g.textAlign(PConstants.CENTER, PConstants.CENTER);
            g.text(yLabel, 0, 0);
            g.popMatrix();
        }
        if (!title.isEmpty()) {
            g.textFont(titleFont);
            // Centred over the chart, but moved sideways (up to centred in the image) so that it stays inside.
            float half = textWidth(s.titleFont, title) / 2;
            float x = Math.max(s.pad + half, Math.min(l.width - s.pad - half, l.left + w / 2));
            if (2 * half > l.width - 2 * s.pad) {
                x = l.width / 2f;
            }
            g.textAlign(PConstants.CENTER, PConstants.BASELINE);
            g.text(title, x, s.pad + s.titleSize);
        }

        drawLegend(g, l, tickFont);
    }

    private void drawLines(PGraphicsJava2D g, Layout l, Series series) {
        Style s = l.style;
        g.noFill();
        g.stroke(series.color);
        g.strokeWeight(s.lineWeight);
        g.strokeJoin(PConstants.ROUND);
        g.strokeCap(PConstants.ROUND);
        // Segments are clipped in double precision to a rectangle a little larger than the chart area, so that
        // points far outside a fixed range never reach Java2D as huge coordinates.
        double margin = s.lineWeight * 2;
        double x0 = l.left - margin;
        double y0 = l.top - margin;
        double x1 = l.right + margin;
        double y1 = l.bottom + margin;
        int n = series.xs.length;
        double[] seg = new double[4];
        boolean open = false;
        for (int i = 0; i < n; i++) {
            if (!series.finite(i)) {
                continue;
            }
            boolean alone = (i == 0 || !series.finite(i - 1)) && (i == n - 1 || !series.finite(i + 1));
            if (alone) {
                float x = (float) l.sx(series.xs[i]);
                float y = (float) l.sy(series.ys[i]);
                if (x >= x0 && x <= x1 && y >= y0 && y <= y1) {
                    g.noStroke();
                    g.fill(series.color);
                    g.ellipse(x, y, s.lineWeight * 1.5f, s.lineWeight * 1.5f);
                    g.noFill();
                    g.stroke(series.color);
                }
            }
            if (i == n - 1 || !series.finite(i + 1)) {
                continue;
            }
            seg[0] = l.sx(series.xs[i]);
            seg[1] = l.sy(series.ys[i]);
            seg[2] = l.sx(series.xs[i + 1]);
            seg[3] = l.sy(series.ys[i + 1]);
            int clipped = clipSegment(seg, x0, y0, x1, y1);
            if (clipped < 0) {
                if (open) {
                    g.endShape();
                    open = false;
                }
                continue;
            }
            if (open && (clipped & 1) != 0) {
                g.endShape();
                open = false;
            }
            if (!open) {
                g.beginShape();
                g.vertex((float) seg[0], (float) seg[1]);
                open = true;
            }
            g.vertex((float) seg[2], (float) seg[3]);
            if ((clipped & 2) != 0) {
                g.endShape();
                open = false;
            }
        }
        if (open) {
            g.endShape();
        }
    }

    /**
     * Clips the segment in {@code seg} (x0, y0, x1, y1) to a rectangle, in place (Liang and Barsky's method).
     * Returns -1 if nothing is left, otherwise bit 0 set if the start was moved and bit 1 set if the end was.
     */
    static int clipSegment(double[] seg, double xmin, double ymin, double xmax, double ymax) {
        for (double v : seg) {
            if (!Double.isFinite(v)) {
                return -1;
            }
        }
        double dx = seg[2] - seg[0];
        double dy = seg[3] - seg[1];
        double[] p = {-dx, dx, -dy, dy};
        double[] q = {seg[0] - xmin, xmax - seg[0], seg[1] - ymin, ymax - seg[1]};
        double t0 = 0;
        double t1 = 1;
        for (int k = 0; k < 4; k++) {
            if (p[k] == 0) {
                if (q[k] < 0) {
                    return -1;
                }
            } else {
                double r = q[k] / p[k];
                if (p[k] < 0) {
                    if (r > t1) {
                        return -1;
                    }
                    t0 = Math.max(t0, r);
                } else {
                    if (r < t0) {
                        return -1;
                    }
                    t1 = Math.min(t1, r);
                }
            }
        }
        double sx = seg[0];
        double sy = seg[1];
        int moved = 0;
        if (t0 > 0) {
            seg[0] = sx + t0 * dx;
            seg[1] = sy + t0 * dy;
            moved |= 1;
        }
        if (t1 < 1) {
            seg[2] = sx + t1 * dx;
            seg[3] = sy + t1 * dy;
            moved |= 2;
        }
        return moved;
    }

    private static void drawMarker(PGraphicsJava2D g, Series series, float x, float y, float size) {
        g.fill(series.color);
        g.stroke(BACKGROUND);
        g.strokeWeight(1);
        float r = size / 2;
        switch (series.index % 4) {
            case 0:
                g.ellipse(x, y, size, size);
                break;
            case 1:
                g.rect(x - r * 0.9f, y - r * 0.9f, r * 1.8f, r * 1.8f);
                break;
            case 2:
                g.triangle(x, y - r * 1.15f, x - r * 1.1f, y + r * 0.8f, x + r * 1.1f, y + r * 0.8f);
                break;
            default:
                g.quad(x, y - r * 1.2f, x + r * 1.2f, y, x, y + r * 1.2f, x - r * 1.2f, y);
                break;
        }
    }

    private void drawLegend(PGraphicsJava2D g, Layout l, PFont font) {
        List<Series> listed = new ArrayList<>();
        for (Series s : series) {
            if (!s.name.isEmpty()) {
                listed.add(s);
            }
        }
        if (listed.isEmpty() || l.legendWidth <= 0) {
            return;
        }
        Style s = l.style;
        float row = s.base * 1.6f;
        float x = crisp(l.right + s.pad);
        float y = crisp(l.top);
        float boxWidth = l.legendWidth - s.pad;
        float boxHeight = listed.size() * row + s.base * 0.6f;
        g.fill(BACKGROUND);
        g.stroke(LEGEND_BORDER);
        g.strokeWeight(1);
        g.rect(x, y, Math.round(boxWidth), Math.round(boxHeight));
        g.textFont(font);
        g.textAlign(PConstants.LEFT, PConstants.CENTER);
        for (int i = 0; i < listed.size(); i++) {
            Series series = listed.get(i);
            float cy = y + s.base * 0.3f + row * (i + 0.5f);
            float sx0 = x + s.base * 0.6f;
            float sx1 = sx0 + s.swatch;
            g.stroke(series.color);
            g.strokeWeight(s.lineWeight);
            g.strokeCap(PConstants.ROUND);
            g.line(sx0, cy, sx1, cy);
            if (markers) {
                drawMarker(g, series, (sx0 + sx1) / 2, cy, s.markerSize);
            }
            g.fill(TEXT);
            g.text(series.name, sx1 + s.base * 0.5f, cy);
        }
    }

    // -----------------------------------------------------------------------------------------------------------
    // Data
    // -----------------------------------------------------------------------------------------------------------

    private static final class Series {
        final String name;
        final double[] xs;
        final double[] ys;
        final int color;
        final int index;

        Series(String name, double[] xs, double[] ys, int color, int index) {
            this.name = name;
            this.xs = xs;
            this.ys = ys;
            this.color = color;
            this.index = index;
        }

        boolean finite(int i) {
            return Double.isFinite(xs[i]) && Double.isFinite(ys[i]);
        }

        void checkPositive(boolean xAxis) {
            double[] values = xAxis ? xs : ys;
            String axis = xAxis ? "x" : "y";
            for (int i = 0; i < values.length; i++) {
                if (finite(i) && values[i] <= 0) {
                    throw new IllegalArgumentException("series \"" + name + "\": " + axis + "[" + i + "] = " + values[i]
                            + " is not positive, but the " + axis + " axis is logarithmic");
                }
            }
        }
    }

    /** Returns {xMin, xMax, yMin, yMax} over all points whose coordinates are both finite. */
    private double[] dataBounds() {
        if (series.isEmpty()) {
            throw new IllegalArgumentException("nothing to plot: the plot has no series");
        }
        double[] b = {Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY,
                      Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY};
        for (Series s : series) {
            for (int i = 0; i < s.xs.length; i++) {
                if (s.finite(i)) {
                    b[0] = Math.min(b[0], s.xs[i]);
                    b[1] = Math.max(b[1], s.xs[i]);
                    b[2] = Math.min(b[2], s.ys[i]);
                    b[3] = Math.max(b[3], s.ys[i]);
                }
            }
        }
        if (b[0] > b[1]) {
            throw new IllegalArgumentException("nothing to plot: no series has a point with finite x and y");
        }
        return b;
    }

    /** Returns the axis range in axis units (log10 of the value on a logarithmic axis), padded if automatic. */
    private static double[] axisRange(double[] fixed, double min, double max, boolean log) {
        if (fixed != null) {
            return log ? new double[] {Math.log10(fixed[0]), Math.log10(fixed[1])} : fixed.clone();
        }
        double a = log ? Math.log10(min) : min;
        double b = log ? Math.log10(max) : max;
        double span = b - a;
        if (span <= Math.max(Math.abs(a), Math.abs(b)) * 1e-12) {
            double half = log ? 0.5 : (a == 0 ? 1 : Math.abs(a) * 0.1);
            return new double[] {a - half, b + half};
        }
        return new double[] {a - span * PADDING, b + span * PADDING};
    }

    private static double[] checkRange(double min, double max, String axis) {
        if (!Double.isFinite(min) || !Double.isFinite(max)) {
            throw new IllegalArgumentException(axis + " range must be finite: [" + min + ", " + max + "]");
        }
        if (min >= max) {
            throw new IllegalArgumentException(axis + " range must have min < max: [" + min + ", " + max + "]");
        }
        return new double[] {min, max};
    }

    private static void checkRangePositive(double[] range, String axis) {
        if (range != null && range[0] <= 0) {
            throw new IllegalArgumentException("the " + axis + " range [" + range[0] + ", " + range[1]
                    + "] is not positive, but the " + axis + " axis is logarithmic");
        }
    }

    private static void checkTickArguments(double min, double max, int maxTicks) {
        if (!Double.isFinite(min) || !Double.isFinite(max) || min >= max) {
            throw new IllegalArgumentException("tick range must be finite with min < max: [" + min + ", " + max + "]");
        }
        if (maxTicks < 2) {
            throw new IllegalArgumentException("maxTicks must be at least 2: " + maxTicks);
        }
    }

    private static double powerOfTen(int mantissa, int exponent) {
        return BigDecimal.valueOf(mantissa).scaleByPowerOfTen(exponent).doubleValue();
    }

    private static double[] toArray(List<Double> values) {
        double[] a = new double[values.size()];
        for (int i = 0; i < a.length; i++) {
            a[i] = values.get(i);
        }
        Arrays.sort(a);
        return a;
    }

    private static float textWidth(Font font, String text) {
        return text.isEmpty() ? 0 : (float) font.getStringBounds(text, FONT_CONTEXT).getWidth();
    }

    private static float crisp(float v) {
        return (float) Math.floor(v) + 0.5f;
    }

    private static int clamp(int v, int lo, int hi) {
        return Math.max(lo, Math.min(hi, v));
    }
}
