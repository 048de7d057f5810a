package tactus.render;

import processing.awt.PGraphicsJava2D;

/** An off-screen JAVA2D target for tests: white, with the origin moved to the centre, pixels read back as ARGB. */
final class Canvas {
    static final int WHITE = 0xFFFFFFFF;
    final int width;
    final int height;
    final PGraphicsJava2D g;
    private int[] pixels;

    Canvas(int width, int height) {
        this.width = width;
        this.height = height;
        g = new PGraphicsJava2D();
        g.setPrimary(false);
        g.setSize(width, height);
    }

    /** Starts a frame: white background, origin at the centre. */
    PGraphicsJava2D begin() {
        g.beginDraw();
        g.background(255);
        g.translate(width / 2f, height / 2f);
        return g;
    }

    /** Ends the frame and reads the pixels back. */
    void end() {
        g.endDraw();
        g.loadPixels();
        pixels = g.pixels.clone();
    }

    /** @return the ARGB pixel whose square contains the drawing point (cx + x, cy + y) of the centred frame. */
    int at(double x, double y) {
        int px = (int) Math.floor(width / 2.0 + x);
        int py = (int) Math.floor(height / 2.0 + y);
        return pixels[py * width + px];
    }

    boolean allWhite() {
        for (int p : pixels) {
            if (p != WHITE) {
                return false;
            }
        }
        return true;
    }

    static int rgb(int r, int g, int b) {
        return 0xFF000000 | (r << 16) | (g << 8) | b;
    }

    static String hex(int argb) {
        return String.format("#%08X", argb);
    }
}
