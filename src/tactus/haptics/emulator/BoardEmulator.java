package tactus.haptics.emulator;

import java.io.IOException;
import java.util.concurrent.locks.LockSupport;
import tactus.haptics.BoardModel;
import tactus.haptics.HaplyPreset;
import tactus.haptics.pantograph.PantographKinematics;
import tactus.haptics.transport.Transport;

/**
 * An emulated Haply board with a pantograph on it: the firmware ({@code Firmware}) drives a simulated
 * linkage whose handle is held by a {@link Hand}.
 *
 * <p>The linkage is a point mass at the handle (task space, default 0.05 kg) pushed by the motors through
 * F = J^-T tau and by the hand; joint angles follow by inverse kinematics. With {@link #setPlant} it is instead a
 * {@link DevicePlant}: joint and rotor inertia, viscous damping, Coulomb friction with a static threshold and an
 * actuation delay, integrated at the plant's substep (20 kHz by default). Time is real time by default, or
 * advances by a fixed step per write ({@link #setLockstep(double)}) for deterministic tests: the torques of a
 * write then act over exactly the next step, and the reply carries the encoders at the write's instant, so the
 * host's next torque is computed from a position one step old, as on the real board.
 *
 * <p>Reach it in-process with {@link #connect()} (each write is handled at once and its reply is readable
 * when the write returns), or over any {@link Transport} with {@link #serve(Transport)}, for instance one end
 * of a {@link PtyPair}, where it runs the firmware's loop on its own thread (one command per pass, a pass at
 * most every 50 microseconds; when idle it sleeps in {@link Transport#readWaiting} until the host writes).
 */
public final class BoardEmulator implements AutoCloseable {
    private static final double SUBSTEP = 1e-4;
    private static final long PASS_NANOS = 50_000;

    private final HaplyPreset preset;
    private final BoardModel model;
    private final PantographKinematics kin;
    private final int[] jointAtPort = new int[5];  // joint (0/1) whose encoder is on the port, or -1
    private final int[] jointOfMotorPort = new int[5];
    private final ByteRing firmwareIn = new ByteRing();
    private final ByteRing hostIn = new ByteRing();
    private final Firmware firmware;
    private final long t0 = System.nanoTime();

    private Hand hand;
    private double mass = 0.05;
    private double friction = 0.5;       // N s/m, bearings and belts
    private double lockstep;             // seconds per write, 0 = real time
    private double time;                 // simulated seconds
    private volatile double x;
    private volatile double y;
    private double vx;
    private double vy;
    private final double[] theta = new double[2];     // joint angles, radians
    private final double[] tau = new double[2];       // physical joint torques, N m
    private final double[] tmp = new double[2];
    private final double[] force = new double[2];

    private volatile boolean unplugged;
    private volatile Thread server;
    private volatile Transport served;
    private volatile Firmware.Output output;
    private DevicePlant plant;            // null: the point mass of the constructor
    private double substep = SUBSTEP;
    private boolean torqueChanged;
    private Probe probe;
    private boolean hasPrevTarget;
    private final double[] prevTarget = new double[2];
    private final double[] handForce = new double[2];
    private final double[] plantBuf = new double[2];
    private int dropReplies;
    private final double[] analog = new double[12];

    /** An M0 board wired as the preset's hardware, the handle at the calibration pose, a following hand there. */
    public BoardEmulator(HaplyPreset preset) {
        this(preset, BoardModel.M0);
    }

    /** A board of the given model wired as the preset's hardware. */
    public BoardEmulator(HaplyPreset preset, BoardModel model) {
        if (preset == null || model == null) {
            throw new IllegalArgumentException("BoardEmulator: preset and model must not be null");
        }
        this.preset = preset;
        this.model = model;
        this.kin = preset.newKinematics();
        java.util.Arrays.fill(jointAtPort, -1);
        java.util.Arrays.fill(jointOfMotorPort, -1);
        for (int j = 1; j <= 2; j++) {
            jointAtPort[preset.encoderPort(j)] = j - 1;
            jointOfMotorPort[preset.motorPort(j)] = j - 1;
        }
        theta[0] = Math.toRadians(preset.encoderOffset(1));
        theta[1] = Math.toRadians(preset.encoderOffset(2));
        kin.forward(theta[0], theta[1]);
        x = kin.x();
        y = kin.y();
        hand = Hand.following(x, y, 300, 3);
        output = hostIn::put;
        firmware = new Firmware(model, firmwareIn, new Wiring(), (d, off, len) -> deliver(d, off, len));
    }

    /** The hardware preset this emulator is wired as. */
    public HaplyPreset preset() {
        return preset;
    }

    /** Sets the hand that holds the handle. */
    public synchronized void setHand(Hand hand) {
        if (hand == null) {
            throw new IllegalArgumentException("BoardEmulator.setHand: hand must not be null");
        }
        this.hand = hand;
    }

    /** The hand that holds the handle. */
    public synchronized Hand hand() {
        return hand;
    }

    /** Sets the moving mass at the handle in kg (> 0). */
    public synchronized void setHandleMass(double kg) {
        if (!(kg > 0) || !Double.isFinite(kg)) {
            throw new IllegalArgumentException("BoardEmulator.setHandleMass: mass must be a finite number > 0 kg, got " + kg);
        }
        mass = kg;
    }

    /**
     * Replaces the point mass with a {@link DevicePlant} of these parameters on this preset's pantograph, at the
     * handle's present pose, at rest. The plant's substep becomes the integration step.
     */
    public synchronized void setPlant(PlantParameters parameters) {
        if (parameters == null) {
            throw new IllegalArgumentException("BoardEmulator.setPlant: parameters must not be null");
        }
        plant = new DevicePlant(parameters, new PantographPlantKinematics(preset.l(), preset.bigL(), preset.d()),
                theta);
        plant.commandTorques(tau);
        substep = parameters.substep();
        vx = 0;
        vy = 0;
    }

    /** The device plant set with {@link #setPlant}, or null while the handle is the constructor's point mass. */
    public synchronized DevicePlant plant() {
        return plant;
    }

    /**
     * Puts the handle at rest at (x, y) in metres (for instance after the setup, which presets the encoders at
     * the calibration pose: the encoders then count the move). Returns false (nothing changed) if out of reach.
     */
    public synchronized boolean place(double px, double py) {
        tmp[0] = px;
        tmp[1] = py;
        if (plant != null) {
            if (!plant.place(tmp)) {
                return false;
            }
            theta[0] = plant.q(0);
            theta[1] = plant.q(1);
        } else {
            if (!kin.inverse(px, py, tmp)) {
                return false;
            }
            theta[0] = tmp[0];
            theta[1] = tmp[1];
        }
        x = px;
        y = py;
        vx = 0;
        vy = 0;
        hasPrevTarget = false;
        return true;
    }

    /** What a {@link Probe} sees at every integration step. */
    public interface Probe {
        /**
         * One integration step: time (s), handle position (m) and velocity (m/s), and the force the hand puts on
         * the handle (N; 0 for a rigid or no hand). Called on the thread that advances the emulator (in-process:
         * the writer's); must not allocate or block.
         */
        void sample(double t, double x, double y, double vx, double vy, double handFx, double handFy);
    }

    /** Sets a probe called at every integration step (null for none). */
    public synchronized void setProbe(Probe p) {
        probe = p;
    }

    /** Handle velocity along x in m/s. */
    public synchronized double vx() {
        return vx;
    }

    /** Handle velocity along y in m/s. */
    public synchronized double vy() {
        return vy;
    }

    /** Advances simulated time by a fixed step per write (seconds, > 0) instead of real time. */
    public synchronized void setLockstep(double secondsPerWrite) {
        if (!(secondsPerWrite > 0) || !Double.isFinite(secondsPerWrite)) {
            throw new IllegalArgumentException("BoardEmulator.setLockstep: step must be a finite number > 0 s, got " + secondsPerWrite);
        }
        lockstep = secondsPerWrite;
    }

    /** A host-side transport to this board, handled in the caller's thread: a reply is readable when write returns. */
    public Transport connect() {
        return new InProcess();
    }

    /**
     * Runs the firmware loop on its own thread, reading commands from and writing replies to a board-side
     * transport (for instance one end of a {@link PtyPair}). Stops on {@link #close()} or {@link #unplug()}.
     */
    public synchronized void serve(Transport boardSide) {
        if (server != null) {
            throw new IllegalStateException("BoardEmulator.serve: already serving " + served.describe());
        }
        served = boardSide;
        output = (d, off, len) -> {
            try {
                boardSide.write(d, off, len);
            } catch (IOException e) {
                unplugged = true;
            }
        };
        Thread t = new Thread(() -> serveLoop(boardSide), "tactus-board-emulator");
        t.setDaemon(true);
        server = t;
        t.start();
    }

    private void serveLoop(Transport boardSide) {
        byte[] buf = new byte[256];
        long lastPass = 0;
        try {
            while (!unplugged) {
                int n = boardSide.available();
                if (n > 0) {
                    int r = boardSide.read(buf, 0, Math.min(n, buf.length));
                    firmwareIn.put(buf, 0, r);
                }
                long now = System.nanoTime();
                if (now - lastPass >= PASS_NANOS) {
                    lastPass = now;
                    boolean busy;
                    synchronized (this) {
                        busy = firmware.pass(now);
                    }
                    if (!busy && n <= 0) {
                        // idle: sleep until the host writes (no polling: this thread shares the host's cores,
                        // which a real board never does); the transport wakes it as soon as a byte arrives
                        int r = boardSide.readWaiting(buf, 0, buf.length);
                        if (r > 0) {
                            firmwareIn.put(buf, 0, r);
                        }
                    }
                } else {
                    LockSupport.parkNanos(PASS_NANOS - (now - lastPass));
                }
            }
        } catch (IOException e) {
            // the link is gone (the host closed its end): the bytes that did arrive are still handled, as a
            // board handles what it received before the cable went (the host's last write is its zero torques)
            synchronized (this) {
                long now = System.nanoTime();
                while (firmware.pass(now)) {
                    // every complete command
                }
            }
            unplugged = true;
        } finally {
            boardSide.close();
        }
    }

    /** Pulls the plug: host transports fail from now on and a serving thread stops and closes its transport. */
    public void unplug() {
        unplugged = true;
        Thread t = server;
        if (t != null) {
            try {
                t.join(1000);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
    }

    /** True once {@link #unplug()} was called or the served link failed. */
    public boolean isUnplugged() {
        return unplugged;
    }

    @Override
    public void close() {
        unplug();
    }

    // ----------------------------------------------------------------------------------- fault injection

    /** Puts raw bytes in front of the host, as if the board had sent them (stray or partial frames). */
    public void injectToHost(byte[] bytes) {
        deliverRaw(bytes, 0, bytes.length);
    }

    /**
     * Sets the raw ADC value of analog input An (0..11). The M0 firmware reads only A1 and A2; the others
     * it reports as 0.
     */
    public synchronized void setAnalog(int n, double value) {
        if (n < 0 || n >= analog.length) {
            throw new IllegalArgumentException("BoardEmulator.setAnalog: input must be 0..11, got " + n);
        }
        analog[n] = value;
    }

    /** Swallows the next n replies (the board answers, the bytes never arrive). */
    public synchronized void dropReplies(int n) {
        dropReplies = n;
    }

    // ----------------------------------------------------------------------------------- observation

    /** Handle x in metres (device coordinates). */
    public double x() {
        return x;
    }

    /** Handle y in metres. */
    public double y() {
        return y;
    }

    /** Physical angle of joint j (1 or 2) in degrees. */
    public synchronized double jointDegrees(int joint) {
        return Math.toDegrees(theta[joint - 1]);
    }

    /** Physical torque of joint j's motor in N m, as the firmware's duty and direction pin make it. */
    public synchronized double motorTorque(int joint) {
        return tau[joint - 1];
    }

    /** The PWM duty (0..pwmResolution) of the motor on a port (1-based). */
    public synchronized int duty(int port) {
        return firmware.duty(port);
    }

    /** True if the direction pin of the motor on a port is HIGH. */
    public synchronized boolean directionPinHigh(int port) {
        return firmware.directionHigh(port);
    }

    /** The pulse byte (0..255) last written to a PWM pin. */
    public synchronized int pwmPulse(int pin) {
        return firmware.pwmPulse(pin);
    }

    /** The angle in degrees the encoder on a port reports now. */
    public synchronized float encoderAngle(int port) {
        return firmware.angle(port - 1);
    }

    /** Number of setups received. */
    public synchronized long setups() {
        return firmware.setups;
    }

    /** Number of resets received. */
    public synchronized long resets() {
        return firmware.resets;
    }

    /** Number of writes applied to the configured device. */
    public synchronized long writes() {
        return firmware.writes;
    }

    /** Number of writes for another id (answered with the id alone; payload read as commands). */
    public synchronized long foreignWrites() {
        return firmware.foreignWrites;
    }

    /** Number of single-byte fields that had not arrived when read (read as 0xFF). */
    public synchronized long lateBytes() {
        return firmware.lateBytes;
    }

    /** Number of unknown command bytes dropped. */
    public synchronized long unknownBytes() {
        return firmware.unknownBytes;
    }

    /** Number of replies sent. */
    public synchronized long replies() {
        return firmware.replies;
    }

    /** True once the emulated firmware has stopped as after a HardFault (an id-0 write read an encoder never set up). */
    public synchronized boolean hasFaulted() {
        return firmware.hardFault();
    }

        /** The id of the configured device, or -1. */
    public synchronized int configuredId() {
        return firmware.configuredId();
    }

    /** Simulated time in seconds. */
    public synchronized double time() {
        return time;
    }

    // ----------------------------------------------------------------------------------- internals

    private synchronized void pump() {
        long now = System.nanoTime();
        while (firmware.pass(now)) {
            // handle every command that is complete
        }
    }

    private void deliver(byte[] d, int off, int len) {
        synchronized (this) {
            if (dropReplies > 0) {
                dropReplies--;
                return;
            }
        }
        deliverRaw(d, off, len);
    }

    private void deliverRaw(byte[] d, int off, int len) {
        if (unplugged) {
            return;
        }
        output.write(d, off, len);
    }

    private synchronized void advance() {
        double target = lockstep > 0 ? time + lockstep : (System.nanoTime() - t0) * 1e-9;
        if (plant != null && torqueChanged) {
            plant.commandTorques(tau);   // the write's torques, from the write's instant
            torqueChanged = false;
        }
        double h = substep;
        while (time + h <= target + 1e-12) {
            if (plant != null) {
                stepPlant(h);
            } else {
                step(h);
            }
        }
    }

    private void stepPlant(double h) {
        time += h;
        Hand hd = hand;
        hd.target(time, tmp);
        double tx = tmp[0];
        double ty = tmp[1];
        handForce[0] = 0;
        handForce[1] = 0;
        if (hd.isRigid()) {
            plant.moveRigidly(tmp, h);
        } else {
            if (!hd.isNone()) {
                double k = hd.stiffness();
                double b = hd.damping();
                double tvx = 0;
                double tvy = 0;
                if (hd.dampsRelativeVelocity() && hasPrevTarget) {
                    tvx = (tx - prevTarget[0]) / h;
                    tvy = (ty - prevTarget[1]) / h;
                }
                handForce[0] = k * (tx - x) + b * (tvx - vx);
                handForce[1] = k * (ty - y) + b * (tvy - vy);
            }
            plant.step(h, handForce, hd.mass());
        }
        prevTarget[0] = tx;
        prevTarget[1] = ty;
        hasPrevTarget = true;
        theta[0] = plant.q(0);
        theta[1] = plant.q(1);
        plant.position(plantBuf);
        x = plantBuf[0];
        y = plantBuf[1];
        plant.velocity(plantBuf);
        vx = plantBuf[0];
        vy = plantBuf[1];
        Probe pr = probe;
        if (pr != null) {
            pr.sample(time, x, y, vx, vy, handForce[0], handForce[1]);
        }
    }

    private void step(double h) {
        time += h;
        hand.target(time, tmp);
        double nx;
        double ny;
        handForce[0] = 0;
        handForce[1] = 0;
        if (hand.isRigid()) {
            nx = tmp[0];
            ny = tmp[1];
            vx = (nx - x) / h;
            vy = (ny - y) / h;
        } else {
            kin.forward(theta[0], theta[1]);
            double fx = 0;
            double fy = 0;
            if (kin.isValid()) {
                kin.forceFromTorques(tau[0], tau[1], force);
                if (Double.isFinite(force[0]) && Double.isFinite(force[1])) {
                    fx = force[0];
                    fy = force[1];
                }
            }
            double tvx = 0;
            double tvy = 0;
            if (hand.dampsRelativeVelocity() && hasPrevTarget) {
                tvx = (tmp[0] - prevTarget[0]) / h;
                tvy = (tmp[1] - prevTarget[1]) / h;
            }
            prevTarget[0] = tmp[0];
            prevTarget[1] = tmp[1];
            hasPrevTarget = true;
            double hfx = hand.stiffness() * (tmp[0] - x) + hand.damping() * (tvx - vx);
            double hfy = hand.stiffness() * (tmp[1] - y) + hand.damping() * (tvy - vy);
            handForce[0] = hfx;
            handForce[1] = hfy;
            fx += hfx - friction * vx;
            fy += hfy - friction * vy;
            double m = mass + hand.mass();
            vx += fx / m * h;
            vy += fy / m * h;
            nx = x + vx * h;
            ny = y + vy * h;
        }
        if (kin.inverse(nx, ny, tmp)) {
            theta[0] = tmp[0];
            theta[1] = tmp[1];
            x = nx;
            y = ny;
        } else {
            vx = 0;
            vy = 0;   // the linkage hits the end of its reach
        }
        Probe pr = probe;
        if (pr != null) {
            pr.sample(time, x, y, vx, vy, handForce[0], handForce[1]);
        }
    }

    private final class Wiring implements Firmware.Hardware {
        @Override
        public double jointDeg(int port) {
            int j = port < jointAtPort.length ? jointAtPort[port] : -1;
            return j < 0 ? 0 : Math.toDegrees(theta[j]);
        }

        @Override
        public void motorTorque(int port, double torque) {
            int j = port < jointOfMotorPort.length ? jointOfMotorPort[port] : -1;
            if (j >= 0) {
                tau[j] = torque;
                torqueChanged = true;
            }
        }

        @Override
        public double analog(int n) {
            return n >= 0 && n < analog.length ? analog[n] : 0;
        }

        @Override
        public void beforeWrite() {
            advance();
        }
    }

    /** The in-process host end: writes run the firmware at once. */
    private final class InProcess implements Transport {
        private volatile boolean closed;

        @Override
        public void write(byte[] data, int offset, int length) throws IOException {
            check();
            firmwareIn.put(data, offset, length);
            pump();
        }

        @Override
        public int available() throws IOException {
            check();
            return hostIn.size();
        }

        @Override
        public int read(byte[] buffer, int offset, int length) throws IOException {
            check();
            return hostIn.take(buffer, offset, length);
        }

        private void check() throws IOException {
            if (closed) {
                throw new IOException("emulator link closed");
            }
            if (unplugged) {
                throw new IOException("the emulated board was unplugged");
            }
        }

        @Override
        public void close() {
            closed = true;
        }

        @Override
        public String describe() {
            return "emulator";
        }
    }
}
