package tactus.haptics.passivity;

import tactus.haptics.HapticDevice;
import tactus.haptics.HapticLoop;

/**
 * What sits between the device and the avatar in a {@link HapticLoop}, in the device's units (metres, newtons, along
 * its axes), so that it works alike for every {@link HapticDevice} and for the 2DIY's board path: the
 * {@link PassivityObserver}, the {@link PassivityController}, an optional {@link VirtualCoupling} and an optional
 * {@link FrictionCompensation}. Each tick the loop calls {@link #sense} with the handle's position (and gets back
 * where the avatar must go), {@link #command} with the model's force (and gets back the force to send), then
 * {@link #sent} with the share of it that went out. One thread (the loop's) calls these; the switches may be
 * flipped from any thread. Nothing here allocates or locks.
 *
 * <p>Not API: public only for {@link tactus.haptics.HapticLoop} and the measurement tools' {@code PortLink} (a documented hook); it may change without notice.
 */
public final class HapticPort {
    private final PassivityObserver observer = new PassivityObserver();
    private final PassivityController controller = new PassivityController();
    private final EnergyBound bound = new EnergyBound();
    private volatile boolean controlOn;
    private volatile FrictionCompensation friction;
    private volatile VirtualCoupling coupling;   // as set, from any thread
    private VirtualCoupling active;              // the one in use on the loop's thread

    private double period = 1e-3;
    private boolean havePrevious;
    private final double[] previous = new double[3];   // the handle's last position, m
    private final double[] position = new double[3];   // this tick's, m
    private final double[] velocity = new double[3];   // backward difference, m/s
    private final double[] portForce = new double[3];  // the force at the port this tick (coupling, model, damper), N
    /** The most ticks of exchange delay the account can follow. */
    public static final int MAX_DELAY = 8;
    private final double[][] sentPort = new double[MAX_DELAY + 1][3];   // the port's forces as sent, N (a ring)
    private final double[][] sentDamper = new double[MAX_DELAY + 1][3]; // the controller's part of them, N
    private int delay;
    private int slot;                                   // where sent() writes this tick's force
    private final double[] damper = new double[3];     // the controller's force this tick, N
    private final double[] inFlight = new double[3];   // forces sent but not yet acted over a measured step, N
    private final double[] proxy = new double[3];      // the coupling's proxy: position, m
    private final double[] proxyVelocity = new double[3];
    private final double[] filtered = new double[3];   // the velocity seen by the friction compensation, m/s
    private final ContactPlay play = new ContactPlay();
    private final double[] playWidths = new double[3]; // m per axis; all 0: no play
    private double frictionGain;                        // its filter's weight per tick
    private double frictionX;
    private double frictionY;
    private double frictionZ;

    /** The largest bound on late answers (ticks) the account can follow. */
    public static final int MAX_LATE = 16;
    /** Ticks of sent forces kept for the late-answer account: a state gap longer than this is charged to these only. */
    private static final int HISTORY = 64;
    private int late;                                            // the bound W on late answers, ticks; 0: off
    private final double[][] history = new double[HISTORY][3];  // the port's forces as sent, by tick (a ring), N
    private final double[][] historyDamper = new double[HISTORY][3];
    private long sentCount;                                     // forces sent since start: the tick index of the next
    private long lastFresh;                                     // sentCount when the last new state was read
    private double lateSpan = 1;                                // ticks the next charged displacement will span

    /** The observer this port keeps (the one {@code HapticLoop.passivity()} returns). */
    public PassivityObserver observer() {
        return observer;
    }

    /** Switches the passivity controller on or off, from any thread. */
    public void setControl(boolean on) {
        controlOn = on;
    }

    /** True while the passivity controller is on. */
    public boolean isControl() {
        return controlOn;
    }

    /** Sets the largest damping the controller may add, in N s/m. */
    public void setDampingLimit(double nsPerM) {
        controller.setDampingLimit(nsPerM);
    }

    /** The largest damping the controller may add, in N s/m. */
    public double dampingLimit() {
        return controller.dampingLimit();
    }

    /**
     * Sets the coupling (null: none), at any time: the loop's thread takes it at its next {@link #sense}, with the
     * proxy placed at the handle and moving with it (the coupling then pulls with zero force: bumpless).
     */
    public void setCoupling(VirtualCoupling c) {
        coupling = c;
    }

    /** Caps the energy (J, >= 0, infinite: no cap) the controller may hold in reserve; see {@link PassivityController}. */
    public void setReserveLimit(double joules) {
        controller.setReserveLimit(joules);
    }

    /** The cap on the energy the controller may hold in reserve, in J. */
    public double reserveLimit() {
        return controller.reserveLimit();
    }

    /** Lets the port run a deficit of this much (J, >= 0) before the controller damps; see {@link PassivityController}. */
    public void setTolerance(double joules) {
        controller.setTolerance(joules);
    }

    /** The deficit the port may run before the controller damps, in J. */
    public double tolerance() {
        return controller.tolerance();
    }

    /**
     * Sets how many ticks pass between reading a position and the force sent at that tick taking effect (0..
     * {@link #MAX_DELAY}; default 0): the account then charges each displacement to the force that was acting over it.
     * Only before {@link #start}.
     */
    public void setDelay(int ticks) {
        delay = ticks;
    }

    /** The exchange delay the account assumes, in ticks. */
    public int delay() {
        return delay;
    }

    /**
     * Sets the bound W (ticks, 0..{@link #MAX_LATE}; 0, the default: off) on how late a state may answer: a tick whose
     * state is not new adds no work and keeps its force in flight, and the displacement between two new states is
     * charged with the worst case, for passivity, of the forces that may have acted over it (those sent from W + d
     * ticks before the earlier state to d ticks before the later one). Off, the account is the fixed-delay one. Only
     * before {@link #start}.
     */
    public void setLateBound(int ticks) {
        late = ticks;
    }

    /** The bound on late answers the account follows, in ticks (0: the fixed-delay account). */
    public int lateBound() {
        return late;
    }

    /** The virtual coupling in use, or null. */
    public VirtualCoupling coupling() {
        return coupling;
    }

    /**
     * Bounds the port's force by the energy the hand put in, as a spring of this stiffness (N/m, > 0; 0: off), from
     * any thread; see {@link EnergyBound}. Switched on, the budget starts at the seed.
     */
    public void setEnergyBound(double stiffness) {
        bound.setStiffness(stiffness);
    }

    /** The stiffness (N/m) the energy bound assumes; 0 when it is off. */
    public double energyBound() {
        return bound.stiffness();
    }

    /** Sets the energy bound's seed (J, >= 0): what a contact may push with before the hand has put anything in. */
    public void setEnergyBoundSeed(double joules) {
        bound.setSeed(joules);
    }

    /** The energy bound's seed, J. */
    public double energyBoundSeed() {
        return bound.seed();
    }

    /**
     * Sets the energy bound's count reserve c (sensor counts, &gt;= 0; 0: none), from any thread: the force is also
     * capped so that the handle moving back by one count at that force takes at most 1 / c of the budget; see
     * {@link EnergyBound}.
     */
    public void setEnergyBoundCountReserve(double counts) {
        bound.setCountReserve(counts);
    }

    /** The energy bound's count reserve, counts (0: none). */
    public double energyBoundCountReserve() {
        return bound.countReserve();
    }

    /**
     * Tells the energy bound the sensor's count at the handle along each axis (m, &gt;= 0; 0: continuous), from the
     * loop's thread before {@link #command}.
     */
    public void setPositionQuantum(double qx, double qy, double qz) {
        bound.setQuantum(qx, qy, qz);
    }

    /** Sets the largest change (N, > 0) of the force, as a vector, from one tick to the next while the bound is on. */
    public void setForceRiseLimit(double newtons) {
        bound.setRise(newtons);
    }

    /**
     * Sets the energy bound's trim ratio r (&gt;= 1; 8 by default), from any thread: the budget never exceeds r times the
     * energy the force sent holds in a spring of the bound's stiffness; see {@link EnergyBound}.
     */
    public void setEnergyBoundTrim(double ratio) {
        bound.setTrim(ratio);
    }

    /** The energy bound's trim ratio. */
    public double energyBoundTrim() {
        return bound.trim();
    }

    /**
     * Switches the energy bound's hold compensation on or off, from any thread: the cap is moved along the measured
     * velocity by K T (d + 1/2), the damping that the tick's hold and the exchange delay take away, where the sensor is
     * fine enough; see {@link EnergyBound}.
     */
    public void setHoldCompensation(boolean on) {
        bound.setHoldCompensation(on);
    }

    /** Whether the energy bound's hold compensation is on. */
    public boolean isHoldCompensation() {
        return bound.holdCompensation();
    }

    /** The largest rise of the force per tick while the bound is on, N. */
    public double forceRiseLimit() {
        return bound.rise();
    }

    /** The energy bound's budget (J) after the last tick: what the force sent may still hold. */
    public double energyBudget() {
        return bound.budget();
    }

    /**
     * Declares lower bounds of the device's own dissipation at the handle, from any thread: viscous damping (N s/m,
     * &gt;= 0) and Coulomb friction (N, &gt;= 0). The energy bound's budget is credited with the least energy they
     * took from the hand over each measured displacement; see {@link EnergyBound}.
     */
    public void setDeviceDissipation(double nsPerM, double newtons) {
        bound.setDissipation(nsPerM, newtons);
    }

    /** The device's declared viscous damping at the handle, N s/m. */
    public double deviceDamping() {
        return bound.damping();
    }

    /** The device's declared Coulomb friction at the handle, N. */
    public double deviceFriction() {
        return bound.friction();
    }

    /** Sets the friction compensation (null: none), from any thread. */
    public void setFriction(FrictionCompensation f) {
        friction = f;
    }

    /** The friction compensation in use, or null. */
    public FrictionCompensation friction() {
        return friction;
    }

    /** Clears the state and the observer's figures, for a loop of this period (s). */
    public void start(double periodSeconds) {
        period = periodSeconds;
        havePrevious = false;
        for (int i = 0; i < 3; i++) {
            previous[i] = 0;
            velocity[i] = 0;
            filtered[i] = 0;
            proxyVelocity[i] = 0;
            for (int j = 0; j <= MAX_DELAY; j++) {
                sentPort[j][i] = 0;
                sentDamper[j][i] = 0;
            }
        }
        for (int j = 0; j < HISTORY; j++) {
            for (int i = 0; i < 3; i++) {
                history[j][i] = 0;
                historyDamper[j][i] = 0;
            }
        }
        sentCount = 0;
        lastFresh = 0;
        lateSpan = 1;
        slot = 0;
        active = null;
        play.reset();
        controller.reset();
        bound.reset();
        observer.reset();
    }

    /**
     * The handle is at (x, y, z) m this tick: accounts for the energy the last force exchanged over the displacement,
     * and writes where the avatar must go (m, device axes) into target[0..2]: the handle, or the coupling's proxy.
     */
    public void sense(double x, double y, double z, double[] target) {
        sense(x, y, z, true, target);
    }

    /**
     * As {@link #sense(double, double, double, double[])}, saying whether this tick's state is new ({@code fresh}):
     * with a bound on late answers ({@link #setLateBound}) a tick whose state is not new adds no work; without one it
     * makes no difference.
     */
    public void sense(double x, double y, double z, boolean fresh, double[] target) {
        position[0] = x;
        position[1] = y;
        position[2] = z;
        if (late > 0) {
            senseLate(fresh);
        } else if (havePrevious) {
            double into = 0;
            double damped = 0;
            // the force acting since the last reading was sent delay + 1 ticks ago (the slot before this tick's)
            int acting = (slot + MAX_DELAY - delay) % (MAX_DELAY + 1);
            double[] f = sentPort[acting];
            double[] d = sentDamper[acting];
            for (int i = 0; i < 3; i++) {
                double dx = position[i] - previous[i];
                into -= f[i] * dx;
                damped -= d[i] * dx;
                velocity[i] = dx / period;
            }
            boolean on = controlOn;
            controller.observe(into, on);
            bound.observe(into);
            bound.credit(position, previous, period);
            observer.record(into, damped);
        }
        if (late == 0) {
            System.arraycopy(position, 0, previous, 0, 3);
            havePrevious = true;
        }
        VirtualCoupling c = coupling;
        if (c != active) {
            // a coupling switched in (or changed): the proxy starts at the handle with its velocity, so the spring
            // and the damper pull with zero force at this tick; switched out, the avatar goes back to the handle
            System.arraycopy(position, 0, proxy, 0, 3);
            System.arraycopy(velocity, 0, proxyVelocity, 0, 3);
            active = c;
        }
        FrictionCompensation f = friction;
        if (f != null) {
            double w = 1 - Math.exp(-2 * Math.PI * f.cutoffHz() * period);
            for (int i = 0; i < 3; i++) {
                filtered[i] += w * (velocity[i] - filtered[i]);
            }
        }
        if (active == null && bound.stiffness() > 0
                && (playWidths[0] > 0 || playWidths[1] > 0 || playWidths[2] > 0)) {
            play.follow(position, playWidths, target);
            return;
        }
        play.reset();
        System.arraycopy(active != null ? proxy : position, 0, target, 0, 3);
    }

    /**
     * Sets the play ({@link ContactPlay}) between the handle and the avatar, m per axis (&gt;= 0; all 0: none), used
     * while the energy bound is on and no coupling is set. From the loop's thread, before {@link #sense}.
     */
    public void setContactPlay(double wx, double wy, double wz) {
        playWidths[0] = wx;
        playWidths[1] = wy;
        playWidths[2] = wz;
    }

    /**
     * The late-answer account (W = {@link #setLateBound} > 0): a new state charges the displacement since the last new
     * state with the force, among those that may have acted over it, that puts the least energy into the model.
     */
    private void senseLate(boolean fresh) {
        long n = sentCount;
        if (!havePrevious) {
            System.arraycopy(position, 0, previous, 0, 3);
            havePrevious = true;
            lastFresh = n;
            return;
        }
        if (!fresh) {
            controller.observe(0, controlOn);
            bound.observe(0);
            observer.record(0, 0);
            lateSpan = n + 1 - lastFresh;
            return;
        }
        double dx = position[0] - previous[0];
        double dy = position[1] - previous[1];
        double dz = position[2] - previous[2];
        long last = n - 1 - delay;
        long first = Math.max(Math.max(lastFresh - late - delay, 0), n - HISTORY);
        double into = 0;
        double damped = 0;
        if (last >= first) {
            into = Double.POSITIVE_INFINITY;
            for (long j = first; j <= last; j++) {
                double[] f = history[(int) (j % HISTORY)];
                double e = -(f[0] * dx + f[1] * dy + f[2] * dz);
                if (e < into) {
                    into = e;
                    double[] d = historyDamper[(int) (j % HISTORY)];
                    damped = -(d[0] * dx + d[1] * dy + d[2] * dz);
                }
            }
        }
        double span = Math.max(1, n - lastFresh) * period;
        velocity[0] = dx / span;
        velocity[1] = dy / span;
        velocity[2] = dz / span;
        controller.observe(into, controlOn);
        bound.observe(into);
        bound.credit(position, previous, span);
        observer.record(into, damped);
        System.arraycopy(position, 0, previous, 0, 3);
        lastFresh = n;
        lateSpan = 1;
    }

    /**
     * The lowest power (W, into the model, at the velocity v) of the forces in flight: those sent since W + d ticks
     * before the last new state; +infinity when there are none.
     */
    private double worstInFlight() {
        long n = sentCount;
        long first = Math.max(Math.max(lastFresh - late - delay, 0), n - HISTORY);
        double worst = Double.POSITIVE_INFINITY;
        for (long j = first; j < n; j++) {
            double[] g = history[(int) (j % HISTORY)];
            double p = -(g[0] * velocity[0] + g[1] * velocity[1] + g[2] * velocity[2]);
            if (p < worst) {
                worst = p;
            }
        }
        return worst;
    }

    /**
     * The model pushes the avatar with f (N, device axes); replaces f with the force to send: through the coupling
     * when there is one, plus the controller's damper when it is on, plus the friction compensation when set.
     */
    public void command(double[] f) {
        VirtualCoupling c = active;
        if (c != null) {
            double k = c.stiffness();
            double b = c.damping();
            double m = c.mass();
            for (int i = 0; i < 3; i++) {
                double onProxy = k * (position[i] - proxy[i]) + b * (velocity[i] - proxyVelocity[i]);
                proxyVelocity[i] += period * (f[i] + onProxy) / m;   // semi-implicit Euler
                proxy[i] += period * proxyVelocity[i];
                f[i] = -onProxy;
            }
        }
        bound.apply(f, velocity, period, period * (delay + 0.5));
        double alpha = 0;
        if (controlOn) {
            System.arraycopy(f, 0, damper, 0, 3);
            for (int i = 0; i < 3; i++) {
                inFlight[i] = 0;
            }
            for (int j = 1; j <= delay; j++) {
                double[] g = sentPort[(slot + MAX_DELAY + 1 - j) % (MAX_DELAY + 1)];
                for (int i = 0; i < 3; i++) {
                    inFlight[i] += g[i];
                }
            }
            if (late > 0) {
                alpha = controller.commandLate(f, velocity, worstInFlight(), lateSpan, period);
            } else {
                alpha = controller.command(f, velocity, inFlight, period);
            }
            for (int i = 0; i < 3; i++) {
                damper[i] = f[i] - damper[i];
            }
        } else {
            damper[0] = 0;
            damper[1] = 0;
            damper[2] = 0;
        }
        observer.damping(alpha);
        System.arraycopy(f, 0, portForce, 0, 3);
        FrictionCompensation fc = friction;
        frictionX = 0;
        frictionY = 0;
        frictionZ = 0;
        if (fc != null) {
            double s = Math.sqrt(filtered[0] * filtered[0] + filtered[1] * filtered[1] + filtered[2] * filtered[2]);
            double add = fc.forceAt(s);
            if (add > 0) {
                frictionX = add * filtered[0] / s;
                frictionY = add * filtered[1] / s;
                frictionZ = add * filtered[2] / s;
                f[0] += frictionX;
                f[1] += frictionY;
                f[2] += frictionZ;
            }
        }
    }

    /**
     * The force returned by {@link #command} went out scaled by this factor (1 as commanded, a torque gain, a limit's
     * scale, or 0 when the loop sent zero instead): records the port's part of it for the next tick's account.
     */
    public void sent(double scale) {
        double[] f = sentPort[slot];
        double[] d = sentDamper[slot];
        for (int i = 0; i < 3; i++) {
            f[i] = scale * portForce[i];
            d[i] = scale * damper[i];
        }
        slot = (slot + 1) % (MAX_DELAY + 1);
        double[] h = history[(int) (sentCount % HISTORY)];
        double[] hd = historyDamper[(int) (sentCount % HISTORY)];
        for (int i = 0; i < 3; i++) {
            h[i] = f[i];
            hd[i] = d[i];
        }
        sentCount++;
    }
}
