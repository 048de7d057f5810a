package tactus.haptics.safety;

import com.fazecast.jSerialComm.SerialPort;
import java.io.IOException;
import java.nio.file.Paths;
import java.util.List;
import tactus.haptics.Device;
import tactus.haptics.transport.SerialTransport;
import tactus.haptics.transport.Transport;

/**
 * The board's side of the {@link MotorGuard}: starts the guard process when a board opens a serial port (before
 * the port itself, so that the guard holds it open for writing first), shares a {@link GuardHeartbeat} with it,
 * tells it the port and each device's setup, and says {@code clean} when the board closed with the torques
 * zeroed and answered.
 * Starting or talking to the guard never fails the board: a failure prints one warning and the board runs
 * without the guard.
 *
 * <p>Not API: public only for {@link tactus.haptics.Board}.
 */
public final class MotorGuardLink {
    /** System property that turns the guard off when "false" (default on). */
    static final String PROPERTY = "tactus.motorGuard";
    /** The link of a board without a guard (in-process transports, or the guard turned off). */
    static final MotorGuardLink NONE = new MotorGuardLink(null, GuardHeartbeat.NONE);
    /**
     * How long the sketch's JVM may give no heartbeat, while a torque is on, before the guard zeroes the motors,
     * in milliseconds. A running JVM beats at every torque write and at least every 5 ms (the board's watchdog
     * thread), yet on the loaded 2-core machine, at normal priority, its threads were seen to get no CPU for up
     * to 53 ms (longest gap in 4 runs of 20 s, load average 8 to 12, with and without a CPU hog and 100 MB/s of
     * garbage; GC pauses were 2 to 6 ms): twice that, so that a busy machine does not make the force dip, and
     * still short beside a debugger's pause (see docs/haptics.md, "The motor guard").
     */
    static final int HEARTBEAT_STALE_MS = 100;
    /** How long opening a port waits for the guard to hold it for writing, in milliseconds (then it opens anyway). */
    static final long READY_WAIT_MS = 3_000;

    private static volatile boolean enabled = !"false".equalsIgnoreCase(System.getProperty(PROPERTY, "true"));
    /** JVM options of the guard: small heap, no JIT, no perf data (it waits, then sends a few bytes). */
    private static final String[] JVM_OPTIONS = {"-Xint", "-XX:+UseSerialGC", "-Xms4m", "-Xmx16m", "-Xss256k",
            "-XX:-UsePerfData", "-Djava.awt.headless=true"};
    /** Properties passed on to the guard so that it finds jSerialComm's native library as the sketch did. */
    private static final String[] INHERITED_PROPERTIES = {"java.io.tmpdir", "fazecast.jSerialComm.appid",
            "jSerialComm.library.path", "jSerialComm.library.randomizeNativeName", "os.arch_full"};

    private final GuardProcess guard;   // null for NONE
    private final GuardHeartbeat heartbeat;

    private MotorGuardLink(GuardProcess guard, GuardHeartbeat heartbeat) {
        this.guard = guard;
        this.heartbeat = heartbeat;
    }

    /** A serial port opened with its guard. */
    public static final class Opened {
        /** The port, opened after the guard. */
        public final SerialTransport transport;
        /** The guard watching the port ({@link #NONE} without one). */
        public final MotorGuardLink guard;

        /** Pairs a port with its guard. */
        public Opened(SerialTransport transport, MotorGuardLink guard) {
            this.transport = transport;
            this.guard = guard;
        }
    }

    /**
     * Opens a serial port with a guard: starts the guard first and waits (up to {@link #READY_WAIT_MS}) until it
     * holds the port open for writing, then opens the port (so that the guard's descriptor exists before an
     * exclusive open could refuse it). Throws as {@link SerialTransport#open} does, with the guard told to leave.
     */
    public static Opened openPort(String portName, int baud) {
        MotorGuardLink link = NONE;
        boolean windows = System.getProperty("os.name", "").toLowerCase(java.util.Locale.ROOT).startsWith("windows");
        String path = systemPath(portName);
        if (enabled && path != null && (windows || java.nio.file.Files.exists(Paths.get(path)))) {
            link = start(path, baud);
            link.awaitReady(READY_WAIT_MS);
        }
        try {
            return new Opened(SerialTransport.open(portName, baud), link);
        } catch (RuntimeException e) {
            link.release(true);   // the port was never ours: nothing to zero
            throw e;
        }
    }

    /** Turns the guard on or off for boards opened from now on (the property {@value #PROPERTY} sets the default). */
    public static void setEnabled(boolean on) {
        enabled = on;
    }

    /** True if boards opened from now on start a guard. */
    static boolean isEnabled() {
        return enabled;
    }

    /** The port's path as jSerialComm opens it ("ttyACM0" is "/dev/ttyACM0" on Linux), or null if none. */
    private static String systemPath(String portName) {
        if (portName == null || portName.isEmpty()) {
            return null;
        }
        try {
            String p = SerialPort.getCommPort(portName).getSystemPortPath();
            return p == null || p.isEmpty() ? portName : p;
        } catch (RuntimeException e) {
            return portName;
        }
    }

    /**
     * Starts a guard for a board on a serial transport that is already open; {@link #NONE} for other transports or
     * when turned off. The guard opens the port for writing after the transport (which works with jSerialComm,
     * whose open takes an advisory lock only).
     */
    public static MotorGuardLink watch(Transport transport) {
        if (!enabled || !(transport instanceof SerialTransport)) {
            return NONE;
        }
        SerialTransport serial = (SerialTransport) transport;
        String path = systemPath(serial.describe());
        return start(path == null ? serial.describe() : path, serial.baudRate());
    }

    /** Starts a guard and tells it the heartbeat and the port. */
    private static MotorGuardLink start(String portName, int baud) {
        GuardHeartbeat heartbeat = GuardHeartbeat.NONE;
        try {
            heartbeat = GuardHeartbeat.create();
        } catch (IOException | RuntimeException e) {
            System.err.println("Tactus: no shared memory for the motor guard's heartbeat (" + e + "); the motors of a "
                    + "paused sketch are not zeroed");
        }
        try {
            MotorGuardLink link = new MotorGuardLink(GuardProcess.start(command(), "the motor guard"), heartbeat);
            link.send(MotorGuard.HELLO + (heartbeat.isShared() ? "\nheartbeat " + HEARTBEAT_STALE_MS + " "
                    + heartbeat.path() : "") + "\nport " + baud + " " + portName);
            return link;
        } catch (IOException | RuntimeException e) {
            heartbeat.unlink();
            System.err.println("Tactus: could not start the motor guard (" + e + "); the motors are zeroed only "
                    + "if the sketch closes the board or its JVM runs its shutdown hooks");
            return NONE;
        }
    }

    /**
     * Waits up to ms for the guard to say whether it holds the port for writing; then removes the shared file's
     * name (both processes keep their mapping). Returns true if the guard watches the heartbeat.
     */
    boolean awaitReady(long ms) {
        if (!heartbeat.isShared()) {
            return false;
        }
        long deadline = System.nanoTime() + ms * 1_000_000L;
        while (heartbeat.state() == GuardHeartbeat.STATE_WAITING && System.nanoTime() - deadline < 0
                && guard.process().isAlive()) {
            java.util.concurrent.locks.LockSupport.parkNanos(1_000_000);
        }
        long state = heartbeat.state();
        if (state != GuardHeartbeat.STATE_WAITING) {
            heartbeat.unlink();
        }
        return state == GuardHeartbeat.STATE_READY;
    }

    /** The memory shared with the guard ({@link GuardHeartbeat#NONE} without a guard). */
    public GuardHeartbeat heartbeat() {
        return heartbeat;
    }

    /** Tells the guard a device's setup: its id, the length of its write message and of the board's reply. */
    public void deviceConfigured(Device device) {
        byte[] zeros = device.zeroMessage();
        if (zeros != null) {
            send("device " + (device.id() & 0xFF) + " " + zeros.length + " " + device.replyBytes());
        }
    }

    /**
     * Ends the link. With motorsZeroed the guard exits at once; otherwise it zeroes the motors itself now
     * (the board has let go of the port).
     */
    public synchronized void release(boolean motorsZeroed) {
        if (guard == null || !guard.isOpen()) {
            return;
        }
        heartbeat.arm(false);
        heartbeat.unlink();
        if (motorsZeroed) {
            send("clean");
        }
        guard.closeInput();
    }

    /** The guard process, or null for {@link #NONE}. Not API: a test hook. */
    public Process process() {
        return guard == null ? null : guard.process();
    }

    private void send(String lines) {
        if (guard != null) {
            guard.send(lines);
        }
    }

    /** The command line that starts a guard: this JVM's java, small-footprint options, Tactus and jSerialComm. */
    static List<String> command() {
        return GuardProcess.command(MotorGuard.class.getName(), JVM_OPTIONS, INHERITED_PROPERTIES, MotorGuard.class,
                SerialPort.class);
    }
}
