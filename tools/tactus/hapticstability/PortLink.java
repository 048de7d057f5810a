package tactus.hapticstability;

import tactus.haptics.passivity.HapticPort;
import tactus.haptics.passivity.FrictionCompensation;
import tactus.haptics.passivity.PassivityObserver;
import tactus.haptics.passivity.VirtualCoupling;
import tactus.haptics.AvatarLink;
import tactus.haptics.HapticLoop;

/**
 * For measurements: a {@link HapticPort} (the passivity observer and controller, a coupling, friction compensation)
 * run around an {@link AvatarLink} instead of inside the {@link HapticLoop}, for rigs that run the loop in lockstep
 * with an emulated plant faster than real time (the loop's rate is then not the simulated period, which the port
 * needs). Converts the model's positions and forces to the device's metres and newtons with the loop's mapping
 * (position gain alpha, force gain beta, x mirrored or not; the origin cancels out). The only difference from the
 * loop's own port: it cannot see the loop's torque limit, so it assumes every force went out as commanded.
 */
public final class PortLink extends ForwardingAvatarLink {
    private final HapticPort port = new HapticPort();
    private final double alpha;
    private final double beta;
    private final double sx;
    private final double[] target = new double[3];
    private final double[] force = new double[3];
    private final double[] play = new double[3];
    private boolean started;
    private final double period;

    /**
     * A port of this period (s) around the link, for a loop with these gains (alpha model units per metre, beta newtons
     * per model force unit) and mirroring; the options are set on {@link #port()} before the first tick.
     */
    public PortLink(AvatarLink inner, double periodSeconds, double alpha, double beta, boolean mirrorX) {
        super(inner);
        this.period = periodSeconds;
        this.alpha = alpha;
        this.beta = beta;
        this.sx = mirrorX ? -1 : 1;
    }

    /** Sets the passivity controller on or off. */
    public PortLink control(boolean on) {
        port.setControl(on);
        return this;
    }

    /** Sets the largest damping the controller adds, N s/m. */
    public PortLink dampingLimit(double nsPerM) {
        port.setDampingLimit(nsPerM);
        return this;
    }

    /** Lets the port run this deficit (J) before the controller damps. */
    public PortLink tolerance(double joules) {
        port.setTolerance(joules);
        return this;
    }

    /** Caps the controller's reserve, J (infinite: no cap). */
    public PortLink reserveLimit(double joules) {
        port.setReserveLimit(joules);
        return this;
    }

    /** Sets a virtual coupling (at any time; taken at the next tick, bumpless). */
    public PortLink coupling(VirtualCoupling c) {
        port.setCoupling(c);
        return this;
    }

    /** Sets the exchange delay the observer assumes, ticks (before the first tick). */
    public PortLink delay(int ticks) {
        port.setDelay(ticks);
        return this;
    }

    /** Bounds the force by the energy the hand put in, as a spring of this stiffness (N/m; 0: off). */
    public PortLink energyBound(double stiffness) {
        port.setEnergyBound(stiffness);
        return this;
    }

    /** Sets the energy bound's seed, J. */
    public PortLink energyBoundSeed(double joules) {
        port.setEnergyBoundSeed(joules);
        return this;
    }

    /** Sets the largest rise of the force per tick while the energy bound is on, N. */
    public PortLink forceRiseLimit(double newtons) {
        port.setForceRiseLimit(newtons);
        return this;
    }

    /** Sets the contact play (m per axis of the device; see {@code HapticLoop.setContactPlay}). */
    public PortLink contactPlay(double wx, double wy, double wz) {
        play[0] = wx;
        play[1] = wy;
        play[2] = wz;
        return this;
    }

    /** Sets the friction compensation. */
    public PortLink friction(FrictionCompensation f) {
        port.setFriction(f);
        return this;
    }

    /** The port itself (its options and figures). */
    public HapticPort port() {
        return port;
    }

    /** The observer. */
    public PassivityObserver observer() {
        return port.observer();
    }

    @Override
    public void setTarget(double x, double y, double z) {
        if (!started) {
            port.start(period);
            started = true;
        }
        port.setContactPlay(play[0], play[1], play[2]);
        port.sense(sx * x / alpha, y / alpha, z / alpha, target);
        inner.setTarget(sx * alpha * target[0], alpha * target[1], alpha * target[2]);
    }

    @Override
    public long takeForceCounted(double[] out) {
        long n = inner.takeForceCounted(force);
        double k = n > 0 ? 1.0 / n : 1;   // the loop renders the mean per step: the port works on that
        force[0] = sx * beta * force[0] * k;
        force[1] = beta * force[1] * k;
        force[2] = beta * force[2] * k;
        if (started) {
            port.command(force);
            port.sent(1);
        }
        out[0] = sx * force[0] / beta;
        out[1] = force[1] / beta;
        out[2] = force[2] / beta;
        return n > 0 ? 1 : n;
    }
}
