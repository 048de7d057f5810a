package tactus;

import processing.core.PApplet;
import processing.core.PConstants;
import processing.core.PGraphics;
import tactus.render.ColorBy;
import tactus.render.ColorScale;
import tactus.render.LinkStyle;
import tactus.render.MassStyle;
import tactus.render.ModelDrawer;

/**
 * The paper's generic renderer: draws a whole {@link PhysicalModel} in one call, masses by type as spheres (P3D)
 * or discs (JAVA2D, projected on the x-y plane), interactions by type as lines, optionally shaded by strain.
 * Same calls as the paper's engine, so its sketches draw unchanged:
 *
 * <pre>{@code
 * ModelRenderer renderer = new ModelRenderer(this);
 * renderer.setColor(matModuleType.Mass3D, 180, 100, 0);
 * renderer.setStrainGradient(linkModuleType.SpringDamper3D, true, 0.1f);
 * renderer.setStrainColor(linkModuleType.SpringDamper3D, 255, 0, 0, 255);
 * ...
 * void draw() { background(0); renderer.renderModel(mdl); }
 * }</pre>
 *
 * <p>Differences from the paper's engine, all on purpose: every type can be styled (Mass1D, Ground1D, Osc1D,
 * Mass3DSimple, PosInput3D, PlaneContact3D and Attractor3D could not be); {@code setStrainGradient} honours its
 * boolean; {@link #setScale(float)} scales the drawing; a link with length parameter 0 is coloured without NaN
 * (see {@link LinkStyle#strain(double, double)}); positions come from the model's lock-free snapshot, so drawing
 * never delays the audio or haptic thread. The defaults are the paper engine's (see
 * {@link tactus.render.RenderStyle}). The work is done by a {@link ModelDrawer}, reachable with
 * {@link #getDrawer()} for what this class does not offer (painters that replace how masses, links or arrows are
 * drawn).
 *
 * <p>Beyond the paper's engine: colouring by speed, force or strain with a legend ({@link #colorBy},
 * {@link #drawLegend}), the avatar's force arrow ({@link #setForceArrowScale}, {@link #displayForceArrows}), and,
 * in {@link tactus.render.OrbitCamera}, a mouse camera. The renderer registers a {@code dispose} callback with the
 * sketch: when the sketch ends it forgets the model and draws nothing more.
 */
public class ModelRenderer implements PConstants {
    private final PApplet app;
    private final ModelDrawer drawer = new ModelDrawer();
    private final Callbacks callbacks = new Callbacks();
    private boolean registered;

    /**
     * Creates a renderer for a sketch, with scale 1, zoom (1, 1, 1), masses shown and the default styles, and
     * registers its {@code dispose} callback with the sketch.
     *
     * @param parent the sketch ({@code this}), whose current renderer {@link #renderModel} draws into
     */
    public ModelRenderer(PApplet parent) {
        if (parent == null) {
            throw new IllegalArgumentException("ModelRenderer: the sketch must not be null");
        }
        app = parent;
        parent.registerMethod("dispose", callbacks);
        registered = true;
    }

    /**
     * The method the sketch calls through {@code registerMethod}; public because Processing calls it by
     * reflection. Not for direct use.
     */
    public final class Callbacks {
        private Callbacks() {
        }

        /** Releases the renderer (Processing calls this when the sketch ends). */
        public void dispose() {
            ModelRenderer.this.dispose();
        }
    }

    /**
     * Releases the renderer: unregisters it from the sketch, forgets the model last drawn, and makes
     * {@link #renderModel} do nothing from now on. Safe to call more than once, from the sketch's
     * {@code dispose} or by hand.
     */
    public void dispose() {
        drawer.dispose();
        if (registered) {
            registered = false;
            app.unregisterMethod("dispose", callbacks);
        }
    }

    /** {@return true after {@link #dispose()}} */
    public boolean isDisposed() {
        return drawer.isDisposed();
    }

    /**
     * Colours the model by speed, force or strain on a blue-to-red scale (see {@link ColorBy}), or by type again
     * with {@code ColorBy.TYPE}.
     *
     * @param by what to colour by
     * @param min the value drawn blue (in the unit of {@code by})
     * @param max the value drawn red, &gt; min
     */
    public void colorBy(ColorBy by, float min, float max) {
        drawer.setColorBy(by, ColorScale.heat(min, max));
    }

    /** Draws the legend of the colour scale into the sketch's renderer (see {@link ColorScale#drawLegend}). */
    public void drawLegend(float x, float y, float w, float h, String label) {
        drawer.getColorScale().drawLegend(app.g, x, y, w, h, label);
    }

    /** Turns the force arrows (of haptic avatars, by default) on or off. */
    public void displayForceArrows(boolean cond) {
        drawer.setShowForceArrows(cond);
    }

    /** Sets the force arrows' length per unit of force, in model length units per force unit, &gt; 0. */
    public void setForceArrowScale(float lengthPerForce) {
        drawer.setForceArrowScale(lengthPerForce);
    }

    /**
     * Sets the colour of a mass type.
     *
     * @return false, changing nothing, for {@code matModuleType.UNDEFINED}
     */
    public boolean setColor(matModuleType m, int r, int g, int b) {
        MassStyle s = mass(m);
        if (s == null) {
            return false;
        }
        s.setColor(r, g, b, 255);
        return true;
    }

    /**
     * Sets the base radius of a mass type, in model length units (before scale).
     *
     * @return false, changing nothing, for {@code matModuleType.UNDEFINED}
     */
    public boolean setSize(matModuleType m, float size) {
        MassStyle s = mass(m);
        if (s == null) {
            return false;
        }
        s.setSize(size);
        return true;
    }

    /**
     * Sets how the radius of a mass type grows with inertia: radius = size + scale × mass.
     *
     * @return false, changing nothing, for {@code matModuleType.UNDEFINED}
     */
    public boolean setScaling(matModuleType m, float scale) {
        MassStyle s = mass(m);
        if (s == null) {
            return false;
        }
        s.setScaling(scale);
        return true;
    }

    /** Sets per-axis multipliers applied to every drawn coordinate (not to radii). */
    public void setZoomVector(float x, float y, float z) {
        drawer.setZoom(x, y, z);
    }

    /**
     * Sets the stroke weight, in pixels, of an interaction type.
     *
     * @return false, changing nothing, for {@code linkModuleType.UNDEFINED}
     */
    public boolean setSize(linkModuleType m, int size) {
        LinkStyle s = link(m);
        if (s == null) {
            return false;
        }
        s.setWeight(size);
        return true;
    }

    /**
     * Sets the colour of an interaction type; alpha 0 hides it (unless its strain colour is visible).
     *
     * @return false, changing nothing, for {@code linkModuleType.UNDEFINED}
     */
    public boolean setColor(linkModuleType m, int r, int g, int b, int alpha) {
        LinkStyle s = link(m);
        if (s == null) {
            return false;
        }
        s.setColor(r, g, b, alpha);
        return true;
    }

    /**
     * Turns strain shading of an interaction type on or off. The colour goes from the base colour at strain 0
     * (elongation / length parameter) to the strain colour at strain {@code max}.
     *
     * @param cond true to shade by strain
     * @param max strain of full strain colour, &gt; 0 (the default is 2)
     * @return false, changing nothing, for {@code linkModuleType.UNDEFINED}
     */
    public boolean setStrainGradient(linkModuleType m, boolean cond, float max) {
        LinkStyle s = link(m);
        if (s == null) {
            return false;
        }
        s.setStrainGradient(cond, max);
        return true;
    }

    /**
     * Sets the colour that strained interactions of a type take (transparent black by default).
     *
     * @return false, changing nothing, for {@code linkModuleType.UNDEFINED}
     */
    public boolean setStrainColor(linkModuleType m, int r, int g, int b, int alpha) {
        LinkStyle s = link(m);
        if (s == null) {
            return false;
        }
        s.setStrainColor(r, g, b, alpha);
        return true;
    }

    /** Sets the uniform scale of the drawing (coordinates and radii), &gt; 0; the default is 1. */
    public void setScale(float scale) {
        drawer.setScale(scale);
    }

    /** {@return the uniform scale of the drawing} */
    public float getScale() {
        return drawer.getScale();
    }

    /** Turns drawing of masses on or off (interactions are still drawn). */
    public void displayMats(boolean cond) {
        drawer.setShowMasses(cond);
    }

    /**
     * Draws the model into the sketch's current renderer ({@code g}); call it in {@code draw()}. Like the paper's
     * engine, it leaves the fill of the last mass, and the stroke of the last visible link, set (see
     * {@link ModelDrawer#leaveStyleAsPaperEngine}).
     */
    public void renderModel(PhysicalModel mdl) {
        renderModel(mdl, app.g);
    }

    /**
     * Draws the model into any graphics, for example an off-screen {@code createGraphics()} buffer, between its
     * {@code beginDraw()} and {@code endDraw()}, leaving the same style set as {@link #renderModel(PhysicalModel)}.
     */
    public void renderModel(PhysicalModel mdl, PGraphics target) {
        drawer.draw(mdl, target);
        drawer.leaveStyleAsPaperEngine(target);
    }

    /** {@return the drawer doing the work: its styles, view and replaceable painters} */
    public ModelDrawer getDrawer() {
        return drawer;
    }

    private MassStyle mass(matModuleType m) {
        if (m == null) {
            throw new IllegalArgumentException("ModelRenderer: the mass type must not be null");
        }
        return m == matModuleType.UNDEFINED ? null : drawer.style().mass(m);
    }

    private LinkStyle link(linkModuleType m) {
        if (m == null) {
            throw new IllegalArgumentException("ModelRenderer: the link type must not be null");
        }
        return m == linkModuleType.UNDEFINED ? null : drawer.style().link(m);
    }
}
