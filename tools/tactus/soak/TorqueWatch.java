package tactus.soak;

import tactus.haptics.AvatarLink;
import tactus.hapticstability.ForwardingAvatarLink;
import tactus.haptics.HapticLoop;

/**
 * Wraps the loop's avatar link (called once per haptic tick, on the haptic thread): counts the NaN forces the model
 * hands the loop (the loop must turn them into zero torque) and checks the torques the loop sent at the previous
 * tick, so that every tick's torque is checked. It never waits, like the link it wraps.
 */
final class TorqueWatch extends ForwardingAvatarLink {
    private final SoakReport report;
    private volatile HapticLoop loop;

    TorqueWatch(AvatarLink inner, SoakReport report) {
        super(inner);
        this.report = report;
    }

    /** The loop whose torques to check; set before it starts. */
    void watch(HapticLoop loop) {
        this.loop = loop;
    }

    @Override
    public long takeForceCounted(double[] out) {
        checkTorques();
        long n = inner.takeForceCounted(out);
        if (!Double.isFinite(out[0]) || !Double.isFinite(out[1]) || !Double.isFinite(out[2])) {
            report.nanForcesFromModel.incrementAndGet();
        }
        report.hapticTicks.incrementAndGet();
        return n;
    }

    private void checkTorques() {
        HapticLoop l = loop;
        if (l == null) {
            return;
        }
        double t1 = l.torque(1);
        double t2 = l.torque(2);
        if (!Double.isFinite(t1) || !Double.isFinite(t2)) {
            report.nan("haptic torque", "the loop sent torques " + t1 + ", " + t2 + " N m");
        }
    }
}
