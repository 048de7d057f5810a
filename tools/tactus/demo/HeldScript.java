package tactus.demo;

import tactus.haptics.emulator.Hand;

/**
 * A hand's script that holds the hand at its first point until it is started, then plays from there: time 0 of
 * the script is the emulator's time at {@link #startAt(double)}. The demo starts it once its haptic loop ticks,
 * so that the loop's set-up (real-time scheduling, a heap warm-up: up to seconds on a loaded machine) does not
 * eat the start of the script while nobody reads the handle. Called on the thread that advances the emulator:
 * allocates nothing and takes no lock.
 */
final class HeldScript implements Hand.Script {
    private final Hand.Script script;
    private volatile double origin = Double.POSITIVE_INFINITY;

    /** Holds {@code script} at its time 0 until {@link #startAt(double)}. */
    HeldScript(Hand.Script script) {
        if (script == null) {
            throw new IllegalArgumentException("HeldScript: script must not be null");
        }
        this.script = script;
    }

    /** Starts the script: its time 0 is the emulator's time {@code emulatorSeconds} (seconds, finite). */
    void startAt(double emulatorSeconds) {
        if (!Double.isFinite(emulatorSeconds)) {
            throw new IllegalArgumentException("HeldScript.startAt: time must be a finite number of seconds, got "
                    + emulatorSeconds);
        }
        origin = emulatorSeconds;
    }

    /** True once {@link #startAt(double)} was called. */
    boolean started() {
        return origin != Double.POSITIVE_INFINITY;
    }

    @Override
    public void at(double t, double[] out) {
        double s = t - origin;
        script.at(s > 0 ? s : 0, out);
    }
}
