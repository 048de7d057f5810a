package tactus.demo;

import tactus.audio.AvatarExchange;
import tactus.haptics.AvatarLink;
import tactus.haptics.HapticLoop;

/**
 * The haptic loop's side of an audio-haptic scene, with a flight recorder: an {@link AvatarLink} that hands
 * the device position to the audio thread through an {@link AvatarExchange} and takes back the force the
 * model put on the avatar (averaged over the audio steps since the previous tick), and that keeps, for
 * every tick, the time, the audio steps done so far, the handle position, the avatar target and force, and
 * the force and torques the loop sent. The recording goes into arrays allocated up front: the haptic thread
 * allocates nothing, takes no lock and does no I/O. Read the recording only after the loop has stopped.
 *
 * <p>In {@code HapticLoop.Mode.AUDIO} the loop never calls {@link #step(int)}: the audio thread steps the
 * model.
 */
final class ExchangeAvatar implements AvatarLink {
    /** Columns of one tick's record. */
    static final int T_NANOS = 0;
    static final int AUDIO_STEPS = 1;
    static final int HANDLE_X = 2;
    static final int HANDLE_Y = 3;
    static final int TARGET_X = 4;
    static final int TARGET_Y = 5;
    static final int MODEL_FX = 6;
    static final int MODEL_FY = 7;
    static final int STEPS_SPANNED = 8;
    /** The device force (N) and torques (N m) the loop sent at the end of this tick. */
    static final int FORCE_X = 9;
    static final int FORCE_Y = 10;
    static final int TAU1 = 11;
    static final int TAU2 = 12;
    static final int COLUMNS = 13;

    private final AvatarExchange exchange;
    private final double[][] log;
    private final double[] tmp = new double[2];
    private volatile HapticLoop loop;
    private int ticks;
    private double targetX = Double.NaN;
    private double targetY = Double.NaN;

    /**
     * @param exchange the exchange attached to the model's PhyUGen
     * @param capacity the most ticks recorded; later ticks are still served, not recorded
     */
    ExchangeAvatar(AvatarExchange exchange, int capacity) {
        this.exchange = exchange;
        this.log = new double[COLUMNS][capacity];
    }

    /** Lets the recorder read the loop's handle position, force and torques (call before the loop starts). */
    void recordFrom(HapticLoop haptics) {
        this.loop = haptics;
    }

    /** The exchange is lock-free: the haptic loop calls this link directly. */
    @Override
    public boolean neverWaits() {
        return true;
    }

    @Override
    public void setTarget(double x, double y, double z) {
        exchange.publishPosition(x, y, z);
        targetX = x;
        targetY = y;
    }

    @Override
    public void takeForce(double[] out) {
        long spanned = exchange.takeForce(out);
        int i = ticks;
        if (i > 0 && i - 1 < log[0].length) {
            completePrevious(i - 1);
        }
        if (i < log[0].length) {
            log[T_NANOS][i] = System.nanoTime();
            log[AUDIO_STEPS][i] = exchange.audioSteps();
            HapticLoop l = loop;
            if (l != null) {
                l.devicePosition(tmp);
                log[HANDLE_X][i] = tmp[0];
                log[HANDLE_Y][i] = tmp[1];
            }
            log[TARGET_X][i] = targetX;
            log[TARGET_Y][i] = targetY;
            log[MODEL_FX][i] = out[0];
            log[MODEL_FY][i] = out[1];
            log[STEPS_SPANNED][i] = spanned;
        }
        ticks = i + 1;
    }

    /** Fills in what the loop sent at the end of tick {@code i} (read at the start of the next one). */
    private void completePrevious(int i) {
        HapticLoop l = loop;
        if (l == null) {
            return;
        }
        l.deviceForce(tmp);
        log[FORCE_X][i] = tmp[0];
        log[FORCE_Y][i] = tmp[1];
        log[TAU1][i] = l.torque(1);
        log[TAU2][i] = l.torque(2);
    }

    @Override
    public void step(int n) {
        // AUDIO mode: the audio thread steps the model
    }

    /**
     * Completes the last record once the loop has stopped.
     *
     * @return the number of ticks recorded
     */
    int finish() {
        int n = Math.min(ticks, log[0].length);
        if (n > 0 && ticks <= log[0].length) {
            completePrevious(n - 1);
        }
        return n;
    }

    /** @return column {@code c} of the recording (the array itself; valid for the first {@link #finish()} ticks). */
    double[] column(int c) {
        return log[c];
    }
}
