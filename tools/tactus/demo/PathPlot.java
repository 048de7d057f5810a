package tactus.demo;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.geom.Line2D;
import java.awt.image.BufferedImage;
import java.io.File;
import java.io.IOException;
import java.util.Locale;

import javax.imageio.ImageIO;

/**
 * The hand path of the demo with the force felt along it, drawn with Java2D: the handle's path in the
 * device plane (centimetres; x increases to the left, as the user sees the device, so that the picture
 * matches the scene), coloured by the magnitude of the force sent to the device, with arrows of that force;
 * the string at rest; and, below, the force magnitude over time with the phases of the script.
 */
final class PathPlot {
    static final int WIDTH = 900;
    static final int HEIGHT = 760;

    private PathPlot() {
    }

    /**
     * @param file     the PNG file
     * @param t        tick times, seconds
     * @param hx       handle x, metres
     * @param hy       handle y, metres
     * @param fx       device force x, N
     * @param fy       device force y, N
     * @param n        number of ticks
     * @param mapping  the device mapping (for the string's position)
     * @param phaseT   start times of the script's phases (seconds, on the same clock as {@code t})
     * @param phases   names of the phases
     */
    static void save(File file, double[] t, double[] hx, double[] hy, double[] fx, double[] fy, int n,
                     DeviceMapping mapping, double[] phaseT, String[] phases) throws IOException {
        BufferedImage img = new BufferedImage(WIDTH, HEIGHT, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = img.createGraphics();
        try {
            g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
            g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
            g.setColor(Color.WHITE);
            g.fillRect(0, 0, WIDTH, HEIGHT);
            double fMax = 1e-9;
            for (int i = 0; i < n; i++) {
                fMax = Math.max(fMax, Math.hypot(fx[i], fy[i]));
            }
            drawPlane(g, hx, hy, fx, fy, n, mapping, fMax);
            drawForceOverTime(g, t, fx, fy, n, fMax, phaseT, phases);
        } finally {
            g.dispose();
        }
        ImageIO.write(img, "png", file);
    }

    private static Color heat(double f) {
        double u = Math.max(0, Math.min(1, f));
        return new Color((int) Math.round(40 + 215 * u), (int) Math.round(90 + 40 * (1 - u)),
                (int) Math.round(220 * (1 - u) + 20));
    }

    private static void drawPlane(Graphics2D g, double[] hx, double[] hy, double[] fx, double[] fy, int n,
                                  DeviceMapping mapping, double fMax) {
        // the region: the string's length plus a margin; y over the path
        double x0 = mapping.deviceX(PluckScene.length() + 0.1);
        double x1 = mapping.deviceX(-0.1);
        double y0 = Double.POSITIVE_INFINITY;
        double y1 = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < n; i++) {
            if (Double.isFinite(hy[i])) {
                y0 = Math.min(y0, hy[i]);
                y1 = Math.max(y1, hy[i]);
            }
        }
        if (!(y1 > y0)) {
            y0 = DeviceMapping.STRING_Y - 0.03;
            y1 = DeviceMapping.STRING_Y + 0.03;
        }
        final double yLow = y0 - 0.005;
        final double yHigh = y1 + 0.005;
        int left = 80;
        int top = 60;
        int w = WIDTH - 140;
        double scale = Math.min(w / (x1 - x0), 400 / (yHigh - yLow));   // pixels per metre
        w = (int) Math.round((x1 - x0) * scale);
        int h = (int) Math.round((yHigh - yLow) * scale);
        // x increases to the left (the user's view, as in the scene)
        java.util.function.DoubleUnaryOperator px = x -> left + (x1 - x) * scale;
        java.util.function.DoubleUnaryOperator py = y -> top + (y - yLow) * scale;

        g.setColor(Color.BLACK);
        g.setFont(new Font(Font.SANS_SERIF, Font.BOLD, 15));
        g.drawString("The hand's path (emulated Haply handle, measured through its encoders) and the force felt", left,
                24);
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 12));
        g.drawString("colour: |force| sent to the device (blue 0 N, red " + String.format(Locale.ROOT, "%.2f", fMax)
                + " N); arrows: the force every 10 ms while touching; grey: the string at rest", left, 42);
        g.setColor(new Color(245, 245, 245));
        g.fillRect(left, top, w, h);
        g.setColor(Color.GRAY);
        g.drawRect(left, top, w, h);
        // axes, every centimetre
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 11));
        for (int cm = (int) Math.ceil(x0 * 100); cm <= Math.floor(x1 * 100); cm++) {
            int X = (int) Math.round(px.applyAsDouble(cm / 100.0));
            g.setColor(new Color(225, 225, 225));
            g.drawLine(X, top, X, top + h);
            g.setColor(Color.DARK_GRAY);
            g.drawString(Integer.toString(cm), X - 5, top + h + 14);
        }
        for (int cm = (int) Math.ceil(yLow * 100); cm <= Math.floor(yHigh * 100); cm++) {
            int Y = (int) Math.round(py.applyAsDouble(cm / 100.0));
            g.setColor(new Color(225, 225, 225));
            g.drawLine(left, Y, left + w, Y);
            g.setColor(Color.DARK_GRAY);
            g.drawString(Integer.toString(cm), left - 22, Y + 4);
        }
        g.drawString("handle x (cm, increasing to the left as the user sees the device)", left + w / 2 - 170,
                top + h + 30);
        g.drawString("y (cm)", left - 60, top + h / 2);
        // the string at rest
        g.setColor(new Color(150, 150, 150));
        g.setStroke(new BasicStroke(4f));
        double sy = py.applyAsDouble(DeviceMapping.STRING_Y);
        g.draw(new Line2D.Double(px.applyAsDouble(mapping.deviceX(0)), sy,
                px.applyAsDouble(mapping.deviceX(PluckScene.length())), sy));
        // the path, coloured by force
        g.setStroke(new BasicStroke(2.5f, BasicStroke.CAP_ROUND, BasicStroke.JOIN_ROUND));
        for (int i = 1; i < n; i++) {
            if (!Double.isFinite(hx[i - 1]) || !Double.isFinite(hx[i])) {
                continue;
            }
            g.setColor(heat(Math.hypot(fx[i], fy[i]) / fMax));
            g.draw(new Line2D.Double(px.applyAsDouble(hx[i - 1]), py.applyAsDouble(hy[i - 1]),
                    px.applyAsDouble(hx[i]), py.applyAsDouble(hy[i])));
        }
        // force arrows: 70 pixels for the largest force
        g.setStroke(new BasicStroke(1.8f));
        double arrow = 70 / fMax;
        for (int i = 0; i < n; i += 10) {
            double f = Math.hypot(fx[i], fy[i]);
            if (!Double.isFinite(hx[i]) || f < 0.02 * fMax) {
                continue;
            }
            double ax = px.applyAsDouble(hx[i]);
            double ay = py.applyAsDouble(hy[i]);
            // x is drawn increasing to the left, so a force towards +x points left
            double bx = ax - fx[i] * arrow;
            double by = ay + fy[i] * arrow;
            g.setColor(heat(f / fMax).darker());
            g.draw(new Line2D.Double(ax, ay, bx, by));
        }
        // colour bar
        for (int k = 0; k < 100; k++) {
            g.setColor(heat(k / 99.0));
            g.fillRect(left + w + 20, top + h - (k + 1) * h / 100, 14, Math.max(1, h / 100 + 1));
        }
        g.setColor(Color.DARK_GRAY);
        g.drawString("0 N", left + w + 18, top + h + 14);
        g.drawString(String.format(Locale.ROOT, "%.2f N", fMax), left + w + 6, top - 4);
    }

    private static void drawForceOverTime(Graphics2D g, double[] t, double[] fx, double[] fy, int n, double fMax,
                                          double[] phaseT, String[] phases) {
        int left = 80;
        int top = HEIGHT - 250;
        int w = WIDTH - 140;
        int h = 190;
        double tEnd = n > 0 ? t[n - 1] : 1;
        java.util.function.DoubleUnaryOperator px = x -> left + x / tEnd * w;
        java.util.function.DoubleUnaryOperator py = f -> top + h - f / fMax * (h - 10);
        g.setColor(Color.BLACK);
        g.setFont(new Font(Font.SANS_SERIF, Font.BOLD, 13));
        g.drawString("|force| on the handle over time (one point per haptic tick, 1 kHz)", left, top - 10);
        g.setColor(new Color(245, 245, 245));
        g.fillRect(left, top, w, h);
        g.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 11));
        for (int p = 0; p < phaseT.length; p++) {
            int X = (int) Math.round(px.applyAsDouble(phaseT[p]));
            g.setColor(new Color(200, 200, 200));
            g.drawLine(X, top, X, top + h);
            g.setColor(Color.DARK_GRAY);
            g.drawString(phases[p], X + 2, top + 12 + 12 * (p % 2));
        }
        for (double s = 0; s <= tEnd; s += 0.5) {
            int X = (int) Math.round(px.applyAsDouble(s));
            g.drawString(String.format(Locale.ROOT, "%.1f", s), X - 8, top + h + 14);
        }
        g.drawString("time (s)", left + w / 2 - 20, top + h + 30);
        g.drawString(String.format(Locale.ROOT, "%.2f N", fMax), left - 50, top + 14);
        g.drawString("0", left - 14, top + h);
        g.setColor(new Color(200, 40, 40));
        g.setStroke(new BasicStroke(1.4f));
        for (int i = 1; i < n; i++) {
            g.draw(new Line2D.Double(px.applyAsDouble(t[i - 1]), py.applyAsDouble(Math.hypot(fx[i - 1], fy[i - 1])),
                    px.applyAsDouble(t[i]), py.applyAsDouble(Math.hypot(fx[i], fy[i]))));
        }
        g.setColor(Color.GRAY);
        g.drawRect(left, top, w, h);
    }
}
