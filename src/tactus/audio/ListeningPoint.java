package tactus.audio;

/**
 * One signal that a {@link PhyUGen} hears: a mass's displacement along an axis (from where it was when the
 * point was added), or an interaction's elongation or tension, each scaled by a gain and placed in the
 * stereo field by an equal-power pan. Gain and pan may be changed from any thread; the audio thread sees
 * both change together. A point whose element has left the model outputs 0 ({@link #isSilent()}) and sounds
 * again once an element of that name is back.
 */
public final class ListeningPoint {
    /** What a listening point reads. */
    public enum Kind {
        /** A mass's displacement along one axis, in model units. */
        MASS_DISPLACEMENT,
        /** An interaction's elongation (distance minus its length parameter), in model units. */
        LINK_ELONGATION,
        /** An interaction's tension, K e + Z de/dt (REAL_UNITS: N). */
        LINK_TENSION
    }

    /** Gains of one setting, replaced as a whole so the audio thread never sees half a change. */
    static final class Gains {
        final double gain;
        final double pan;
        final double left;
        final double right;

        Gains(double gain, double pan) {
            this.gain = gain;
            this.pan = pan;
            double angle = (pan + 1) * Math.PI / 4;
            this.left = gain * Math.cos(angle);
            this.right = gain * Math.sin(angle);
        }
    }

    private final Kind kind;
    private final String element;
    private final int axis;
    private volatile Gains gains;
    // resolved against one SteppedModel by PhyUGen, outside the audio path
    SteppedModel boundTo;
    int handle;
    double origin;
    /** True while the element cannot be read (it left the model); written by the audio thread only. */
    private volatile boolean silent;

    ListeningPoint(Kind kind, String element, int axis, double gain, double pan) {
        this.kind = kind;
        this.element = element;
        this.axis = axis;
        this.gains = checkedGains(gain, pan);
    }

    private Gains checkedGains(double gain, double pan) {
        if (!Double.isFinite(gain)) {
            throw new IllegalArgumentException("listening point \"" + element + "\": gain must be finite, got " + gain);
        }
        if (!(pan >= -1 && pan <= 1)) {
            throw new IllegalArgumentException("listening point \"" + element + "\": pan must be in [-1, 1], got " + pan);
        }
        return new Gains(gain, pan);
    }

    /** {@return what this point reads} */
    public Kind kind() {
        return kind;
    }

    /** {@return the name of the mass or interaction it reads} */
    public String element() {
        return element;
    }

    /** {@return the axis (0 = x, 1 = y, 2 = z) of a displacement point, -1 for interactions} */
    public int axis() {
        return axis;
    }

    /** {@return the gain (output units per model unit)} */
    public double gain() {
        return gains.gain;
    }

    /** {@return the pan, from -1 (left) through 0 (centre) to 1 (right)} */
    public double pan() {
        return gains.pan;
    }

    /** Sets the gain (finite; output units per model unit). */
    public ListeningPoint setGain(double gain) {
        gains = checkedGains(gain, gains.pan);
        return this;
    }

    /** Sets the pan, from -1 (left) to 1 (right); equal power: cos/sin of (pan + 1) pi / 4. */
    public ListeningPoint setPan(double pan) {
        gains = checkedGains(gains.gain, pan);
        return this;
    }

    Gains gains() {
        return gains;
    }

    void bind(SteppedModel model) {
        switch (kind) {
            case MASS_DISPLACEMENT:
                handle = model.resolveMass(element);
                origin = model.massPositionForSetup(handle, axis);
                break;
            case LINK_ELONGATION:
                handle = model.resolveLink(element, false);
                break;
            default:
                handle = model.resolveLink(element, true);
                break;
        }
        boundTo = model;
    }

    /**
     * {@return true while this point outputs 0 because its mass or interaction is no longer in the model (removed,
     *     or the model cleared); it sounds again, from its first origin, once an element with its name is back}
     */
    public boolean isSilent() {
        return silent;
    }

    void setSilent(boolean s) {
        silent = s;
    }

    /** Asks the model whether the element is back under its name; audio thread, rarely. */
    boolean reattach(SteppedModel model) {
        return kind == Kind.MASS_DISPLACEMENT ? model.reattachMass(handle) : model.reattachLink(handle);
    }

    /** Reads the raw value (before gain) from the bound model; audio thread only. */
    double read(SteppedModel model) {
        switch (kind) {
            case MASS_DISPLACEMENT:
                return model.massPosition(handle, axis) - origin;
            case LINK_ELONGATION:
                return model.linkElongation(handle);
            default:
                return model.linkTension(handle);
        }
    }

    @Override
    public String toString() {
        return kind + "(" + element + (axis >= 0 ? ", axis " + "xyz".charAt(axis) : "") + ", gain " + gains.gain
                + ", pan " + gains.pan + ")";
    }
}
