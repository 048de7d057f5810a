package tactus.haptics.emulator;

import java.io.IOException;
import java.util.concurrent.locks.LockSupport;
import tactus.haptics.BoardModel;
import tactus.haptics.HaplyPreset;
import tactus.haptics.PantographKinematics;
import tactus.haptics.Transport;

/**
 * An emulated Haply board with a pantograph on it: the firmware ({@code Firmware}) drives a simulated
 * linkage whose handle is held by a {@link Hand}.
 *
 * <p>The linkage is a point mass at the handle (task space, default 0.05 kg) pushed by the motors through
 * F = J^-T tau and by the hand; joint angles follow by inverse kinematics. Time is real time by default, or
 * advances by a fixed step per write ({@link #setLockstep(double)}) for deterministic tests.
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
        while (time + SUBSTEP <= target + 1e-12) {
            step(SUBSTEP);
        }
    }

    private void step(double h) {
        time += h;
        hand.target(time, tmp);
        double nx;
        double ny;
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
            fx += hand.stiffness() * (tmp[0] - x) - (hand.damping() + friction) * vx;
            fy += hand.stiffness() * (tmp[1] - y) - (hand.damping() + friction) * vy;
            vx += fx / mass * h;
            vy += fy / mass * h;
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
