package tactus.audio;

/**
 * One-pole DC-blocking high-pass, y(n) = x(n) - x(n-1) + r y(n-1). Its -3 dB corner is about
 * (1 - r) fs / (2 pi): r = 0.95 (the paper's sketches) has its corner near 343 Hz at 44.1 kHz,
 * r = 0.995 near 35 Hz (see {@link #cornerHz(double, double)}).
 */
public final class DcBlocker {
    private double r;
    private double lastIn;
    private double lastOut;

    /**
     * Creates a DC blocker with pole r.
     *
     * @param r the pole, 0 &le; r &lt; 1
     */
    public DcBlocker(double r) {
        setCoefficient(r);
    }

    /** Sets the pole r (0 &le; r &lt; 1); the filter state is kept. */
    public void setCoefficient(double r) {
        if (!(r >= 0 && r < 1)) {
            throw new IllegalArgumentException("DcBlocker: the coefficient must be in [0, 1), got " + r);
        }
        this.r = r;
    }

    /** {@return the pole r} */
    public double coefficient() {
        return r;
    }

    /** Filters one sample. */
    public double process(double x) {
        double y = x - lastIn + r * lastOut;
        lastIn = x;
        lastOut = y;
        return y;
    }

    /** Clears the state; the next input is taken as the previous one, so a constant input gives 0 at once. */
    public void reset(double x) {
        lastIn = x;
        lastOut = 0;
    }

    /**
     * {@return the -3 dB corner in Hz at a sample rate, from the exact response
     *     |H|^2 = 2 (1 - cos w) / (1 + r^2 - 2 r cos w), which gives cos w = (3 - r^2) / (4 - 2 r)}
     */
    public static double cornerHz(double r, double sampleRate) {
        double cosW = (3 - r * r) / (4 - 2 * r);
        return Math.acos(Math.max(-1, Math.min(1, cosW))) * sampleRate / (2 * Math.PI);
    }
}
