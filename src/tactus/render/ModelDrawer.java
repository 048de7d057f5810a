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
 * <p>Colours: by type (the default), or by speed, force or strain through a {@link ColorScale}
 * ({@link #setColorBy}). Force arrows: each mass of a type chosen with {@link #setForceArrow} (by default the
 * haptic avatar, HapticInput3D) gets an arrow along the force of the interactions on it, of length
 * {@code arrowScale × force} in model length units (then scale and zoom), drawn on top of the masses. The model
 * copies velocities and forces of every mass into its snapshot only on request ({@link ModelSnapshot#requestMotion});
 * the drawer asks for them while it needs them, so the first frame after switching to speed or force (or to
 * arrows on other masses than avatars) may show zero values.
 *
 * <p>Use it from one thread (the sketch's animation thread). The painters can be replaced to draw masses, links
 * or arrows differently. After {@link #dispose()} it forgets the model it drew and draws nothing more.
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
    private ColorBy colorBy = ColorBy.TYPE;
    private ColorScale colorScale = ColorScale.heat(0, 1);
    private final boolean[] arrowTypes = new boolean[matModuleType.values().length];
    private ArrowPainter arrowPainter = StandardPainters.arrows();
    private float arrowScale = 1;
    private float arrowWeight = 2;
    private int arrowColor = Colors.argb(200, 0, 160, 255);
    private boolean showArrows = true;
    private boolean disposed;
    private boolean motionRequested;
    /** What the paper engine's renderer would have left set after the last draw (see {@link #leaveStyleAsPaperEngine}). */
    private final Leftovers leftovers = new Leftovers();
    /** What this drawer last asked the model for: interactions (the model's default) or masses only. */
    private boolean linksRequested = true;

    /**
     * Creates a drawer with the default styles, scale 1, zoom (1, 1, 1), colours by type, and force arrows of
     * scale 1 on haptic avatars.
     */
    public ModelDrawer() {
        arrowTypes[matModuleType.HapticInput3D.ordinal()] = true;
    }

    /**
     * Chooses what elements are coloured by, and the scale that maps the values to colours.
     *
     * @param by {@link ColorBy#TYPE} (the default), SPEED, FORCE or STRAIN; not null
     * @param scale the value-to-colour map (its range in the unit of {@code by}); not null; kept, not copied
     */
    public void setColorBy(ColorBy by, ColorScale scale) {
        if (by == null || scale == null) {
            throw new IllegalArgumentException("setColorBy: " + (by == null ? "what to colour by" : "the scale")
                    + " must not be null");
        }
        colorBy = by;
        colorScale = scale;
    }

    /** {@return what elements are coloured by} */
    public ColorBy getColorBy() {
        return colorBy;
    }

    /** {@return the colour scale used unless colouring by type (for a legend)} */
    public ColorScale getColorScale() {
        return colorScale;
    }

    /**
     * Turns the force arrow of every mass of a type on or off (on for HapticInput3D by default).
     *
     * @param type the mass type, not null
     * @param on true to draw its force arrows
     */
    public void setForceArrow(matModuleType type, boolean on) {
        if (type == null) {
            throw new IllegalArgumentException("setForceArrow: the mass type must not be null");
        }
        arrowTypes[type.ordinal()] = on;
    }

    /** {@return true when masses of this type get a force arrow} */
    public boolean hasForceArrow(matModuleType type) {
        return type != null && arrowTypes[type.ordinal()];
    }

    /** Turns every force arrow on or off, keeping the per-type choices. */
    public void setShowForceArrows(boolean show) {
        showArrows = show;
    }

    /** {@return true when force arrows are drawn} */
    public boolean getShowForceArrows() {
        return showArrows;
    }

    /**
     * Sets the arrow length per unit of force, in model length units per force unit (the model's: newtons in
     * REAL_UNITS); finite and &gt; 0, the default 1.
     */
    public void setForceArrowScale(float lengthPerForce) {
        if (!(lengthPerForce > 0) || !Float.isFinite(lengthPerForce)) {
            throw new IllegalArgumentException("setForceArrowScale: the scale must be finite and > 0, got "
                    + lengthPerForce);
        }
        arrowScale = lengthPerForce;
    }

    /** {@return the arrow length per unit of force} */
    public float getForceArrowScale() {
        return arrowScale;
    }

    /** Sets the colour (channels 0..255) and stroke weight (pixels, &ge; 0) of force arrows. */
    public void setForceArrowStyle(int r, int g, int b, int a, float weight) {
        Colors.checkChannels("setForceArrowStyle", r, g, b, a);
        Colors.checkSize("setForceArrowStyle", "weight", weight);
        arrowColor = Colors.argb(r, g, b, a);
        arrowWeight = weight;
    }

    /** {@return the colour of force arrows, packed ARGB} */
    public int getForceArrowColor() {
        return arrowColor;
    }

    /** Replaces the arrow painter (not null); {@link StandardPainters#arrows()} is the default. */
    public void setArrowPainter(ArrowPainter painter) {
        if (painter == null) {
            throw new IllegalArgumentException("setArrowPainter: the painter must not be null");
        }
        arrowPainter = painter;
    }

    /** Forgets the model last drawn (so it can be collected) and makes {@link #draw} do nothing from now on. */
    public void dispose() {
        disposed = true;
        cache.forget();
    }

    /** {@return true after {@link #dispose()}} */
    public boolean isDisposed() {
        return disposed;
    }

    /** {@return the styles, to change in place} */
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

    /** {@return the uniform scale} */
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

    /** {@return the zoom factor on x} */
    public float getZoomX() {
        return zoomX;
    }

    /** {@return the zoom factor on y} */
    public float getZoomY() {
        return zoomY;
    }

    /** {@return the zoom factor on z} */
    public float getZoomZ() {
        return zoomZ;
    }

    /** Turns drawing of masses on or off. */
    public void setShowMasses(boolean show) {
        showMasses = show;
    }

    /** {@return true when masses are drawn} */
    public boolean getShowMasses() {
        return showMasses;
    }

    /** Turns drawing of interactions on or off. */
    public void setShowLinks(boolean show) {
        showLinks = show;
    }

    /** {@return true when interactions are drawn} */
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

    /** {@return how many times inertias and lengths were read from a model under its lock (for tests)} */
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
        leftovers.clear();
        if (disposed) {
            return;
        }
        ModelSnapshot s = cache.sync(model);
        // Velocities and forces of every mass are copied by the model only on request (avatars' forces always).
        if (needsMotion()) {
            if (!s.hasMotion()) {
                s.requestMotion(true);
            }
            motionRequested = true;
        } else if (motionRequested) {
            s.requestMotion(false);
            motionRequested = false;
        }
        // The model copies its interactions only for a reader that draws them.
        if (showLinks != linksRequested) {
            s.requestLinks(showLinks);
            linksRequested = showLinks;
        }
        g.pushStyle();
        try {
            g.colorMode(PConstants.RGB, 255);
            if (showLinks && s.hasLinks()) {
                drawLinks(s, g);
            }
            if (showMasses) {
                drawMasses(s, g);
            }
            if (showArrows) {
                drawArrows(s, g);
            }
        } finally {
            g.popStyle();
        }
    }

    private void drawLinks(ModelSnapshot s, PGraphics g) {
        int n = s.getNumberOfLinks();
        LinkPainter p = linkPainter;
        ColorBy by = colorBy;   // links take every colouring
        ColorScale scaleOf = colorScale;
        p.begin(g, n);
        leftovers.links = n;
        float kx = scale * zoomX;
        float ky = scale * zoomY;
        float kz = scale * zoomZ;
        for (int l = 0; l < n; l++) {
            linkModuleType type = s.getLinkType(l);
            LinkStyle ls = style.link(type);
            if (!ls.isVisible()) {
                continue;
            }
            int a = s.getLinkMat1Idx(l);
            int argb;
            if (by == ColorBy.TYPE) {
                argb = ls.hasStrainGradient()
                        ? ls.colorAt(LinkStyle.strain(s.getLinkElongation(l), cache.restLength(l)))
                        : ls.argb();
            } else {
                double v;
                if (by == ColorBy.STRAIN) {
                    v = LinkStyle.strain(s.getLinkElongation(l), cache.restLength(l));
                } else {
                    int b = cache.planeAxis(l) >= 0 ? a : s.getLinkMat2Idx(l);
                    v = 0.5 * (massValue(s, a, by) + massValue(s, b, by));
                }
                argb = (ls.argb() & 0xFF000000) | (scaleOf.colorAt(v) & 0x00FFFFFF);
            }
            leftovers.link(l, argb, ls.getWeight());
            if ((argb >>> 24) == 0) {
                continue;
            }
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
        // masses take the speed and force colourings; by strain they keep their type colour
        ColorBy by = colorBy == ColorBy.STRAIN ? ColorBy.TYPE : colorBy;
        ColorScale scaleOf = colorScale;
        p.begin(g, n);
        float kx = scale * zoomX;
        float ky = scale * zoomY;
        float kz = scale * zoomZ;
        for (int i = 0; i < n; i++) {
            matModuleType type = s.getMatType(i);
            MassStyle ms = style.mass(type);
            int argb = ms.argb();
            if (by != ColorBy.TYPE && ModelCache.isSimulated(type)) {
                argb = (argb & 0xFF000000) | (scaleOf.colorAt(massValue(s, i, by)) & 0x00FFFFFF);
            }
            leftovers.mass(argb);
            float r = scale * ms.radius(cache.inertia(i));
            if ((argb >>> 24) == 0 || !(r > 0)) {
                continue;
            }
            p.mass(g, i, type, (float) (kx * s.x(i)), (float) (ky * s.y(i)), (float) (kz * s.z(i)), r, argb);
        }
        p.end(g);
    }

    /**
     * Sets on {@code g} the fill, stroke and stroke weight that the paper engine's renderer left set after drawing
     * the model of the last {@link #draw} (which itself restores the target's style): the fill of the last mass in
     * model order and no stroke, when masses are shown; then, when there are links, the stroke colour of the last
     * visible link and a stroke weight of that link's weight if it is the last link, else 1. Some of the paper's
     * sketches draw with what it left (TinyWreckingBall fills its plane with the fixed point's green);
     * {@link tactus.ModelRenderer} calls this after every drawing.
     *
     * @param g the target the last {@link #draw} drew into, not null
     */
    public void leaveStyleAsPaperEngine(PGraphics g) {
        if (g == null) {
            throw new IllegalArgumentException("leaveStyleAsPaperEngine: the target must not be null");
        }
        leftovers.apply(g);
    }

    /** The style the paper engine's renderer leaves set, recorded while drawing (no allocation). */
    private static final class Leftovers {
        private boolean massSeen;
        private int fill;
        private int links;
        private int lastVisible = -1;
        private int stroke;
        private float weight;

        void clear() {
            massSeen = false;
            links = 0;
            lastVisible = -1;
        }

        void mass(int argb) {
            massSeen = true;
            fill = argb;
        }

        void link(int index, int argb, float w) {
            lastVisible = index;
            stroke = argb;
            weight = w;
        }

        void apply(PGraphics g) {
            if (massSeen) {
                g.fill(fill);
                g.noStroke();
            }
            if (lastVisible >= 0) {
                g.stroke(stroke);
            }
            if (links > 0) {
                g.strokeWeight(lastVisible == links - 1 ? weight : 1);
            }
        }
    }

    /** True when this drawer shows velocities or forces of masses other than avatars. */
    private boolean needsMotion() {
        if (colorBy == ColorBy.SPEED || colorBy == ColorBy.FORCE) {
            return true;
        }
        if (showArrows) {
            for (matModuleType t : ARROW_TYPES) {
                if (t != matModuleType.HapticInput3D && arrowTypes[t.ordinal()]) {
                    return true;
                }
            }
        }
        return false;
    }

    private static final matModuleType[] ARROW_TYPES = matModuleType.values();

    /** The speed or force norm of a mass for colouring; 0 for masses that are not simulated. */
    private static double massValue(ModelSnapshot s, int i, ColorBy by) {
        if (!ModelCache.isSimulated(s.getMatType(i))) {
            return 0;
        }
        return by == ColorBy.SPEED ? s.speed(i) : s.forceNorm(i);
    }

    private void drawArrows(ModelSnapshot s, PGraphics g) {
        if ((arrowColor >>> 24) == 0) {
            return;
        }
        int n = s.getNumberOfMats();
        float kx = scale * zoomX;
        float ky = scale * zoomY;
        float kz = scale * zoomZ;
        float k = arrowScale;
        for (int i = 0; i < n; i++) {
            matModuleType type = s.getMatType(i);
            if (!arrowTypes[type.ordinal()]) {
                continue;
            }
            double fx = s.fx(i);
            double fy = s.fy(i);
            double fz = s.fz(i);
            if (!(Double.isFinite(fx) && Double.isFinite(fy) && Double.isFinite(fz)) || fx == 0 && fy == 0 && fz == 0) {
                continue;
            }
            arrowPainter.arrow(g, i, type, (float) (kx * s.x(i)), (float) (ky * s.y(i)), (float) (kz * s.z(i)),
                    (float) (kx * k * fx), (float) (ky * k * fy), (float) (kz * k * fz), arrowWeight, arrowColor);
        }
    }
}
