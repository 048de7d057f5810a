package tactus.render;

import processing.core.PConstants;
import processing.core.PGraphics;
import tactus.ModelSnapshot;
import tactus.PhysicalModel;
import tactus.linkModuleType;
import tactus.matModuleType;

/**
 * The generic model renderer: draws any {@link PhysicalModel} into any {@code PGraphics}, 3D (P3D: spheres and 3D
 * lines) or 2D (JAVA2D, P2D: discs and lines, the model's x-y plane projected orthographically; z is ignored).
 *
 * <p>Masses and interactions are drawn by type, with the {@link RenderStyle} of their type; interactions can be
 * shaded by strain. A mass of inertia m is drawn with radius {@code scale × (size + scaling × m)}; a point p of the
 * model is drawn at {@code scale × (zoom.x p.x, zoom.y p.y, zoom.z p.z)} in the target's current coordinate system,
 * so the sketch's own {@code translate()}, {@code rotate()} and camera apply. Links are drawn first, then masses on
 * top. A plane contact is drawn from its mass to the mass's foot on the plane. Nothing else is drawn: no
 * background, no plane, no lights.
 *
 * <p>Positions come only from {@link PhysicalModel#getSnapshot()}, so drawing never waits for a thread that steps
 * the model. Inertias and length parameters, which the snapshot does not carry, are read under the model's lock
 * once, and again only when the snapshot's topology changes; call {@link #refresh()} after changing masses or
 * lengths of an unchanged topology. Once the first frame of a topology is drawn, drawing allocates nothing. Before
 * the model's {@code init()} its snapshot is empty and nothing is drawn.
 *
 * <p>Use it from one thread (the sketch's animation thread). The painters can be replaced to draw masses or links
 * differently.
 */
public final class ModelDrawer {
    private final RenderStyle style = new RenderStyle();
    private final ModelCache cache = new ModelCache();
    private MassPainter massPainter = StandardPainters.masses();
    private LinkPainter linkPainter = StandardPainters.links();
    private float scale = 1;
    private float zoomX = 1;
    private float zoomY = 1;
    private float zoomZ = 1;
    private boolean showMasses = true;
    private boolean showLinks = true;

    /** Creates a drawer with the default styles, scale 1 and zoom (1, 1, 1). */
    public ModelDrawer() {
    }

    /** @return the styles, to change in place. */
    public RenderStyle style() {
        return style;
    }

    /** Sets the uniform scale applied to every drawn coordinate and radius; finite and &gt; 0. */
    public void setScale(float scale) {
        if (!(scale > 0) || !Float.isFinite(scale)) {
            throw new IllegalArgumentException("setScale: scale must be finite and > 0, got " + scale);
        }
        this.scale = scale;
    }

    /** @return the uniform scale. */
    public float getScale() {
        return scale;
    }

    /** Sets the per-axis multipliers applied to every drawn coordinate (not to radii); each finite. */
    public void setZoom(float x, float y, float z) {
        if (!Float.isFinite(x) || !Float.isFinite(y) || !Float.isFinite(z)) {
            throw new IllegalArgumentException("setZoomVector: each factor must be finite, got (" + x + ", " + y
                    + ", " + z + ")");
        }
        zoomX = x;
        zoomY = y;
        zoomZ = z;
    }

    /** @return the zoom factor on x. */
    public float getZoomX() {
        return zoomX;
    }

    /** @return the zoom factor on y. */
    public float getZoomY() {
        return zoomY;
    }

    /** @return the zoom factor on z. */
    public float getZoomZ() {
        return zoomZ;
    }

    /** Turns drawing of masses on or off. */
    public void setShowMasses(boolean show) {
        showMasses = show;
    }

    /** @return true when masses are drawn. */
    public boolean getShowMasses() {
        return showMasses;
    }

    /** Turns drawing of interactions on or off. */
    public void setShowLinks(boolean show) {
        showLinks = show;
    }

    /** @return true when interactions are drawn. */
    public boolean getShowLinks() {
        return showLinks;
    }

    /** Replaces the mass painter (not null); {@link StandardPainters#masses()} is the default. */
    public void setMassPainter(MassPainter painter) {
        if (painter == null) {
            throw new IllegalArgumentException("setMassPainter: the painter must not be null");
        }
        massPainter = painter;
    }

    /** Replaces the link painter (not null); {@link StandardPainters#links()} is the default. */
    public void setLinkPainter(LinkPainter painter) {
        if (painter == null) {
            throw new IllegalArgumentException("setLinkPainter: the painter must not be null");
        }
        linkPainter = painter;
    }

    /** Makes the next frame re-read inertias, length parameters and plane parameters from the model. */
    public void refresh() {
        cache.invalidate();
    }

    /** @return how many times inertias and lengths were read from a model under its lock (for tests). */
    int cacheRefreshes() {
        return cache.refreshes();
    }

    /**
     * Draws the newest snapshot of a model into a target that is between {@code beginDraw()} and {@code endDraw()}
     * (a sketch's {@code g} inside {@code draw()} always is). The target's style is saved and restored; its sphere
     * detail is left as set for the model's size, as the paper's engine did.
     *
     * @param model the model, not null
     * @param g the target, not null
     */
    public void draw(PhysicalModel model, PGraphics g) {
        if (model == null || g == null) {
            throw new IllegalArgumentException("draw: " + (model == null ? "the model" : "the target")
                    + " must not be null");
        }
        ModelSnapshot s = cache.sync(model);
        g.pushStyle();
        try {
            g.colorMode(PConstants.RGB, 255);
            if (showLinks) {
                drawLinks(s, g);
            }
            if (showMasses) {
                drawMasses(s, g);
            }
        } finally {
            g.popStyle();
        }
    }

    private void drawLinks(ModelSnapshot s, PGraphics g) {
        int n = s.getNumberOfLinks();
        LinkPainter p = linkPainter;
        p.begin(g, n);
        float kx = scale * zoomX;
        float ky = scale * zoomY;
        float kz = scale * zoomZ;
        for (int l = 0; l < n; l++) {
            linkModuleType type = s.getLinkType(l);
            LinkStyle ls = style.link(type);
            if (!ls.isVisible()) {
                continue;
            }
            int argb = ls.hasStrainGradient()
                    ? ls.colorAt(LinkStyle.strain(s.getLinkElongation(l), cache.restLength(l)))
                    : ls.argb();
            if ((argb >>> 24) == 0) {
                continue;
            }
            int a = s.getLinkMat1Idx(l);
            double x1 = s.x(a);
            double y1 = s.y(a);
            double z1 = s.z(a);
            double x2;
            double y2;
            double z2;
            int axis = cache.planeAxis(l);
            if (axis >= 0) {
                // The foot of the mass on the plane.
                double plane = cache.planePosition(l);
                x2 = axis == 0 ? plane : x1;
                y2 = axis == 1 ? plane : y1;
                z2 = axis == 2 ? plane : z1;
            } else {
                int b = s.getLinkMat2Idx(l);
                x2 = s.x(b);
                y2 = s.y(b);
                z2 = s.z(b);
            }
            p.link(g, l, type, (float) (kx * x1), (float) (ky * y1), (float) (kz * z1),
                    (float) (kx * x2), (float) (ky * y2), (float) (kz * z2), ls.getWeight(), argb);
        }
        p.end(g);
    }

    private void drawMasses(ModelSnapshot s, PGraphics g) {
        int n = s.getNumberOfMats();
        MassPainter p = massPainter;
        p.begin(g, n);
        float kx = scale * zoomX;
        float ky = scale * zoomY;
        float kz = scale * zoomZ;
        for (int i = 0; i < n; i++) {
            matModuleType type = s.getMatType(i);
            MassStyle ms = style.mass(type);
            int argb = ms.argb();
            float r = scale * ms.radius(cache.inertia(i));
            if ((argb >>> 24) == 0 || !(r > 0)) {
                continue;
            }
            p.mass(g, i, type, (float) (kx * s.x(i)), (float) (ky * s.y(i)), (float) (kz * s.z(i)), r, argb);
        }
        p.end(g);
    }
}
