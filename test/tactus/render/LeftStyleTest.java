package tactus.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import processing.awt.PGraphicsJava2D;
import processing.core.PApplet;
import tactus.ModelRenderer;
import tactus.PhysicalModel;
import tactus.Vect3D;
import tactus.linkModuleType;

/**
 * The style {@code renderModel} leaves set, as the paper engine's renderer left it: it never restored the fill
 * and stroke, and its TinyWreckingBall fills its plane with what was left (the fixed point's green). Its renderer
 * fills each mass in model order and turns the stroke off, then sets the stroke weight to 1 for every link and,
 * for each visible link, its colour and weight. The expected values below follow those rules.
 */
class LeftStyleTest {
    static final int GROUND_GREEN = Canvas.rgb(0, 220, 130);
    static final int SKETCH_FILL = Canvas.rgb(255, 255, 255);
    static final int SKETCH_STROKE = Canvas.rgb(12, 34, 56);

    /** TinyWreckingBall: three masses on ropes from a fixed point (added last), each over a plane contact. */
    static PhysicalModel wreckingBall() {
        PhysicalModel m = new PhysicalModel(1050, 60);
        m.addMass3D("mass1", 20, new Vect3D(270, 0, 200), new Vect3D(0, 0, 0));
        m.addMass3D("mass2", 1, new Vect3D(180, 0, 200), new Vect3D(0, 0, 0));
        m.addMass3D("mass3", 1, new Vect3D(90, 0, 200), new Vect3D(0, 0, 0));
        m.addGround3D("ground1", new Vect3D(0, 0, 200));
        m.addRope3D("rope1", 90, 0.02, 0.08, "mass1", "mass2");
        m.addRope3D("rope2", 90, 0.02, 0.08, "mass2", "mass3");
        m.addRope3D("rope3", 90, 0.02, 0.08, "mass3", "ground1");
        for (int i = 1; i <= 3; i++) {
            m.addPlaneContact("plane" + i, 50, 0.01, 0.1, 0, -160, "mass" + i);
        }
        m.init();
        return m;
    }

    /** Draws with a sketch style set first, as a sketch's draw() would have it. */
    static PGraphicsJava2D render(ModelRenderer r, PhysicalModel m, Canvas c) {
        PGraphicsJava2D g = c.begin();
        g.fill(SKETCH_FILL);
        g.stroke(SKETCH_STROKE);
        g.strokeWeight(7);
        r.renderModel(m, g);
        return g;
    }

    @Test
    void theWreckingBallsPlaneIsFilledWithTheFixedPointsGreen() {
        ModelRenderer r = new ModelRenderer(new PApplet());
        r.setColor(linkModuleType.Rope3D, 155, 200, 200, 255);
        r.setSize(linkModuleType.Rope3D, 3);
        Canvas c = new Canvas(60, 60);
        PGraphicsJava2D g = render(r, wreckingBall(), c);
        assertEquals(Canvas.hex(GROUND_GREEN), Canvas.hex(g.fillColor), "the fill of the last mass, ground1");
        assertTrue(g.fill);
        assertTrue(g.stroke, "a visible link turned the stroke back on");
        assertEquals(Canvas.hex(Canvas.rgb(155, 200, 200)), Canvas.hex(g.strokeColor), "the last visible link, rope3");
        assertEquals(1f, g.strokeWeight, 0f, "the plane contacts after it are hidden: weight 1");
        c.end();
    }

    @Test
    void aVisibleLastLinkLeavesItsWeight() {
        PhysicalModel m = new PhysicalModel(1050, 60);
        m.addGround3D("g", new Vect3D(0, 0, 0));
        m.addMass3D("a", 1, new Vect3D(10, 0, 0), new Vect3D(0, 0, 0));
        m.addSpringDamper3D("s", 10, 0.01, 0.001, "g", "a");
        m.init();
        ModelRenderer r = new ModelRenderer(new PApplet());
        r.setColor(tactus.matModuleType.Mass3D, 10, 20, 30);
        r.setSize(linkModuleType.SpringDamper3D, 4);
        Canvas c = new Canvas(60, 60);
        PGraphicsJava2D g = render(r, m, c);
        assertEquals(Canvas.hex(Canvas.rgb(10, 20, 30)), Canvas.hex(g.fillColor), "the last mass is the Mass3D");
        assertEquals(Canvas.hex(Canvas.rgb(30, 250, 250)), Canvas.hex(g.strokeColor), "SpringDamper3D's colour");
        assertEquals(4f, g.strokeWeight, 0f);
        c.end();
    }

    @Test
    void withoutAVisibleLinkTheStrokeStaysOffAndWithoutMassesTheFillIsTheSketchs() {
        PhysicalModel m = new PhysicalModel(1050, 60);
        m.addGround3D("g", new Vect3D(0, 0, 0));
        m.addMass3D("a", 1, new Vect3D(10, 0, 0), new Vect3D(0, 0, 0));
        m.addContact3D("c", 1, 0.01, 0.001, "g", "a");   // contacts are hidden by default
        m.init();
        ModelRenderer r = new ModelRenderer(new PApplet());
        Canvas c = new Canvas(60, 60);
        PGraphicsJava2D g = render(r, m, c);
        assertFalse(g.stroke, "the masses turned the stroke off and no link turned it on");
        assertEquals(1f, g.strokeWeight, 0f);
        c.end();

        r.displayMats(false);
        g = render(r, m, c);
        assertEquals(Canvas.hex(SKETCH_FILL), Canvas.hex(g.fillColor), "no mass drawn: the sketch's fill");
        assertTrue(g.stroke);
        assertEquals(Canvas.hex(SKETCH_STROKE), Canvas.hex(g.strokeColor), "no link drawn: the sketch's stroke");
        assertEquals(1f, g.strokeWeight, 0f, "a link, even hidden, set the weight to 1");
        c.end();
    }
}
