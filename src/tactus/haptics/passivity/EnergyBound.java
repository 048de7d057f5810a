package tactus.haptics.passivity;

/**
 * Energy bounding of the port's force (after Kim &amp; Ryu): the force sent may never hold more energy, as a spring of
 * stiffness K, than the budget the hand has put in through the port plus a small seed,
 * {@code |F|^2 / (2 K) <= E + E0}. No damper multiplies the force, and the velocity enters it only through the hold
 * compensation below, where the sensor is fine, so the encoders' steps do not make it buzz.
 *
 * <p>The budget E is the port's ledger (the work of the held forces over the measured displacements, with the exchange
 * delay, as the {@link PassivityObserver} counts it), trimmed each tick to what the force sent would hold in a spring
 * r times softer than K (the trim ratio, {@value #DEFAULT_TRIM} by default), {@code E <= r |F|^2 / (2 K)}: energy
 * the hand spent on the model's dampers, or in free space, is no reserve for a later contact, so a contact that
 * appears, moves or stiffens around the handle starts with the seed only; a contact down to K / r still gets back, on
 * release, what it stored (softer ones get back less), and a wall stiffened under a held handle may push with at most
 * sqrt(r) times the force it held. While the cap binds, the force is a spring of slope K whose surface shifts inwards
 * just enough to keep the budget: the energy the hold and the delay create becomes a slow drift of the surface instead
 * of an oscillation, and a contact stiffer than K is felt as K. Then the force may change by at most a given step per
 * tick, as a vector: rises, falls and turns alike, so that neither a contact's onset nor a fast release (a 200 mm/s
 * tap lets the force fall by 1 N in one tick) is a buzz; a limited fall pushes on for a few ticks beyond the cap,
 * which the ledger counts.
 *
 * <p><b>The hold compensation</b> ({@link #setHoldCompensation}). A spring sampled every T and held for a delay tau
 * (half a tick of zero-order hold plus d ticks of exchange delay: tau = T (d + 1/2)) acts as the spring with a
 * negative damping of K tau: on a device whose own damping is smaller, a handle on the cap rings for long after a
 * contact. The cap is then moved along the measured velocity, {@code cap - K tau v}, with v the handle's velocity
 * along the force (positive outwards): a damping of K tau that cancels the hold's to first order. The ledger still
 * charges every force sent. It is used only where the sensor is fine enough: where one count per tick of velocity
 * would move the cap by more than {@value #LEAD_NOISE} N (the 2DIY's encoders), it is off.
 *
 * <p>A deficit (E below zero: the port gave back more than the budget, over a release the cap reacted to one exchange
 * late, or over an encoder count that the ledger charges in full) is forgiven only down to the port's net energy since
 * the bound was switched on: {@code E >= min(0, N)}. So the energy the port has given the hand, as the ledger counts
 * it, stays below the seed plus what one exchange can leak; and a hand that has put more in than it got back is not
 * held at zero force by a deficit the encoders' steps made. The cap does not predict the next displacement: a
 * prediction from the quantised velocity made force steps of 0.6-0.7 N on the 2DIY.
 *
 * <p>One thread (the haptic loop's) calls everything but the setters; nothing allocates.
 */
final class EnergyBound {
    /** The default seed, J. */
    static final double DEFAULT_SEED = 1e-5;
    /** The default largest change of the force per tick, N. */
    static final double DEFAULT_RISE = 0.5;
    /** The default trim ratio: how much softer than K a contact may be and still get back, on release, what it stored. */
    static final double DEFAULT_TRIM = 8;
    /** The most (N) one sensor count per tick of velocity may move the cap by the hold compensation; above, it is off. */
    static final double LEAD_NOISE = 0.01;

    private volatile double stiffness;                // N/m; 0: off
    private volatile double seed = DEFAULT_SEED;      // J
    private volatile double rise = DEFAULT_RISE;      // N per tick
    private boolean on;                               // what the loop's thread last saw
    private double budget;                            // J
    private double net;                               // J: the port's net energy in since the bound was switched on
    private final double[] last = new double[3];      // the force sent at the last tick, N
    private volatile double countReserve;             // c, counts; 0: off
    private final double[] quantum = new double[3];   // the sensor's count along each axis at the handle, m
    private volatile double damping;                  // N s/m: a lower bound of the device's own viscous damping
    private volatile double friction;                 // N: a lower bound of its own Coulomb friction
    private volatile double trim = DEFAULT_TRIM;      // r, >= 1
    private volatile boolean holdCompensation;        // true: the cap is moved by K tau v (see the class)

    /** Sets the stiffness K (N/m, > 0; 0 switches the bound off), from any thread. */
    void setStiffness(double nPerM) {
        stiffness = nPerM;
    }

    double stiffness() {
        return stiffness;
    }

    /** Sets the seed E0 (J, >= 0), from any thread. */
    void setSeed(double joules) {
        seed = joules;
    }

    double seed() {
        return seed;
    }

    /** Sets the largest change of the force per tick (N, > 0, as a vector), from any thread. */
    void setRise(double newtons) {
        rise = newtons;
    }

    double rise() {
        return rise;
    }

    /** Sets the count reserve c (counts, &gt;= 0; 0: off), from any thread. */
    void setCountReserve(double counts) {
        countReserve = counts;
    }

    double countReserve() {
        return countReserve;
    }

    /** Sets the sensor's count along each axis at the handle (m, &gt;= 0), from the loop's thread before {@link #apply}. */
    void setQuantum(double qx, double qy, double qz) {
        quantum[0] = qx;
        quantum[1] = qy;
        quantum[2] = qz;
    }

    /** Sets the trim ratio r (&gt;= 1), from any thread: the budget never exceeds r times what the force sent needs. */
    void setTrim(double ratio) {
        trim = ratio;
    }

    double trim() {
        return trim;
    }

    /** Switches the hold compensation on or off, from any thread; see the class. */
    void setHoldCompensation(boolean on) {
        holdCompensation = on;
    }

    boolean holdCompensation() {
        return holdCompensation;
    }

    /** The budget E (J) as the loop's thread last left it. */
    double budget() {
        return budget;
    }

    void reset() {
        on = false;
        budget = 0;
        net = 0;
        last[0] = 0;
        last[1] = 0;
        last[2] = 0;
    }

    /** Declares lower bounds of the device's own damping (N s/m, &gt;= 0) and friction (N, &gt;= 0), from any thread. */
    void setDissipation(double nsPerM, double newtons) {
        damping = nsPerM;
        friction = newtons;
    }

    double damping() {
        return damping;
    }

    double friction() {
        return friction;
    }

    /**
     * Adds to the budget only the least energy the device's declared damping b and friction f took from the hand while
     * the handle moved from {@code from} to {@code to} (m) in {@code seconds}: with d the displacement less one sensor
     * count per axis (the least the handle can have moved), {@code b |d|^2 / seconds + f |d|} (a motion over a time
     * t dissipates at least {@code b |d|^2 / t} in a damper, by Cauchy-Schwarz, and {@code f |d|} in friction). It
     * pays for force as the hand's input does, but it is not the port's, so it does not move the floor a deficit is
     * forgiven down to, and the trim still drops what no force holds.
     */
    void credit(double[] to, double[] from, double seconds) {
        double b = damping;
        double f = friction;
        if (!(b > 0) && !(f > 0)) {
            return;
        }
        double d2 = 0;
        for (int i = 0; i < 3; i++) {
            double d = Math.max(0, Math.abs(to[i] - from[i]) - quantum[i]);
            d2 += d * d;
        }
        budget += b * d2 / seconds + f * Math.sqrt(d2);
    }

    /** Adds the energy (J) that entered the model through the port during the last tick. */
    void observe(double intoModel) {
        budget += intoModel;
        net += intoModel;
    }

    /**
     * Bounds the force f (N, in place) sent at this tick: scaled down to the energy cap (with the hold compensation on,
     * moved along the handle's velocity v, m/s, for a tick of {@code tickSeconds} and a hold of {@code holdSeconds}),
     * then moved towards it from the last force sent by at most the step limit.
     */
    void apply(double[] f, double[] v, double tickSeconds, double holdSeconds) {
        double k = stiffness;
        double magnitude = Math.sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
        if (!(k > 0)) {
            on = false;
            last[0] = f[0];
            last[1] = f[1];
            last[2] = f[2];
            return;
        }
        if (!on) {
            on = true;
            budget = 0;   // switched on: a contact starts with the seed only, whatever came before
            net = 0;
        }
        double floor = Math.min(0, net);
        if (budget < floor) {
            budget = floor;
        }
        double available = budget + seed;
        double c = countReserve;
        // the sensor's count along the force: a count on each axis, weighted by the force's share of that axis
        double q = magnitude > 0 ? (Math.abs(f[0]) * quantum[0] + Math.abs(f[1]) * quantum[1]
                + Math.abs(f[2]) * quantum[2]) / magnitude : 0;
        double reserved = c * c * q * q * k;   // B*, J; 0 without a count reserve
        double cap;
        if (!(available > 0)) {
            cap = 0;
        } else if (available < reserved) {
            cap = available / (c * q);
        } else {
            cap = Math.sqrt(2 * k * (available - reserved / 2));
        }
        double b = holdCompensation ? k * holdSeconds : 0;   // N s/m: the damping the hold takes away
        if (b > 0 && cap > 0 && magnitude > 0 && b * q / tickSeconds <= LEAD_NOISE) {
            double outwards = (v[0] * f[0] + v[1] * f[1] + v[2] * f[2]) / magnitude;
            cap = Math.max(0, cap - b * outwards);
        }
        if (magnitude > cap) {
            double scale = cap / magnitude;
            f[0] *= scale;
            f[1] *= scale;
            f[2] *= scale;
            magnitude = cap;
        }
        // the step from the last force sent, as a vector, is at most the rise limit (rises, falls and turns)
        double dx = f[0] - last[0];
        double dy = f[1] - last[1];
        double dz = f[2] - last[2];
        double step = Math.sqrt(dx * dx + dy * dy + dz * dz);
        double r = rise;
        if (step > r) {
            double g = r / step;
            f[0] = last[0] + g * dx;
            f[1] = last[1] + g * dy;
            f[2] = last[2] + g * dz;
            magnitude = Math.sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
        }
        last[0] = f[0];
        last[1] = f[1];
        last[2] = f[2];
        // what the force sent needs, by the inverse of the cap, is the most the budget keeps
        double need = magnitude < c * q * k ? c * q * magnitude : magnitude * magnitude / (2 * k) + reserved / 2;
        budget = Math.min(budget, trim * need);
    }
}
