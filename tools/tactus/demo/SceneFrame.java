package tactus.demo;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;
import java.io.File;
import java.io.IOException;

import javax.imageio.ImageIO;

import processing.awt.PGraphicsJava2D;
import tactus.PhysicalModel;
import tactus.linkModuleType;
import tactus.matModuleType;
import tactus.render.ModelDrawer;

/**
 * One frame of the plucked-string scene, drawn headless by the library's generic renderer
 * ({@link ModelDrawer}, the engine of {@code ModelRenderer}) into an off-screen JAVA2D {@code PGraphics}: the
 * string's links, its masses, the fixed ends, and the plectrum drawn as its sphere of
 * action. The force on the plectrum (an arrow) and a caption are added afterwards with Java2D. The drawer
 * reads the model's lock-free snapshot, so a frame can be drawn while the audio thread steps the model.
 */
final class SceneFrame {
    /** Width of the frame, pixels. */
    static final int WIDTH = 900;
    /** Height of the frame, pixels. */
    static final int HEIGHT = 420;
    /** Pixels per model unit. */
    static final float SCALE = 260;

    private final PGraphicsJava2D g = new PGraphicsJava2D();
    private final ModelDrawer drawer = new ModelDrawer();
    private BufferedImage image;
    private double forceX;
    private double forceY;
    private String caption = "";

    SceneFrame() {
        g.setPrimary(false);
        g.setSize(WIDTH, HEIGHT);
        drawer.setScale(SCALE);
        drawer.style().mass(matModuleType.Mass2DPlane).setSize(0.012f);
        drawer.style().mass(matModuleType.Mass2DPlane).setScaling(0);
        drawer.style().mass(matModuleType.Mass2DPlane).setColor(250, 210, 120, 255);
        drawer.style().mass(matModuleType.Ground3D).setSize(0.025f);
        drawer.style().mass(matModuleType.Ground3D).setScaling(0);
        drawer.style().mass(matModuleType.HapticInput3D).setSize((float) PluckScene.SPHERE);
        drawer.style().mass(matModuleType.HapticInput3D).setScaling(0);
        drawer.style().mass(matModuleType.HapticInput3D).setColor(230, 60, 60, 150);
        drawer.style().link(linkModuleType.SpringDamper3D).setColor(90, 200, 230, 255);
        drawer.style().link(linkModuleType.SpringDamper3D).setWeight(2);
    }

    /**
     * Draws the model as it is now (from its newest snapshot).
     *
     * @param mdl     the model
     * @param forceX  the device force felt at this moment, x, N (drawn as an arrow on the plectrum)
     * @param forceY  the device force, y, N
     * @param caption a line of text for the frame
     */
    void draw(PhysicalModel mdl, double forceX, double forceY, String caption) {
        g.beginDraw();
        g.background(20, 24, 32);
        g.translate(WIDTH / 2f - SCALE * (float) PluckScene.length() / 2, HEIGHT / 2f);
        drawer.draw(mdl, g);
        g.endDraw();
        g.loadPixels();
        BufferedImage img = new BufferedImage(WIDTH, HEIGHT, BufferedImage.TYPE_INT_RGB);
        img.setRGB(0, 0, WIDTH, HEIGHT, g.pixels, 0, WIDTH);
        image = img;
        this.forceX = forceX;
        this.forceY = forceY;
        this.caption = caption;
    }

    /**
     * Saves the last frame drawn, with the force arrow at the plectrum and the caption.
     *
     * @param file     the PNG file
     * @param plectrumX the plectrum's model x at that frame
     * @param plectrumY the plectrum's model y at that frame
     */
    void save(File file, double plectrumX, double plectrumY) throws IOException {
        BufferedImage img = image;
        Graphics2D g2 = img.createGraphics();
        try {
            g2.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
            g2.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
            float px = WIDTH / 2f + SCALE * (float) (plectrumX - PluckScene.length() / 2);
            float py = HEIGHT / 2f + SCALE * (float) plectrumY;
            // The device force in model directions: the mapping mirrors x, so the model's x is -Fx.
            double pixelsPerNewton = 60;
            float ax = px + (float) (-forceX * pixelsPerNewton);
            float ay = py + (float) (forceY * pixelsPerNewton);
            g2.setColor(new Color(255, 230, 90));
            g2.setStroke(new BasicStroke(3f));
            g2.drawLine(Math.round(px), Math.round(py), Math.round(ax), Math.round(ay));
            double angle = Math.atan2(ay - py, ax - px);
            if (Math.hypot(ax - px, ay - py) > 4) {
                for (int side = -1; side <= 1; side += 2) {
                    double a = angle + Math.PI + side * 0.45;
                    g2.drawLine(Math.round(ax), Math.round(ay), (int) Math.round(ax + 10 * Math.cos(a)),
                            (int) Math.round(ay + 10 * Math.sin(a)));
                }
            }
            g2.setColor(new Color(225, 225, 225));
            g2.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 15));
            g2.drawString("Tactus: the plucked string of the paper, drawn by tactus.render.ModelDrawer "
                    + "(ModelRenderer) off-screen", 14, 24);
            g2.drawString(caption, 14, 46);
            g2.setFont(new Font(Font.SANS_SERIF, Font.PLAIN, 13));
            g2.drawString("red disc: the plectrum (HapticInput3D) and its sphere of action", 14, HEIGHT - 32);
            g2.drawString("yellow arrow: the force felt on the handle (60 px per N)", 14,
                    HEIGHT - 14);
        } finally {
            g2.dispose();
        }
        ImageIO.write(img, "png", file);
    }
}
