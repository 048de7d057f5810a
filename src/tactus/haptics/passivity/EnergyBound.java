package tactus.haptics.passivity;

/**
 * Energy bounding of the port's force (after Kim &amp; Ryu): the force sent may never hold more energy, as a spring of
 * stiffness K, than the hand has put in through the port plus a small seed, {@code |F|^2 / (2 K) <= E + E0}. No
 * damper and no velocity multiplies the force, so the encoders' steps do not make it buzz.
 *
 * <p>The budget E is the port's ledger (the work of the held forces over the measured displacements, as the
 * {@link PassivityObserver} counts it, with the exchange delay), trimmed each tick to what the force sent holds,
 * {@code E <= |F|^2 / (2 K)}: energy the hand spent on the model's dampers, or in free space, is no reserve for a later
 * contact, so a contact that appears, moves or stiffens around the handle starts with the seed only. While the cap
 * binds, the force is a spring of slope K whose surface shifts inwards just enough to keep the budget: the energy the
 * hold and the delay create becomes a slow drift of the surface instead of an oscillation, and a contact stiffer than
 * K is felt as K. A rise of |F| is limited to a given step per tick (it only removes energy); falls are not limited.
 *
 * <p>The budget is kept at or above zero: a deficit is forgiven. With the 2DIY's encoders (about 0.15 mm per count at
 * the handle along y) the ledger charges a one-count flicker at the contact with |F| times a count, which can exceed
 * the whole stored energy near the surface; a budget left below zero would hold the force at zero for the rest of the
 * contact (measured: the wall vanished). The cost is that the hand may get up to the seed back per such event; the
 * energy the plant really gave the hand is what the tests bound. The cap reacts to a release one exchange late (it
 * does not predict the displacement: a prediction from the quantised velocity made force steps of 0.6-0.7 N).
 *
 * <p>One thread (the haptic loop's) calls everything but the setters; nothing allocates.
 */
final class EnergyBound {
    /** The default seed, J. */
    static final double DEFAULT_SEED = 1e-5;
    /** The default largest rise of the force per tick, N. */
    static final double DEFAULT_RISE = 0.5;

    private volatile double stiffness;                // N/m; 0: off
    private volatile double seed = DEFAULT_SEED;      // J
    private volatile double rise = DEFAULT_RISE;      // N per tick
    private boolean on;                               // what the loop's thread last saw
    private double budget;                            // J
    private double lastMagnitude;                     // |F| sent at the last tick, N

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

    /** Sets the largest rise of |F| per tick (N, > 0), from any thread. */
    void setRise(double newtons) {
        rise = newtons;
    }

    double rise() {
        return rise;
    }

    /** The budget E (J) as the loop's thread last left it. */
    double budget() {
        return budget;
    }

    void reset() {
        on = false;
        budget = 0;
        lastMagnitude = 0;
    }

    /** Adds the energy (J) that entered the model through the port during the last tick. */
    void observe(double intoModel) {
        budget += intoModel;
    }

    /** Caps the force f (N, in place) sent at this tick; returns the factor f was scaled by (1 when untouched). */
    double apply(double[] f) {
        double k = stiffness;
        double magnitude = Math.sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
        if (!(k > 0)) {
            on = false;
            lastMagnitude = magnitude;
            return 1;
        }
        if (!on) {
            on = true;
            budget = 0;   // switched on: a contact starts with the seed only, whatever came before
        }
        if (budget < 0) {
            budget = 0;
        }
        double cap = Math.min(Math.sqrt(2 * k * (budget + seed)), lastMagnitude + rise);
        double scale = 1;
        if (magnitude > cap) {
            scale = cap / magnitude;
            f[0] *= scale;
            f[1] *= scale;
            f[2] *= scale;
            magnitude = cap;
        }
        budget = Math.min(budget, magnitude * magnitude / (2 * k));
        lastMagnitude = magnitude;
        return scale;
    }
}
