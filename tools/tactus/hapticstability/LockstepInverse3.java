package tactus.hapticstability;

import tactus.haptics.HapticDevice;
import tactus.haptics.WorkspaceMapping;
import tactus.haptics.emulator.SimulatedInverse3;

/**
 * The emulated Inverse3 ({@link SimulatedInverse3}, with its {@link tactus.haptics.emulator.DevicePlant}) as a
 * {@link HapticDevice} that runs in lockstep with the haptic loop, exchanging in the order the Inverse Service
 * emulator does ({@code InverseServiceEmulator.handle}): each force the loop sends is applied at once, the device
 * advances by one period T, and the state it reaches is what the loop reads at its next tick. So the force computed
 * from the position read at tick n acts from tick n to tick n + 1: a zero-order hold with no tick of delay (d = 0),
 * as on the emulator's WebSocket path whenever its reply arrives within the tick.
 *
 * <p>What it leaves out of that path: the WebSocket and JSON (which only carry the numbers), the emulator's 10 ms
 * force hold (never reached: a force comes every tick) and {@code Inverse3Device}'s 100 ms start ramp, which is timed
 * by the wall clock and would make a run depend on it. Everything here runs on the loop's thread, so a run depends
 * only on the tick count.
 *
 * <p>It keeps the exact work of the held forces on the handle ({@link #work()}: F(n) · (x(n+1) - x(n)), joules,
 * energy given to the handle) and calls a {@link Listener} after each tick (the rig's recorder, and the offline
 * audio renderer in AUDIO mode).
 */
public final class LockstepInverse3 implements HapticDevice {
    /** Called on the loop's thread after each tick's advance. */
    public interface Listener {
        /**
         * @param tick the tick just run (0 for the loop's first request)
         * @param position the handle's position at its end, metres
         * @param force the force held over it, newtons
         */
        void afterTick(long tick, double[] position, double[] force);
    }

    private final SimulatedInverse3 device;
    private final double period;
    private final double[] position = new double[3];
    private final double[] velocity = new double[3];
    private final double[] before = new double[3];
    private final double[] held = new double[3];
    private volatile Listener listener;
    private boolean fresh;
    private long tick;
    private double work;
    private double lastWork;

    /** Runs this device with this period (seconds, > 0) per exchange. */
    public LockstepInverse3(SimulatedInverse3 device, double periodSeconds) {
        if (device == null || !(periodSeconds > 0)) {
            throw new IllegalArgumentException("LockstepInverse3: need a device and a period > 0 s, got " + periodSeconds);
        }
        this.device = device;
        this.period = periodSeconds;
        device.position(position);
    }

    /** Sets what is called after each tick (null: nothing). */
    public void setListener(Listener l) {
        listener = l;
    }

    /** The work the held forces did on the handle so far, joules (energy the device gave to the handle). */
    public double work() {
        return work;
    }

    /**
     * The work of the held forces on the handle up to the position the loop read last, joules: {@link #work()}
     * without the last exchange, whose displacement the loop has not read yet (what its observer can have seen).
     */
    public double workSeen() {
        return work - lastWork;
    }

    /** The exchanges so far. */
    public long ticks() {
        return tick;
    }

    @Override
    public int dimensions() {
        return 3;
    }

    @Override
    public boolean isReady() {
        return true;
    }

    @Override
    public void begin() {
        sendForce(0, 0, 0);   // as Inverse3Device: the first exchange gives the first state
    }

    @Override
    public boolean update() {
        boolean f = fresh;
        fresh = false;
        return f;
    }

    @Override
    public void position(double[] out) {
        out[0] = position[0];
        out[1] = position[1];
        out[2] = position[2];
    }

    @Override
    public void velocity(double[] out) {
        out[0] = velocity[0];
        out[1] = velocity[1];
        out[2] = velocity[2];
    }

    @Override
    public void sendForce(double fx, double fy, double fz) {
        held[0] = fx;
        held[1] = fy;
        held[2] = fz;
        device.setForce(fx, fy, fz);
        device.position(before);
        device.advance(period);
        device.position(position);
        device.velocity(velocity);
        lastWork = fx * (position[0] - before[0]) + fy * (position[1] - before[1]) + fz * (position[2] - before[2]);
        work += lastWork;
        fresh = true;
        Listener l = listener;
        if (l != null) {
            l.afterTick(tick, position, held);
        }
        tick++;
    }

    @Override
    public void zeroForce() {
        device.setForce(0, 0, 0);
    }

    @Override
    public WorkspaceMapping defaultMapping() {
        return WorkspaceMapping.identity();
    }

    @Override
    public String describe() {
        return "emulated Inverse3 in lockstep (" + period * 1e3 + " ms a tick)";
    }

    @Override
    public String status() {
        return describe();
    }

    @Override
    public void close() {
        device.setForce(0, 0, 0);
    }
}
