package tactus.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.reflect.Modifier;

import org.junit.jupiter.api.Test;

import processing.core.PApplet;
import processing.event.MouseEvent;
import tactus.ModelRenderer;
import tactus.PhysicalModel;
import tactus.Vect3D;

/**
 * The renderer and the camera live through Processing's {@code registerMethod}: Processing calls their callbacks
 * by reflection (which fails silently for a non-public class), here through the sketch's own dispatcher on a
 * sketch that is never started (no display needed).
 */
class LifecycleTest {
    /** A sketch whose event dispatch can be triggered from the test. */
    public static final class Host extends PApplet {
        void fire(String method, Object... args) {
            handleMethods(method, args);
        }
    }

    private static PhysicalModel model() {
        PhysicalModel m = new PhysicalModel(1000, 50);
        m.addGround3D("g", new Vect3D(0, 0, 0));
        m.init();
        return m;
    }

    @Test
    void theCallbackClassesArePublicAsReflectionNeeds() throws Exception {
        for (Class<?> c : new Class<?>[] {ModelRenderer.Callbacks.class, OrbitCamera.Callbacks.class}) {
            assertTrue(Modifier.isPublic(c.getModifiers()), c + " must be public");
        }
        assertTrue(Modifier.isPublic(ModelRenderer.Callbacks.class.getMethod("dispose").getModifiers()));
        assertTrue(Modifier.isPublic(OrbitCamera.Callbacks.class.getMethod("pre").getModifiers()));
        assertTrue(Modifier.isPublic(OrbitCamera.Callbacks.class.getMethod("mouseEvent", MouseEvent.class)
                .getModifiers()));
    }

    @Test
    void whenTheSketchEndsTheRendererForgetsTheModelAndDrawsNothingMore() {
        Host host = new Host();
        ModelRenderer r = new ModelRenderer(host);
        PhysicalModel m = model();
        Canvas c = new Canvas(100, 100);
        r.renderModel(m, c.begin());
        c.end();
        assertFalse(c.allWhite(), "drawn while alive");
        assertFalse(r.isDisposed());

        host.fire("dispose");
        assertTrue(r.isDisposed(), "Processing's dispose reached the renderer");
        c = new Canvas(100, 100);
        r.renderModel(m, c.begin());
        c.end();
        assertTrue(c.allWhite(), "nothing drawn after dispose");
        r.dispose();   // again, by hand: harmless
        host.fire("dispose");
        assertTrue(r.isDisposed());
    }

    @Test
    void theCameraIsAppliedBeforeDrawSteeredByTheMouseAndUnregisteredAtTheEnd() {
        Host host = new Host();
        OrbitCamera cam = new OrbitCamera(host);
        assertTrue(cam.isRegistered());
        Canvas c = new Canvas(120, 120);
        host.g = c.g;
        c.g.beginDraw();
        host.fire("pre");
        // in 2D, pre translated the target (the origin) to the centre
        assertEquals(60, c.g.getMatrix().get(null)[2], 1e-6);
        assertEquals(60, c.g.getMatrix().get(null)[5], 1e-6);
        c.g.endDraw();
        double d = cam.getDistance();
        host.fire("mouseEvent", new MouseEvent(null, 0, MouseEvent.WHEEL, 0, 10, 10, 0, 1));
        assertEquals(1.1 * d, cam.getDistance(), 1e-9, "the wheel event reached the camera");

        host.fire("dispose");
        assertFalse(cam.isRegistered());
        host.fire("mouseEvent", new MouseEvent(null, 0, MouseEvent.WHEEL, 0, 10, 10, 0, 1));
        assertEquals(1.1 * d, cam.getDistance(), 1e-9, "no events after dispose");
        cam.dispose();   // idempotent
    }
}
