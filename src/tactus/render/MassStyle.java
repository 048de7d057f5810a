package tactus.render;

/**
 * How one type of mass is drawn: a fill colour and a radius that grows with the mass's inertia,
 * {@code radius = size + scaling × mass}, in model length units before the view's scale.
 * A sphere in a 3D renderer, a disc in a 2D one. Colour channels are 0..255.
 */
public final class MassStyle {
    private int red;
    private int green;
    private int blue;
    private int alpha = 255;
    private float size;
    private float scaling;

    /** Creates an opaque style of colour (r, g, b), base radius {@code size} and no mass scaling. */
    public MassStyle(int r, int g, int b, float size) {
        setColor(r, g, b, 255);
        setSize(size);
    }

    /** Copies another style. */
    public MassStyle(MassStyle other) {
        red = other.red;
        green = other.green;
        blue = other.blue;
        alpha = other.alpha;
        size = other.size;
        scaling = other.scaling;
    }

    /** Sets the fill colour; each channel 0..255, alpha 0 hides the mass. */
    public void setColor(int r, int g, int b, int a) {
        Colors.checkChannels("MassStyle.setColor", r, g, b, a);
        red = r;
        green = g;
        blue = b;
        alpha = a;
    }

    /** Sets the base radius, in model length units, finite and &ge; 0. */
    public void setSize(float size) {
        Colors.checkSize("MassStyle.setSize", "size", size);
        this.size = size;
    }

    /** Sets how much the radius grows per unit of inertia, in length units per mass unit; finite, may be negative. */
    public void setScaling(float scaling) {
        if (!Float.isFinite(scaling)) {
            throw new IllegalArgumentException("MassStyle.setScaling: scaling must be finite, got " + scaling);
        }
        this.scaling = scaling;
    }

    /** {@return the base radius, in model length units} */
    public float getSize() {
        return size;
    }

    /** {@return the radius growth per unit of inertia} */
    public float getScaling() {
        return scaling;
    }

    /** {@return the fill colour as a packed ARGB int ({@code 0xAARRGGBB})} */
    public int argb() {
        return Colors.argb(red, green, blue, alpha);
    }

    /** {@return the radius for a mass of inertia {@code mass}, before the view's scale; never negative} */
    public float radius(double mass) {
        float r = (float) (size + scaling * mass);
        return r > 0 ? r : 0;
    }
}
