package tactus.audio;

import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;

/**
 * The lock-free hand-off between the haptic thread (about 1 kHz) and the audio thread that steps the model
 * (44.1 kHz or more): the haptic side publishes the device position, the audio side adds the force on the
 * avatar after every step, and the haptic side takes that force when it needs it.
 *
 * <p>Each direction has exactly one writer and is a sequence lock: the writer makes its counter odd,
 * writes, and makes it even again; a reader keeps a copy only if the counter was even and unchanged across
 * its read. Nobody ever waits: if a read collides with a write, the audio side keeps the previous
 * position (one step older), and the haptic side reports no new steps this time, leaving the force for
 * its next take. Nothing here allocates.
 *
 * <p>Force: the audio side keeps running totals (compensated sums) of the force and of the steps; a take
 * returns the difference since the previous take, either as the {@link ForceMode#AVERAGE} over the steps it
 * spans (the default: the force gain then does not depend on the audio or haptic rate) or as the
 * {@link ForceMode#SUM} (what the paper's sketches feel, tuned with beta about 0.3-1). With AVERAGE,
 * average x steps is exactly the sum, so the impulse (force x time) that the haptic side can account for
 * equals the one the model produced. When a take spans no step (Minim computes audio in bursts of one
 * buffer), AVERAGE repeats the last average and SUM returns zero.
 *
 * <p>Latency: a position published before the audio thread starts a step is that step's avatar target, so
 * the exchange adds at most one step; the avatar's EWMA (weight w = 1/smoothing) then follows with a time
 * constant of -1/ln(1 - w) steps, and Minim's output buffering comes on top (see docs/audio.md).
 */
public final class AvatarExchange {
    /** How {@link #takeForce(double[])} reports the force accumulated since the previous take. */
    public enum ForceMode {
        /** The mean force per step over the steps since the previous take. */
        AVERAGE,
        /** The sum of the forces of every step since the previous take (the paper's behaviour). */
        SUM
    }

    private static final VarHandle POSITION_SEQ;
    private static final VarHandle FORCE_SEQ;
    private static final int READ_ATTEMPTS = 4;

    static {
        try {
            MethodHandles.Lookup l = MethodHandles.lookup();
            POSITION_SEQ = l.findVarHandle(AvatarExchange.class, "positionSeq", long.class);
            FORCE_SEQ = l.findVarHandle(AvatarExchange.class, "forceSeq", long.class);
        } catch (ReflectiveOperationException e) {
            throw new ExceptionInInitializerError(e);
        }
    }

    // ---- position: written by the haptic thread only
    @SuppressWarnings("unused") // accessed through POSITION_SEQ
    private volatile long positionSeq;
    private double px;
    private double py;
    private double pz;
    // audio side's last consistent copy
    private double lastX;
    private double lastY;
    private double lastZ;
    private boolean havePosition;

    // ---- force totals: written by the audio thread only
    @SuppressWarnings("unused") // accessed through FORCE_SEQ
    private volatile long forceSeq;
    private double sumX;
    private double sumY;
    private double sumZ;
    private double compX;
    private double compY;
    private double compZ;
    private long steps;
    // the audio thread's working totals
    private double wSumX;
    private double wSumY;
    private double wSumZ;
    private double wCompX;
    private double wCompY;
    private double wCompZ;
    private long wSteps;

    // ---- the haptic side's view at its previous take
    private double takenX;
    private double takenY;
    private double takenZ;
    private long takenSteps;
    private final double[] lastAverage = new double[3];
    private volatile ForceMode mode;

    /** Creates an exchange that reports the force {@link ForceMode#AVERAGE}d over the steps a take spans. */
    public AvatarExchange() {
        this(ForceMode.AVERAGE);
    }

    /** Creates an exchange with the given force mode. */
    public AvatarExchange(ForceMode mode) {
        setForceMode(mode);
    }

    /** Sets how {@link #takeForce(double[])} reports the force; call it from the haptic thread. */
    public void setForceMode(ForceMode mode) {
        if (mode == null) {
            throw new IllegalArgumentException("AvatarExchange: the force mode must not be null");
        }
        this.mode = mode;
    }

    /** {@return the force mode} */
    public ForceMode forceMode() {
        return mode;
    }

    // =================================================================== haptic side

    /** Publishes the device position, in model units (haptic thread only; never waits). */
    public void publishPosition(double x, double y, double z) {
        long s = (long) POSITION_SEQ.getOpaque(this);
        POSITION_SEQ.setOpaque(this, s + 1);
        VarHandle.storeStoreFence();
        px = x;
        py = y;
        pz = z;
        // a volatile store (a full fence on x86): the position is visible to the audio thread before this
        // method returns, so "published" has a definite moment; 1 kHz makes its cost irrelevant
        POSITION_SEQ.setVolatile(this, s + 2);
    }

    /**
     * Takes the force applied to the avatar since the previous take (haptic thread only; never waits).
     *
     * @param out receives the average or the sum, per {@link #forceMode()}, in the model's force units
     * @return the number of model steps the take spans (0 if none ran, or if the audio thread was
     *     writing at that instant: the force is then left for the next take)
     */
    public long takeForce(double[] out) {
        for (int attempt = 0; attempt < READ_ATTEMPTS; attempt++) {
            long s1 = (long) FORCE_SEQ.getAcquire(this);
            if ((s1 & 1) != 0) {
                Thread.onSpinWait();
                continue;
            }
            double sx = sumX - compX;
            double sy = sumY - compY;
            double sz = sumZ - compZ;
            long n = steps;
            VarHandle.loadLoadFence();
            if ((long) FORCE_SEQ.getAcquire(this) != s1) {
                continue;
            }
            long spanned = n - takenSteps;
            double fx = sx - takenX;
            double fy = sy - takenY;
            double fz = sz - takenZ;
            takenX = sx;
            takenY = sy;
            takenZ = sz;
            takenSteps = n;
            report(out, fx, fy, fz, spanned);
            return spanned;
        }
        report(out, 0, 0, 0, 0);
        return 0;
    }

    private void report(double[] out, double fx, double fy, double fz, long spanned) {
        if (mode == ForceMode.SUM) {
            out[0] = fx;
            out[1] = fy;
            out[2] = fz;
        } else {
            if (spanned > 0) {
                lastAverage[0] = fx / spanned;
                lastAverage[1] = fy / spanned;
                lastAverage[2] = fz / spanned;
            }
            out[0] = lastAverage[0];
            out[1] = lastAverage[1];
            out[2] = lastAverage[2];
        }
    }

    // =================================================================== audio side

    /**
     * Copies the latest published position into {@code out[0..2]} (audio thread only; never waits).
     *
     * @return false while nothing has been published yet (out is then untouched)
     */
    public boolean readPosition(double[] out) {
        for (int attempt = 0; attempt < READ_ATTEMPTS; attempt++) {
            long s1 = (long) POSITION_SEQ.getAcquire(this);
            if ((s1 & 1) != 0) {
                continue;
            }
            if (s1 == 0) {
                return false;
            }
            double x = px;
            double y = py;
            double z = pz;
            VarHandle.loadLoadFence();
            if ((long) POSITION_SEQ.getAcquire(this) == s1) {
                lastX = x;
                lastY = y;
                lastZ = z;
                havePosition = true;
                break;
            }
        }
        if (!havePosition) {
            return false;
        }
        out[0] = lastX;
        out[1] = lastY;
        out[2] = lastZ;
        return true;
    }

    /** Adds one step's force on the avatar (audio thread only; never waits). */
    public void addForce(double fx, double fy, double fz) {
        double y = fx - wCompX;
        double t = wSumX + y;
        wCompX = (t - wSumX) - y;
        wSumX = t;
        y = fy - wCompY;
        t = wSumY + y;
        wCompY = (t - wSumY) - y;
        wSumY = t;
        y = fz - wCompZ;
        t = wSumZ + y;
        wCompZ = (t - wSumZ) - y;
        wSumZ = t;
        wSteps++;
        long s = (long) FORCE_SEQ.getOpaque(this);
        FORCE_SEQ.setOpaque(this, s + 1);
        VarHandle.storeStoreFence();
        sumX = wSumX;
        sumY = wSumY;
        sumZ = wSumZ;
        compX = wCompX;
        compY = wCompY;
        compZ = wCompZ;
        steps = wSteps;
        FORCE_SEQ.setRelease(this, s + 2);
    }

    /** {@return the number of steps the audio side has reported so far (any thread; for latency checks)} */
    public long audioSteps() {
        while (true) {
            long s1 = (long) FORCE_SEQ.getAcquire(this);
            long n = steps;
            VarHandle.loadLoadFence();
            if ((s1 & 1) == 0 && (long) FORCE_SEQ.getAcquire(this) == s1) {
                return n;
            }
            Thread.onSpinWait();
        }
    }

    /**
     * Copies the latest published position into {@code out[0..2]} for a thread other than the audio one
     * (display, tests); retries while a write is in progress.
     *
     * @return false while nothing has been published yet
     */
    public boolean peekPosition(double[] out) {
        while (true) {
            long s1 = (long) POSITION_SEQ.getAcquire(this);
            if ((s1 & 1) == 0) {
                if (s1 == 0) {
                    return false;
                }
                double x = px;
                double y = py;
                double z = pz;
                VarHandle.loadLoadFence();
                if ((long) POSITION_SEQ.getAcquire(this) == s1) {
                    out[0] = x;
                    out[1] = y;
                    out[2] = z;
                    return true;
                }
            }
            Thread.onSpinWait();
        }
    }
}
