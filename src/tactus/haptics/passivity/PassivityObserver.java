package tactus.haptics.passivity;

import tactus.haptics.HapticLoop;

/**
 * The passivity observer of a {@link HapticLoop}: the energy that flows through the haptic port, between the device
 * and the model (the avatar, with the virtual coupling and the passivity controller's damper when they are on), in
 * joules at the handle. Each tick the loop adds the work of the force it sent at the previous tick over the handle's
 * displacement since then, {@code -F(n-1)·(x(n) - x(n-1))}: the force is held between ticks (a zero-order hold) and
 * the displacement is measured, so the sum is the energy the held force really exchanged with the handle, to the
 * resolution of the position readings. Positions are metres and forces newtons along the device's axes whatever the
 * model's units, so the figures are joules for a model in REAL_UNITS and for one in ALGO_UNITS alike. On a device
 * whose states may answer late ({@link HapticLoop#setLateAnswerBound}, the Inverse3 by default) a tick with no new
 * state adds nothing, and a new state's displacement is charged to the force, among those that may have acted over
 * it, that puts the least energy into the model: the figures are then conservative (net energy at or below the true
 * one), not exact, and {@link #dissipated()} is the damper's share of the force charged, which may be negative.
 *
 * <p>Signs: energy <em>in</em> is energy the hand (through the device) gave to the model; energy <em>out</em> is
 * energy the model gave back to the hand. A passive model never gives back more than it was given: its
 * {@link #netEnergy()} stays at or above zero (Hannaford &amp; Ryu 2002). A sampled stiff wall does not: the hold
 * pushes the handle out a little harder than it was pushed in, and the difference is energy created at each touch.
 *
 * <p>Threads: written by the loop thread once per tick, read from any thread without a lock (each value is a
 * volatile field; two values read one after the other may come from two consecutive ticks). Nothing here allocates.
 */
public final class PassivityObserver {
    private volatile double lastTick;
    private volatile double energyIn;
    private volatile double energyOut;
    private volatile double dissipated;
    private volatile long ticks;
    private volatile long activeTicks;
    private volatile double damping;

    PassivityObserver() {
    }

    /** Clears every figure (the loop calls it when it starts). */
    void reset() {
        lastTick = 0;
        energyIn = 0;
        energyOut = 0;
        dissipated = 0;
        ticks = 0;
        activeTicks = 0;
        damping = 0;
    }

    /**
     * Records one tick: the energy that entered the model through the port since the last tick (J; negative when the
     * model gave energy to the hand) and the part of it the controller's damper dissipated (J).
     */
    void record(double intoModel, double damperDissipated) {
        lastTick = intoModel;
        if (intoModel >= 0) {
            energyIn = energyIn + intoModel;
        } else {
            energyOut = energyOut - intoModel;
        }
        dissipated = dissipated + damperDissipated;
        ticks = ticks + 1;
    }

    /** Records the damping (N s/m) the controller added at this tick's command, 0 when it was inactive. */
    void damping(double added) {
        damping = added;
        if (added > 0) {
            activeTicks = activeTicks + 1;
        }
    }

    /** Energy (J) that entered the model through the port during the last tick; negative when it went to the hand. */
    public double lastTick() {
        return lastTick;
    }

    /** Total energy (J) the hand gave to the model through the device since the loop started. */
    public double energyIn() {
        return energyIn;
    }

    /** Total energy (J) the model gave back to the hand since the loop started. */
    public double energyOut() {
        return energyOut;
    }

    /**
     * Energy in minus energy out (J): what the model holds or has dissipated. A passive model keeps it at or above 0;
     * below 0 the rendering has created energy, and the hand has received it.
     */
    public double netEnergy() {
        return energyIn - energyOut;
    }

    /** Total energy (J) the passivity controller's damper has dissipated (0 while the controller is off). */
    public double dissipated() {
        return dissipated;
    }

    /** The damping (N s/m) the passivity controller added at the last tick; 0 when it was inactive. */
    public double damping() {
        return damping;
    }

    /** Ticks observed since the loop started. */
    public long ticks() {
        return ticks;
    }

    /** Ticks at which the passivity controller added damping. */
    public long activeTicks() {
        return activeTicks;
    }

    /** The share of ticks (0..1) at which the passivity controller added damping; 0 before the first tick. */
    public double activeShare() {
        long n = ticks;
        return n == 0 ? 0 : (double) activeTicks / n;
    }

    @Override
    public String toString() {
        return String.format(java.util.Locale.ROOT, "in %.3g J, out %.3g J, net %.3g J, dissipated %.3g J, active %.2f %% of %d ticks",
                energyIn, energyOut, netEnergy(), dissipated, 100 * activeShare(), ticks);
    }
}
