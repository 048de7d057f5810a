package tactus.haptics.passivity;

/**
 * The time-domain passivity controller (Hannaford &amp; Ryu 2002; Ryu, Kim &amp; Hannaford 2004), impedance form: an
 * adaptive damper added to the force the model asks for, which dissipates the energy the observer has seen the port
 * create, and no more.
 *
 * <p>Causality. The force sent at tick n is held until tick n+1, and its work, {@code F(n)·(x(n+1) - x(n))}, is known
 * only at tick n+1. So the controller keeps the exact account up to tick n (the observer's energy into the model) and
 * adds the predicted work of this tick's force over the next displacement, estimated as {@code v(n) T} with the
 * backward-difference velocity. If that predicted balance is below zero it adds the damping
 * {@code alpha = -E / (T |v|^2)} (at most {@link #setDampingLimit the limit}), which brings the predicted balance back
 * to zero. Whatever the prediction missed shows in the exact account at the next tick and is dissipated then.
 *
 * <p>With a tolerance ({@link #setTolerance}) the controller lets the account run that far below zero before it
 * damps, and damps it back to that level only: the port is then passive with that much energy stored at the start.
 *
 * <p>The account forgets deficits while the controller is off, so that switching it on does not brake the hand for
 * energy created before. It is also capped ({@link #setReserveLimit}): energy the hand put in long ago (pushing
 * through a damper, say) is not a reserve a later stiff contact may give back before the controller acts; the cap
 * must lie above the energy the model itself stores and returns (a mass set moving, a spring wound up), or the
 * controller brakes that honest return. One thread (the haptic loop's) calls everything here; nothing allocates.
 */
final class PassivityController {
    /**
     * The default damping limit, N s/m: measured on the emulated 2DIY (0.019 kg along the wall, one tick of delay),
     * where it lies near m / (T (d + 1/2)); a larger limit made the delayed damper itself shake the handle
     * (docs/haptics-stability.md, "Passivity control").
     */
    static final double DEFAULT_DAMPING_LIMIT = 10;

    /**
     * The default cap on the reserve, J: measured on the emulated 2DIY not to change what the paper's soft examples
     * feel like (docs/haptics-stability.md, "Does it change a soft model?").
     */
    static final double DEFAULT_RESERVE_LIMIT = 0.1;

    private double dampingLimit = DEFAULT_DAMPING_LIMIT;
    private volatile double reserveLimit = DEFAULT_RESERVE_LIMIT;
    private volatile double tolerance;
    private double account;     // J, energy into the model through the port, as the controller counts it
    private double added;       // N s/m, the damping added at the last command

    /** Sets the largest damping (N s/m, > 0) the controller adds in one tick. */
    void setDampingLimit(double nsPerM) {
        dampingLimit = nsPerM;
    }

    double dampingLimit() {
        return dampingLimit;
    }

    /** Sets the largest energy (J, >= 0; infinite for no cap) the account may hold in reserve. */
    void setReserveLimit(double joules) {
        reserveLimit = joules;
    }

    double reserveLimit() {
        return reserveLimit;
    }

    /** Sets the deficit (J, >= 0; default 0) the controller lets the port run before it damps, and damps down to. */
    void setTolerance(double joules) {
        tolerance = joules;
    }

    double tolerance() {
        return tolerance;
    }

    void reset() {
        account = 0;
        added = 0;
    }

    /** Adds the energy (J) that entered the model through the port during the last tick. */
    void observe(double intoModel, boolean on) {
        account += intoModel;
        if (!on && account < 0) {
            account = 0;
        }
        double cap = reserveLimit;
        if (account > cap) {
            account = cap;
        }
    }

    /**
     * Adds the damper to the force f (N, device axes, in place) for the velocity v (m/s) over a period of T seconds;
     * returns the damping added (N s/m, 0 when none). The damper's force is -alpha v. {@code inFlight} (N) is the sum
     * of the forces already sent that have not yet acted over a measured displacement (with d ticks of exchange delay,
     * the last d forces); their work is predicted with the same velocity.
     */
    double command(double[] f, double[] v, double[] inFlight, double period) {
        double v2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
        double power = (f[0] + inFlight[0]) * v[0] + (f[1] + inFlight[1]) * v[1] + (f[2] + inFlight[2]) * v[2];
        double predicted = account - power * period + tolerance;
        added = 0;
        if (predicted < 0 && v2 > 0) {
            double alpha = Math.min(-predicted / (period * v2), dampingLimit);
            f[0] -= alpha * v[0];
            f[1] -= alpha * v[1];
            f[2] -= alpha * v[2];
            added = alpha;
        }
        return added;
    }

    /**
     * As {@link #command}, for late answers ({@link HapticPort#setLateBound}): the next new state will charge its
     * displacement, predicted as {@code v T span}, to whichever force that may have acted over it puts the least energy
     * into the model, this one (f) or one in flight, whose lowest power at v is {@code worstInFlight} (W; +infinity
     * when none). If that predicted balance is below zero, adds the damping that brings it back to zero (at most the
     * limit); the damping changes f only, so when a force in flight is the worst the balance may stay below zero, and
     * the next ticks damp again.
     */
    double commandLate(double[] f, double[] v, double worstInFlight, double span, double period) {
        double v2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
        double own = -(f[0] * v[0] + f[1] * v[1] + f[2] * v[2]);
        double worst = Math.min(own, worstInFlight);
        double predicted = account + worst * span * period + tolerance;
        added = 0;
        if (predicted < 0 && v2 > 0) {
            double alpha = Math.min(-predicted / (span * period * v2), dampingLimit);
            f[0] -= alpha * v[0];
            f[1] -= alpha * v[1];
            f[2] -= alpha * v[2];
            added = alpha;
        }
        return added;
    }

    /** The damping (N s/m) added at the last command. */
    double added() {
        return added;
    }
}
