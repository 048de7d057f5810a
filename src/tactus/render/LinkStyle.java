package tactus.render;

/**
 * How one type of interaction is drawn: a line of a given stroke weight (pixels) and colour, optionally shaded
 * by strain. With the strain gradient on, the colour goes linearly from the base colour at strain 0 to the strain
 * colour at strain {@code strainMax}, channel by channel (alpha too); compressed links (strain &lt; 0) keep the base
 * colour and links strained beyond the maximum take the strain colour. Strain is elongation divided by the
 * interaction's length parameter (see {@link #strain(double, double)}). Colour channels are 0..255; a link whose
 * resulting alpha is 0 is not drawn.
 */
public final class LinkStyle {
    private int base;
    private int strainColor;
    private float weight;
    private boolean gradient;
    private float strainMax = 2;

    /** Creates a style of colour (r, g, b, a) and stroke weight {@code weight}, without strain gradient. */
    public LinkStyle(int r, int g, int b, int a, float weight) {
        setColor(r, g, b, a);
        setWeight(weight);
    }

    /** Copies another style. */
    public LinkStyle(LinkStyle other) {
        base = other.base;
        strainColor = other.strainColor;
        weight = other.weight;
        gradient = other.gradient;
        strainMax = other.strainMax;
    }

    /** Sets the base colour; channels 0..255. */
    public void setColor(int r, int g, int b, int a) {
        Colors.checkChannels("LinkStyle.setColor", r, g, b, a);
        base = Colors.argb(r, g, b, a);
    }

    /** Sets the colour reached at strain {@code strainMax}; channels 0..255. */
    public void setStrainColor(int r, int g, int b, int a) {
        Colors.checkChannels("LinkStyle.setStrainColor", r, g, b, a);
        strainColor = Colors.argb(r, g, b, a);
    }

    /** Sets the stroke weight, in pixels, finite and &ge; 0. */
    public void setWeight(float weight) {
        Colors.checkSize("LinkStyle.setWeight", "weight", weight);
        this.weight = weight;
    }

    /**
     * Turns the strain gradient on or off and sets the strain at which the strain colour is fully reached.
     *
     * @param on true to shade by strain
     * @param max the strain (dimensionless) of full strain colour, finite and &gt; 0
     */
    public void setStrainGradient(boolean on, float max) {
        if (!(max > 0) || !Float.isFinite(max)) {
            throw new IllegalArgumentException("LinkStyle.setStrainGradient: max must be finite and > 0, got " + max);
        }
        gradient = on;
        strainMax = max;
    }

    /** {@return the stroke weight, in pixels} */
    public float getWeight() {
        return weight;
    }

    /** {@return true when the link is shaded by strain} */
    public boolean hasStrainGradient() {
        return gradient;
    }

    /** {@return the strain of full strain colour} */
    public float getStrainMax() {
        return strainMax;
    }

    /** {@return the base colour as packed ARGB} */
    public int argb() {
        return base;
    }

    /** {@return the strain colour as packed ARGB} */
    public int strainArgb() {
        return strainColor;
    }

    /** {@return false when nothing of this type can ever be visible (every colour it may take has alpha 0)} */
    public boolean isVisible() {
        return (base >>> 24) != 0 || (gradient && (strainColor >>> 24) != 0);
    }

    /**
     * Returns the colour for a given strain: the base colour without gradient, else the blend described above.
     * {@code NaN} counts as no strain.
     *
     * @param strain elongation over length parameter (dimensionless)
     * @return packed ARGB
     */
    public int colorAt(double strain) {
        if (!gradient || !(strain > 0)) {
            return base;
        }
        if (strain >= strainMax) {
            return strainColor;
        }
        return Colors.lerp(base, strainColor, (float) (strain / strainMax));
    }

    /**
     * Strain of an interaction: {@code elongation / restLength}. A length parameter of 0 (a zero-length spring, a
     * damper, a contact with threshold 0) has no relative scale: any stretch counts as infinite strain, and no
     * stretch as none, so the result is never {@code NaN}.
     *
     * @param elongation distance minus length parameter, in length units
     * @param restLength the length parameter, in length units
     * @return the strain; {@code +Infinity} for a stretched zero-length link, 0 for a non-finite elongation
     */
    public static double strain(double elongation, double restLength) {
        if (!Double.isFinite(elongation)) {
            return 0;
        }
        double l = Math.abs(restLength);
        if (l > 0 && Double.isFinite(l)) {
            return elongation / l;
        }
        return elongation > 0 ? Double.POSITIVE_INFINITY : 0;
    }
}
