package tactus.haptics;

import tactus.haptics.pantograph.PantographDevice;

/**
 * A haptic device as the {@link HapticLoop} sees it: the handle's position and velocity in metres (device axes)
 * in, a force in newtons out, one exchange per tick. Implemented by {@link PantographDevice} (the 2-DoF Haply
 * 2DIY and its predecessors, over a {@link Board}) and by {@link tactus.haptics.inverse.Inverse3Device} (the
 * 3-DoF Inverse3, Inverse3x and Minverse through Haply's Inverse Service).
 *
 * <p>Threads: {@link #begin()}, {@link #update()}, {@link #position}, {@link #velocity} and {@link #sendForce}
 * are called by one thread (the haptic loop's) and never wait for the device; {@link #zeroForce()} and
 * {@link #close()} may be called from any thread, and are bounded in time.
 */
public interface HapticDevice extends AutoCloseable {
    /** The axes the device moves in and pushes along: 2 for a planar pantograph (z is then always 0), or 3. */
    int dimensions();

    /** True when the device is set up and the loop may start (a board's device after its setup, a connected service). */
    boolean isReady();

    /** Asks for the first state, so that the first tick finds one. Called once by the loop thread before its first tick. */
    void begin();

    /**
     * Takes the newest state if one has arrived since the last call, without waiting; returns true if it did.
     *
     * @throws HaplyLinkException when the link to the device is lost, with a message that says what to check
     */
    boolean update();

    /**
     * How many ticks late, at most, a state may answer the force it follows (0: every new state answers the force
     * sent at the previous tick, or a fixed delay later), for the {@link HapticLoop}'s passivity account: above 0 the
     * loop charges each displacement to the worst of the forces that may have acted over it
     * ({@link HapticLoop#setLateAnswerBound}). The default is 0.
     */
    default int lateAnswerBound() {
        return 0;
    }

    /** The handle's position in metres along the device's axes, written into out[0..2]; NaN before the first state. */
    void position(double[] out);

    /** The handle's velocity in metres per second along the device's axes, written into out[0..2]. */
    void velocity(double[] out);

    /**
     * The position's quantum at the current pose: the largest change of the position along each axis when each of
     * the device's sensors moves by at most one count, in metres, written into out[0..2]. The default writes 0 (a
     * resolution too fine to matter, or unknown).
     */
    default void positionQuantum(double[] out) {
        out[0] = 0;
        out[1] = 0;
        out[2] = 0;
    }

    /**
     * Sends a force in newtons along the device's axes (a planar device ignores fz). The device may reduce it
     * to its own limits, keeping its direction.
     *
     * @throws HaplyLinkException when the link to the device is lost
     */
    void sendForce(double fx, double fy, double fz);

    /**
     * Whether the device can render a force where its handle is now: false at a pose its kinematics cannot reach (the
     * loop then counts a fault and sends zero force). The default is true.
     */
    default boolean canRender() {
        return true;
    }

    /**
     * The share of the last {@link #sendForce} that reached the handle (1: as asked; less when the device scaled it to
     * its limits or applied a gain; 0 when it sent none), for the loop's passivity account. The default is 1.
     */
    default double renderedShare() {
        return 1;
    }

    /** How many forces the device has scaled down to its limits since it was opened. The default is 0. */
    default long limitedForces() {
        return 0;
    }

    /** Sends zero force, from any thread, best effort and bounded in time; never throws. */
    void zeroForce();

    /** The default mapping from this device's metres to a model's axes (before scale and offset). */
    WorkspaceMapping defaultMapping();

    /** What the device is and where: for messages and banners, e.g. "Haply 2DIY on /dev/ttyACM0". */
    String describe();

    /** A one-line status (link, counters), for the telemetry line. */
    String status();

    /** Sends zero force and closes the link; idempotent, bounded in time. */
    @Override
    void close();
}
