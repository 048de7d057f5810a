package tactus.haptics.pantograph;

import tactus.haptics.Board;
import tactus.haptics.BoardModel;
import tactus.haptics.Device;
import tactus.haptics.HapticDevice;
import tactus.haptics.HapticLoop;
import tactus.haptics.WorkspaceMapping;

/**
 * The 2-DoF Haply (2DIY, and the 2018 dev kit) as a {@link HapticDevice}: a set-up {@link Device} on its
 * {@link Board}, read through {@link PantographKinematics}. Position: the forward kinematics of the newest
 * encoder angles; velocity: the difference of the last two positions over the time between them; force: joint
 * torques tau = g J^T F, both scaled down by the same factor when one is above the torque limit (0.123 N m, the
 * firmware's clip, by default), so that the force keeps its direction. z is always 0 and fz is ignored.
 *
 * <p>The {@link HapticLoop} built on a {@code Device} (its first constructor) drives the 2DIY through one of these,
 * as it drives any other {@link HapticDevice}; this class also lets any code drive the 2DIY through the common interface.
 */
public final class PantographDevice implements HapticDevice {
    private final Device device;
    private final PantographKinematics kin;
    private final double[] tau = new double[2];
    private double torqueGain = 1;
    private double torqueLimit = BoardModel.MAX_TORQUE;
    private double x = Double.NaN;
    private double y = Double.NaN;
    private double vx;
    private double vy;
    private long lastNanos;
    private volatile long limited;
    private double share = 1;
    private volatile double torque1;
    private volatile double torque2;

    /** Wraps a device (encoders 1, 2 give theta1, theta2; actuators 1, 2 take tau1, tau2) and its kinematics. */
    public PantographDevice(Device device, PantographKinematics kinematics) {
        if (device == null || kinematics == null) {
            throw new IllegalArgumentException("PantographDevice: device and kinematics must not be null, got "
                    + device + ", " + kinematics);
        }
        this.device = device;
        this.kin = kinematics;
    }

    /** Sets the gain on J^T F (finite, >= 0; default 1, physical torques). */
    public void setTorqueGain(double gain) {
        if (!(gain >= 0) || !Double.isFinite(gain)) {
            throw new IllegalArgumentException("PantographDevice.setTorqueGain: gain must be a finite number >= 0, got " + gain);
        }
        torqueGain = gain;
    }

    /** Sets the largest joint torque in N m (0 &lt; limit &lt;= 0.123, the firmware's clip; default 0.123). */
    public void setTorqueLimit(double nm) {
        if (!(nm > 0) || nm > BoardModel.MAX_TORQUE) {
            throw new IllegalArgumentException("PantographDevice.setTorqueLimit: limit must be in (0, " + BoardModel.MAX_TORQUE
                    + "] N m, got " + nm);
        }
        torqueLimit = nm;
    }

    /** The wrapped device. */
    public Device device() {
        return device;
    }

    /** The kinematics, as of the last {@link #update()}. */
    public PantographKinematics kinematics() {
        return kin;
    }

    /** How many forces were scaled down to the torque limit. */
    @Override
    public long limitedForces() {
        return limited;
    }

    /** The torque in N m sent to joint j (1 or 2) by the last {@link #sendForce}. */
    public double torque(int joint) {
        return joint == 1 ? torque1 : torque2;
    }

    /** False before the first pose and at a pose the kinematics cannot reach (no force is rendered there). */
    @Override
    public boolean canRender() {
        return !Double.isNaN(x) && kin.isValid();
    }

    /**
     * The torque gain times the torque limit's scale at the last {@link #sendForce} (the force at the handle is
     * g J^-T tau), 0 when it sent no force.
     */
    @Override
    public double renderedShare() {
        return share;
    }

    @Override
    public int dimensions() {
        return 2;
    }

    @Override
    public boolean isReady() {
        return device.isConfigured();
    }

    @Override
    public void begin() {
        device.device_read_request();
    }

    /**
     * Takes the newest frame; true when one came. At a pose the kinematics cannot reach, the position stays the
     * last reachable one and {@link #canRender()} is false until the handle is back.
     */
    @Override
    public boolean update() {
        if (!device.poll_data()) {
            return false;
        }
        double th1 = Math.toRadians(device.angle(1));
        double th2 = Math.toRadians(device.angle(2));
        if (!kin.forward(th1, th2)) {
            return true;
        }
        long now = System.nanoTime();
        double nx = kin.x();
        double ny = kin.y();
        if (!Double.isNaN(x) && now != lastNanos) {
            double dt = (now - lastNanos) * 1e-9;
            vx = (nx - x) / dt;
            vy = (ny - y) / dt;
        }
        x = nx;
        y = ny;
        lastNanos = now;
        return true;
    }

    @Override
    public void position(double[] out) {
        out[0] = x;
        out[1] = y;
        out[2] = Double.isNaN(x) ? Double.NaN : 0;
    }

    @Override
    public void velocity(double[] out) {
        out[0] = vx;
        out[1] = vy;
        out[2] = 0;
    }

    /**
     * The position's quantum at the current pose: for each axis, the largest change that one count of each encoder
     * makes there (the sum over the encoders of the Jacobian's entry times 2 pi over the encoder's counts per turn:
     * both encoders may tick between two readings), in metres; z is 0, and so is every axis before the first
     * reachable pose.
     */
    @Override
    public void positionQuantum(double[] out) {
        out[2] = 0;
        if (Double.isNaN(x) || !kin.isValid()) {
            out[0] = 0;
            out[1] = 0;
            return;
        }
        kin.quantum(countAngle(1), countAngle(2), out);
    }

    /** One count of this encoder, in radians (0 when it has no valid resolution). */
    private double countAngle(int encoder) {
        double r = device.resolution(encoder);
        return r > 0 ? 2 * Math.PI / r : 0;
    }

    @Override
    public void sendForce(double fx, double fy, double fz) {
        if (!canRender() || !Double.isFinite(fx) || !Double.isFinite(fy)) {
            share = 0;
            write(0, 0);
            return;
        }
        if (fx == 0 && fy == 0) {
            share = torqueGain;
            write(0, 0);                     // exact zeros (J^T 0 may give -0.0)
            return;
        }
        kin.torques(fx, fy, torqueGain, tau);
        double m = Math.max(Math.abs(tau[0]), Math.abs(tau[1]));
        double scale = torqueGain;
        if (m > torqueLimit) {
            double s = torqueLimit / m;
            tau[0] *= s;
            tau[1] *= s;
            scale *= s;
            limited++;
        }
        share = scale;
        write(tau[0], tau[1]);
    }

    private void write(double t1, double t2) {
        torque1 = t1;
        torque2 = t2;
        device.set_actuator_torque(1, (float) t1);
        device.set_actuator_torque(2, (float) t2);
        device.device_write_torques();
    }

    @Override
    public void zeroForce() {
        try {
            device.board().zeroTorques();
        } catch (RuntimeException e) {
            // best effort: the board reports its own failures once
        }
    }

    @Override
    public WorkspaceMapping defaultMapping() {
        return WorkspaceMapping.pantograph();
    }

    @Override
    public String describe() {
        return "Haply pantograph on " + device.board().describe();
    }

    @Override
    public String status() {
        Board b = device.board();
        return b.isClosed() ? "closed" + (b.lostReason() != null ? " (" + b.lostReason() + ")" : "") : "open";
    }

    @Override
    public void close() {
        device.board().close();
    }
}
