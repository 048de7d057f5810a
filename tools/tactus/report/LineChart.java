package tactus.report;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.geom.Ellipse2D;
import java.awt.image.BufferedImage;
import java.io.File;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

import org.jfree.chart.ChartUtils;
import org.jfree.chart.JFreeChart;
import org.jfree.chart.axis.LogarithmicAxis;
import org.jfree.chart.axis.NumberAxis;
import org.jfree.chart.axis.ValueAxis;
import org.jfree.chart.plot.XYPlot;
import org.jfree.chart.renderer.xy.XYLineAndShapeRenderer;
import org.jfree.chart.title.LegendTitle;
import org.jfree.chart.title.TextTitle;
import org.jfree.chart.ui.RectangleEdge;
import org.jfree.chart.ui.RectangleInsets;
import org.jfree.data.xy.XYSeries;
import org.jfree.data.xy.XYSeriesCollection;

/**
 * A line chart of named data series for the reports and the demo, drawn by JFreeChart and saved as PNG.
 *
 * <p>A chart has a title, a label on each axis and any number of series; each series is a list of (x, y)
 * points joined by straight lines, in its own colour, named in a legend below the chart. Each axis is linear
 * or logarithmic (base 10). A point whose x or y is {@code NaN} or infinite is not drawn, and the line is
 * broken there. Everything else that cannot be drawn is rejected with an {@link IllegalArgumentException}
 * that names the series and the point: arrays of different lengths, and zero or negative values on a
 * logarithmic axis.
 *
 * <p>Drawing needs no display: it works with {@code -Djava.awt.headless=true}. The text uses the logical
 * font {@code SansSerif} (DejaVu Sans on Debian). Methods return the chart itself, so calls can be chained:
 *
 * <pre>{@code
 * new LineChart("Error of the integrators", "time step (ns)", "max. position error (m)")
 *     .logX(true).logY(true).markers(true)
 *     .series("Euler", steps, eulerError)
 *     .save(new File("build/report/error.png"), 800, 500);
 * }</pre>
 *
 * <p>The chart keeps copies of the arrays it is given. It is not thread-safe.
 */
public final class LineChart {

    /** Default series colours, easy to tell apart; used in this order and then repeated. */
    private static final Color[] PALETTE = {
        new Color(0x1F5FBF), // blue
        new Color(0xD9480F), // vermilion
        new Color(0x2B8A3E), // green
        new Color(0x862E9C), // purple
        new Color(0xC2255C), // crimson
        new Color(0x0B7285), // teal
        new Color(0xE67700), // amber
        new Color(0x495057), // slate
    };
    private static final Color TEXT = new Color(0x212529);
    private static final Color GRID = new Color(0xE9ECEF);

    private final String title;
    private final String xLabel;
    private final String yLabel;
    private final List<String> names = new ArrayList<>();
    private final List<double[][]> points = new ArrayList<>();
    private final List<Boolean> lowerBounds = new ArrayList<>();
    private final List<String> notes = new ArrayList<>();
    private boolean logX;
    private boolean logY;
    private boolean markers;

    /**
     * Creates an empty chart.
     *
     * @param title  the title drawn above the chart; {@code null} or empty for none
     * @param xLabel the label of the horizontal axis; {@code null} or empty for none
     * @param yLabel the label of the vertical axis; {@code null} or empty for none
     */
    public LineChart(String title, String xLabel, String yLabel) {
        this.title = title == null ? "" : title.trim();
        this.xLabel = xLabel == null ? "" : xLabel.trim();
        this.yLabel = yLabel == null ? "" : yLabel.trim();
    }

    /**
     * Makes the horizontal axis logarithmic (base 10) or linear. Linear is the default.
     *
     * @param on {@code true} for a logarithmic axis
     * @return this chart
     * @throws IllegalArgumentException if {@code on} and a series already added has a zero or negative x
     */
    public LineChart logX(boolean on) {
        if (on) {
            for (int i = 0; i < names.size(); i++) {
                checkPositive(names.get(i), points.get(i)[0], "x");
            }
        }
        logX = on;
        return this;
    }

    /**
     * Makes the vertical axis logarithmic (base 10) or linear. Linear is the default.
     *
     * @param on {@code true} for a logarithmic axis
     * @return this chart
     * @throws IllegalArgumentException if {@code on} and a series already added has a zero or negative y
     */
    public LineChart logY(boolean on) {
        if (on) {
            for (int i = 0; i < names.size(); i++) {
                checkPositive(names.get(i), points.get(i)[1], "y");
            }
        }
        logY = on;
        return this;
    }

    /**
     * Draws a small dot on every point, as well as the lines. Off by default.
     *
     * @param on {@code true} to draw the dots
     * @return this chart
     */
    public LineChart markers(boolean on) {
        markers = on;
        return this;
    }

    /**
     * Adds a series in the next colour of the palette.
     *
     * @param name the name shown in the legend
     * @param xs   the x of each point
     * @param ys   the y of each point, as many as {@code xs}
     * @return this chart
     * @throws IllegalArgumentException if an array is {@code null}, the lengths differ, or a value is zero or
     *                                  negative on a logarithmic axis
     */
    public LineChart series(String name, double[] xs, double[] ys) {
        String n = name == null ? "" : name;
        if (xs == null || ys == null) {
            throw new IllegalArgumentException("series \"" + n + "\": " + (xs == null ? "xs" : "ys") + " is null");
        }
        if (xs.length != ys.length) {
            throw new IllegalArgumentException("series \"" + n + "\": " + xs.length + " x values but " + ys.length
                    + " y values");
        }
        if (logX) {
            checkPositive(n, xs, "x");
        }
        if (logY) {
            checkPositive(n, ys, "y");
        }
        names.add(n);
        points.add(new double[][] {xs.clone(), ys.clone()});
        lowerBounds.add(false);
        return this;
    }

    /**
     * Adds a series of lower bounds (censored points: the true value is at least y, for example a search that was
     * still stable at its top), drawn as upward arrows from each point, not joined by lines, in the next colour.
     * A series with no point is not added (no legend entry without a mark).
     *
     * @param name the name shown in the legend
     * @param xs   the x of each point
     * @param ys   the lower bound at each point, as many as {@code xs}
     * @return this chart
     * @throws IllegalArgumentException as {@link #series}
     */
    public LineChart lowerBounds(String name, double[] xs, double[] ys) {
        if (xs != null && xs.length == 0 && ys != null && ys.length == 0) {
            return this;
        }
        series(name, xs, ys);
        lowerBounds.set(lowerBounds.size() - 1, true);
        return this;
    }

    /**
     * Adds a line of small text under the chart (an assumption behind the data, say), in the order added.
     *
     * @param line the text; {@code null} or empty adds nothing
     * @return this chart
     */
    public LineChart note(String line) {
        if (line != null && !line.isEmpty()) {
            notes.add(line);
        }
        return this;
    }

    /**
     * Tells whether a series is drawn as lower bounds (arrows).
     *
     * @param index the series index, from 0
     * @return true for a series added by {@link #lowerBounds}
     */
    public boolean isLowerBounds(int index) {
        return lowerBounds.get(index);
    }

    /** An upward arrow whose foot is at the point: a stem of 16 pixels and a head. */
    private static java.awt.Shape arrow() {
        java.awt.geom.Path2D.Double a = new java.awt.geom.Path2D.Double();
        a.moveTo(-1, 0);
        a.lineTo(-1, -11);
        a.lineTo(-5, -11);
        a.lineTo(0, -18);
        a.lineTo(5, -11);
        a.lineTo(1, -11);
        a.lineTo(1, 0);
        a.closePath();
        return a;
    }

    /** @return the number of series added so far */
    public int seriesCount() {
        return names.size();
    }

    /** The line of a series in the given pass over the palette: solid, then dashed, then dotted. */
    private static BasicStroke stroke(int pass) {
        switch (Math.floorMod(pass, 3)) {
            case 0:
                return new BasicStroke(1.6f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND);
            case 1:
                return new BasicStroke(1.6f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_ROUND, 10f, new float[] {7f, 4f}, 0f);
            default:
                return new BasicStroke(1.6f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND, 10f, new float[] {1f, 4f}, 0f);
        }
    }

    /** The marker of a series in the given pass over the palette: a dot, then a square, then a diamond. */
    private static java.awt.Shape marker(int pass) {
        switch (Math.floorMod(pass, 3)) {
            case 0:
                return new Ellipse2D.Double(-3, -3, 6, 6);
            case 1:
                return new java.awt.geom.Rectangle2D.Double(-3, -3, 6, 6);
            default:
                java.awt.geom.Path2D.Double d = new java.awt.geom.Path2D.Double();
                d.moveTo(0, -4);
                d.lineTo(4, 0);
                d.lineTo(0, 4);
                d.lineTo(-4, 0);
                d.closePath();
                return d;
        }
    }

    /**
     * Returns the colour of a series: the palette, in order, repeated.
     *
     * @param index the series index, from 0
     * @return its colour
     */
    public static Color color(int index) {
        return PALETTE[Math.floorMod(index, PALETTE.length)];
    }

    /**
     * Draws the chart into a new image.
     *
     * @param width  image width, pixels (at least 1)
     * @param height image height, pixels (at least 1)
     * @return the image, {@code width} by {@code height}, opaque
     * @throws IllegalArgumentException if a size is below 1
     */
    public BufferedImage render(int width, int height) {
        checkSize(width, height);
        return build().createBufferedImage(width, height, BufferedImage.TYPE_INT_RGB, null);
    }

    /**
     * Draws the chart and saves it as a PNG file, creating missing parent folders.
     *
     * @param file   the file to write; its name must end in {@code .png}
     * @param width  image width, pixels (at least 1)
     * @param height image height, pixels (at least 1)
     * @return {@code file}
     * @throws IllegalArgumentException if the name does not end in {@code .png} or a size is below 1
     * @throws UncheckedIOException     if the file cannot be written
     */
    public File save(File file, int width, int height) {
        if (!file.getName().toLowerCase(Locale.ROOT).endsWith(".png")) {
            throw new IllegalArgumentException("chart file " + file + " must end in .png");
        }
        checkSize(width, height);
        File parent = file.getAbsoluteFile().getParentFile();
        if (parent != null && !parent.isDirectory() && !parent.mkdirs()) {
            throw new UncheckedIOException(new IOException("cannot create folder " + parent));
        }
        try {
            ChartUtils.saveChartAsPNG(file, build(), width, height);
        } catch (IOException e) {
            throw new UncheckedIOException("cannot write chart " + file, e);
        }
        return file;
    }

    private JFreeChart build() {
        XYSeriesCollection data = new XYSeriesCollection();
        for (int i = 0; i < names.size(); i++) {
            // Series keys must be unique in JFreeChart; a repeated name gets an invisible suffix of spaces.
            String key = names.get(i);
            while (data.getSeriesIndex(key) >= 0) {
                key = key + " ";
            }
            XYSeries s = new XYSeries(key, false, true);
            double[] xs = points.get(i)[0];
            double[] ys = points.get(i)[1];
            double lastX = Double.NaN;
            for (int p = 0; p < xs.length; p++) {
                if (Double.isFinite(xs[p]) && Double.isFinite(ys[p])) {
                    s.add(xs[p], ys[p]);
                    lastX = xs[p];
                } else if (!Double.isNaN(lastX)) {
                    s.add(lastX, Double.NaN);   // a NaN y breaks the line here
                }
            }
            data.addSeries(s);
        }

        XYLineAndShapeRenderer renderer = new XYLineAndShapeRenderer(true, markers);
        for (int i = 0; i < names.size(); i++) {
            int pass = i / PALETTE.length;   // past the palette's length, the colours repeat: the dash and marker tell
            renderer.setSeriesPaint(i, color(i));
            renderer.setSeriesStroke(i, stroke(pass));
            renderer.setSeriesShape(i, marker(pass));
            if (lowerBounds.get(i)) {
                renderer.setSeriesShape(i, arrow());
                renderer.setSeriesShapesVisible(i, true);
                renderer.setSeriesShapesFilled(i, true);
                renderer.setSeriesLinesVisible(i, false);
            }
        }

        XYPlot plot = new XYPlot(data, axis(xLabel, logX, false), axis(yLabel, logY, true), renderer);
        plot.setBackgroundPaint(Color.WHITE);
        plot.setDomainGridlinePaint(GRID);
        plot.setRangeGridlinePaint(GRID);
        plot.setDomainGridlineStroke(new BasicStroke(1f));
        plot.setRangeGridlineStroke(new BasicStroke(1f));
        plot.setOutlinePaint(Color.GRAY);
        plot.setAxisOffset(RectangleInsets.ZERO_INSETS);

        JFreeChart chart = new JFreeChart(null, new Font(Font.SANS_SERIF, Font.BOLD, 15), plot, !names.isEmpty());
        chart.setBackgroundPaint(Color.WHITE);
        chart.setAntiAlias(true);
        chart.setTextAntiAlias(true);
        chart.setPadding(new RectangleInsets(8, 8, 8, 16));
        if (!title.isEmpty()) {
            TextTitle t = new TextTitle(title, new Font(Font.SANS_SERIF, Font.BOLD, 15));
            t.setPaint(TEXT);
            chart.setTitle(t);
        }
        for (int i = notes.size() - 1; i >= 0; i--) {   // bottom titles stack outwards: the last added goes first
            TextTitle t = new TextTitle(notes.get(i), new Font(Font.SANS_SERIF, Font.PLAIN, 11));
            t.setPaint(TEXT);
            t.setPosition(RectangleEdge.BOTTOM);
            chart.addSubtitle(t);
        }
        LegendTitle legend = chart.getLegend();
        if (legend != null) {
            legend.setPosition(RectangleEdge.BOTTOM);
            legend.setItemFont(new Font(Font.SANS_SERIF, Font.PLAIN, 12));
            legend.setItemPaint(TEXT);
            legend.setFrame(org.jfree.chart.block.BlockBorder.NONE);
        }
        return chart;
    }

    private static ValueAxis axis(String label, boolean log, boolean vertical) {
        ValueAxis a;
        if (log) {
            // Ticks at 1..9 x 10^n, labelled like 2e6; over many decades only the powers of ten are labelled.
            LogarithmicAxis l = new LogarithmicAxis(label.isEmpty() ? null : label);
            l.setStrictValuesFlag(false);
            l.setExpTickLabelsFlag(true);
            // The vertical range is widened to whole decades, so that no point sits on the frame.
            l.setAutoRangeNextLogFlag(vertical);
            a = l;
        } else {
            NumberAxis n = new NumberAxis(label.isEmpty() ? null : label);
            n.setAutoRangeIncludesZero(false);
            a = n;
        }
        a.setLabelFont(new Font(Font.SANS_SERIF, Font.PLAIN, 13));
        a.setTickLabelFont(new Font(Font.SANS_SERIF, Font.PLAIN, 11));
        a.setLabelPaint(TEXT);
        a.setTickLabelPaint(TEXT);
        return a;
    }

    private static void checkPositive(String name, double[] values, String axis) {
        for (int p = 0; p < values.length; p++) {
            double v = values[p];
            if (Double.isFinite(v) && v <= 0) {
                throw new IllegalArgumentException("series \"" + name + "\", point " + p + ": " + axis + " = " + v
                        + " cannot be drawn on a logarithmic " + axis + " axis");
            }
        }
    }

    private static void checkSize(int width, int height) {
        if (width < 1 || height < 1) {
            throw new IllegalArgumentException("chart size " + width + " x " + height + " must be at least 1 x 1");
        }
    }
}
