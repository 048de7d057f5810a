package tactus.haptics;

/**
 * Test fixture: a one-axis device as a sampled-data plant. A handle of mass m with viscous damping b and an optional
 * Coulomb friction (a static threshold: a handle at rest moves only when the other forces exceed it), optionally held
 * by a hand (a spring-damper to a scripted intended position), driven by a force held constant between ticks (zero-
 * order hold) that takes effect d ticks after it is sent, simulated with many substeps per tick. It integrates the
 * work the device force does on the handle exactly, as the reference for the observer. Deterministic, simulated time.
 */
final class SampledPlant {
    final double mass;
    final double damping;
    final double period;
    private final int substeps;
    private final double[] queue;   // forces waiting for their delay, N
    private int head;
    private double coulomb;
    private double handStiffness;
    private double handDamping;
    private double intended = Double.NaN;   // NaN: no hand
    double x;
    double v;
    /** Work (J) the device force has done on the handle: energy the device gave to the hand and handle. */
    double workOnHandle;

    SampledPlant(double mass, double damping, double period, int delayTicks) {
        this.mass = mass;
        this.damping = damping;
        this.period = period;
        this.substeps = 200;
        this.queue = new double[delayTicks + 1];
    }

    SampledPlant coulomb(double newtons) {
        coulomb = newtons;
        return this;
    }

    SampledPlant hand(double stiffness, double damping) {
        handStiffness = stiffness;
        handDamping = damping;
        return this;
    }

    /** Where the hand wants the handle (m); NaN lets go. */
    void intend(double position) {
        intended = position;
    }

    /** Sends the force (N) computed this tick; it acts d ticks from now, for one tick. */
    void send(double force) {
        queue[head] = force;
    }

    /** Advances one tick under the force sent d ticks ago. */
    void advance() {
        int acting = (head + 1) % queue.length;   // the oldest force in the queue (this tick's when d = 0)
        double f = queue[acting];
        head = acting;
        double h = period / substeps;
        for (int i = 0; i < substeps; i++) {
            double hand = Double.isNaN(intended) ? 0 : handStiffness * (intended - x) - handDamping * v;
            double push = f + hand;
            double eff = mass + 0;   // the hand's mass is part of m when it holds the handle
            double vNew;
            if (v == 0 && Math.abs(push) <= coulomb) {
                vNew = 0;   // stuck: the threshold holds it
            } else {
                double fr = v != 0 ? -coulomb * Math.signum(v) : -coulomb * Math.signum(push);
                vNew = (eff * v + h * (push + fr)) / (eff + h * damping);   // damping implicit
                if (coulomb > 0 && v != 0 && Math.signum(vNew) != Math.signum(v)) {
                    vNew = 0;   // friction stops it, never reverses it
                }
            }
            double xNew = x + h * vNew;
            workOnHandle += f * (xNew - x);
            x = xNew;
            v = vNew;
        }
    }
}
