package tactus.render;

import processing.core.PApplet;
import tactus.ModelRenderer;
import tactus.PhysicalModel;
import tactus.Vect3D;
import tactus.linkModuleType;
import tactus.matModuleType;

/**
 * A P3D sketch run in a child JVM under Xvfb by {@link P3DRenderTest}: it draws a small model with
 * {@link ModelRenderer} in the sketch's own P3D renderer, saves the third frame to the PNG named by its first
 * argument, and exits. The model is built by {@link #model()}, so the test knows where everything is.
 */
public class P3DSketch extends PApplet {
    static final int SIZE = 240;
    private PhysicalModel mdl;
    private ModelRenderer renderer;
    private String out;

    /** Masses at z = 0 (drawn where the 2D mapping says) and one at z = 50 (drawn in perspective). */
    static PhysicalModel model() {
        PhysicalModel m = new PhysicalModel(1000, 50);
        m.addMass3D("left", 1, new Vect3D(-60, -40, 0), new Vect3D(0, 0, 0));
        m.addGround3D("right", new Vect3D(60, -40, 0));
        m.addSpringDamper3D("top", 120, 0.01, 0.001, "left", "right");
        m.addGround3D("near", new Vect3D(60, 40, 50));
        m.init();
        return m;
    }

    @Override
    public void settings() {
        size(SIZE, SIZE, P3D);
    }

    @Override
    public void setup() {
        out = args != null && args.length > 0 ? args[0] : "p3d.png";
        mdl = model();
        renderer = new ModelRenderer(this);
        renderer.setSize(linkModuleType.SpringDamper3D, 4);
        renderer.setColor(matModuleType.Ground3D, 0, 0, 255);
    }

    @Override
    public void draw() {
        background(255);
        translate(width / 2f, height / 2f);
        renderer.renderModel(mdl);
        if (frameCount == 3) {
            save(out);
            exit();
        }
    }

    /**
     * Runs the sketch.
     *
     * @param a the PNG path
     */
    public static void main(String[] a) {
        PApplet.main(P3DSketch.class.getName(), a);
    }
}
