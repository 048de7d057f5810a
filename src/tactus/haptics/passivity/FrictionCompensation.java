package tactus.haptics.passivity;

import tactus.haptics.HapticLoop;

/**
 * Friction compensation for the motors' torque threshold: a small force pushed along the handle's motion, so that the
 * hand does not have to break the Coulomb friction of the motors and belts itself. The velocity is low-pass filtered
 * (the encoders' counts make the raw difference noisy); below the deadband speed nothing is added, so a handle at rest
 * does not creep, and the force ramps up to its full value at twice the deadband. It adds energy by design: set it at
 * or below the friction the device really has (measured as the force that just starts the handle moving), or it
 * pushes the hand. The loop adds it outside the observed port: the {@link PassivityObserver} does not count it.
 *
 * <p>Immutable settings; give them to {@link HapticLoop#setFrictionCompensation(FrictionCompensation)}.
 */
public final class FrictionCompensation {
    private final double force;
    private final double deadband;
    private final double cutoffHz;

    /**
     * Compensation of this force (N, >= 0) above this speed (m/s, > 0), with the velocity filtered at this cut-off
     * (Hz, > 0).
     *
     * @throws IllegalArgumentException naming the value when one is out of range or not finite
     */
    public FrictionCompensation(double force, double deadband, double cutoffHz) {
        if (!(force >= 0) || !Double.isFinite(force)) {
            throw new IllegalArgumentException("FrictionCompensation: force must be a finite number >= 0 N, got " + force);
        }
        if (!(deadband > 0) || !Double.isFinite(deadband)) {
            throw new IllegalArgumentException("FrictionCompensation: deadband must be a finite number > 0 m/s, got " + deadband);
        }
        if (!(cutoffHz > 0) || !Double.isFinite(cutoffHz)) {
            throw new IllegalArgumentException("FrictionCompensation: cutoff must be a finite number > 0 Hz, got " + cutoffHz);
        }
        this.force = force;
        this.deadband = deadband;
        this.cutoffHz = cutoffHz;
    }

    /** Compensation of this force (N) with a 5 mm/s deadband and the velocity filtered at 30 Hz. */
    public FrictionCompensation(double force) {
        this(force, 0.005, 30);
    }

    /** The force added along the motion, N. */
    public double force() {
        return force;
    }

    /** The speed below which nothing is added, m/s. */
    public double deadband() {
        return deadband;
    }

    /** The velocity filter's cut-off, Hz. */
    public double cutoffHz() {
        return cutoffHz;
    }

    /**
     * The force (N) to add along a filtered velocity of this speed (m/s, >= 0): 0 up to the deadband, the full force
     * from twice the deadband, linear in between.
     */
    public double forceAt(double speed) {
        if (speed <= deadband) {
            return 0;
        }
        return force * Math.min(1, (speed - deadband) / deadband);
    }

    @Override
    public String toString() {
        return "FrictionCompensation(" + force + " N above " + deadband + " m/s, filter " + cutoffHz + " Hz)";
    }
}
