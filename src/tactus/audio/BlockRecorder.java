package tactus.audio;

/**
 * The listening points of a {@link PhyUGen} read a whole block at a time: the mass handles and axes that
 * {@link SteppedModel#stepRecording} records after each step, the buffer it records into, and the mix of one
 * recorded step. Made on the audio thread when the points, the model or the block size change (never per block);
 * only for points that all read mass displacements (an interaction's elongation or tension is read per sample).
 */
final class BlockRecorder {
    final ListeningPoint[] points;
    final SteppedModel model;
    final int count;
    final int[] handles;
    final int[] axes;
    /** Recorded positions, {@code count} per step, for up to {@link #capacity} steps. */
    final double[] values;
    final int capacity;
    // this block's origins and gains, read once per block
    private final double[] origin;
    private final double[] left;
    private final double[] right;
    private final double[] mono;
    double mixLeft;
    double mixRight;
    double mixMono;

    private BlockRecorder(ListeningPoint[] points, SteppedModel model, int capacity) {
        this.points = points;
        this.model = model;
        this.capacity = capacity;
        count = points.length;
        handles = new int[count];
        axes = new int[count];
        origin = new double[count];
        left = new double[count];
        right = new double[count];
        mono = new double[count];
        values = new double[Math.max(1, count * capacity)];
        for (int i = 0; i < count; i++) {
            handles[i] = points[i].handle;
            axes[i] = points[i].axis();
        }
    }

    /**
     * {@return a recorder for these points on this model for blocks of up to {@code capacity} steps, or null when a
     *     point reads an interaction (those are read per sample)}
     */
    static BlockRecorder of(ListeningPoint[] points, SteppedModel model, int capacity) {
        for (ListeningPoint p : points) {
            if (p.kind() != ListeningPoint.Kind.MASS_DISPLACEMENT || p.boundTo != model) {
                return null;
            }
        }
        return new BlockRecorder(points, model, capacity);
    }

    /** {@return true when this recorder serves these points on this model for a block of n steps} */
    boolean serves(ListeningPoint[] pts, SteppedModel m, int n) {
        if (pts != points || m != model || n > capacity) {
            return false;
        }
        for (int i = 0; i < count; i++) {
            if (pts[i].handle != handles[i]) {
                return false;   // bound again (a new model stepper): the handles changed
            }
        }
        return true;
    }

    /** {@return true when every point can be read (none has gone silent)} */
    boolean allAudible() {
        for (ListeningPoint p : points) {
            if (p.isSilent()) {
                return false;
            }
        }
        return true;
    }

    /** Reads each point's origin and gains for this block: a change made during the block lands at the next. */
    void beginBlock() {
        for (int i = 0; i < count; i++) {
            ListeningPoint p = points[i];
            ListeningPoint.Gains g = p.gains();
            origin[i] = p.origin;
            left[i] = g.left;
            right[i] = g.right;
            mono[i] = g.gain;
        }
    }

    /** Mixes the points recorded after step s into {@link #mixLeft}, {@link #mixRight} and {@link #mixMono}. */
    void mix(int s) {
        double l = 0;
        double r = 0;
        double m = 0;
        int q = s * count;
        for (int i = 0; i < count; i++) {
            double v = values[q + i] - origin[i];
            l += left[i] * v;
            r += right[i] * v;
            m += mono[i] * v;
        }
        mixLeft = l;
        mixRight = r;
        mixMono = m;
    }
}
