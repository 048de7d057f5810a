package tactus.render;

import processing.core.PApplet;
import tactus.ModelRenderer;
import tactus.PhysicalModel;
import tactus.Vect3D;

/**
 * A P3D sketch run in a child JVM under Xvfb by {@link P3DRenderTest}: an {@link OrbitCamera} turned 90° about
 * the vertical (the eye on +x, so world -z is screen right), masses coloured by speed, and the avatar's force
 * arrow. It saves the third frame to the PNG named by its first argument and exits.
 */
public class P3DCameraSketch extends PApplet {
    static final int SIZE = 240;
    /** The avatar's spring: zero length, this stiffness, to a fixed point 80 units along -z. */
    static final double K = 0.002;
    private PhysicalModel mdl;
    private ModelRenderer renderer;
    private String out;

    static PhysicalModel model() {
        PhysicalModel m = new PhysicalModel(1000, 50);
        m.addMass3D("still", 1, new Vect3D(0, 0, -50), new Vect3D());
        m.addMass3D("fast", 1, new Vect3D(0, 0, 50), new Vect3D(0, 0, 10));   // along the view: stays in place
        m.addHapticInput3D("hand", new Vect3D(0, 60, 0), 1);
        m.addGround3D("anchor", new Vect3D(0, 60, -80));
        m.addSpring3D("pull", 0, K, "anchor", "hand");
        m.init();
        m.getSnapshot().requestMotion(true);   // the renderer would ask on its first frame; this sketch never steps
        m.computeNSteps(10);
        return m;
    }

    @Override
    public void settings() {
        size(SIZE, SIZE, P3D);
    }

    @Override
    public void setup() {
        out = args != null && args.length > 0 ? args[0] : "camera.png";
        mdl = model();
        OrbitCamera cam = new OrbitCamera(this);
        cam.setRotation(HALF_PI, 0);
        renderer = new ModelRenderer(this);
        renderer.getDrawer().setShowLinks(false);
        renderer.colorBy(ColorBy.SPEED, 0, 10);
        renderer.getDrawer().setForceArrowStyle(0, 0, 255, 255, 3);
        renderer.setForceArrowScale((float) (60 / (K * 80)));   // 60 units long
    }

    @Override
    public void draw() {
        background(255);
        renderer.renderModel(mdl);   // no translate(): the camera centres its target (the origin)
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
        PApplet.main(P3DCameraSketch.class.getName(), a);
    }
}
