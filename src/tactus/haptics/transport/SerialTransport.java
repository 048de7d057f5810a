package tactus.haptics.transport;

import com.fazecast.jSerialComm.SerialPort;
import java.io.IOException;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.locks.LockSupport;
import tactus.haptics.Board;
import tactus.haptics.HaplyLinkException;
import tactus.haptics.SerialPorts;

/**
 * A {@link Transport} over a serial port through jSerialComm. Works with USB CDC boards and with
 * pseudo-terminals (for the emulator over socat).
 *
 * <p>Reads never wait ({@link Board} does the waiting), except {@link #readWaiting}. Writes never spin and
 * never block without a bound: the port's file descriptor is in blocking mode, so a write to a board that has
 * stopped reading sleeps in the operating system once the driver's buffer is full (in non-blocking mode
 * jSerialComm's native write retries for ever and burns a core), and a guard thread closes the port when
 * one write has lasted {@link #WRITE_TIMEOUT_MS}: the write then fails with an {@link IOException}. (jSerialComm's
 * own write timeout only works on Windows, where it is set too.)
 */
public final class SerialTransport implements Transport {
    /** Longest time one write may take before the port is closed and the write fails, in milliseconds. */
    public static final int WRITE_TIMEOUT_MS = 250;
    /** How often the guard thread looks for a stalled write, in milliseconds. */
    private static final long GUARD_PERIOD_NANOS = 20_000_000L;
    /** A wake-up of the guard thread this much later than asked means the JVM was paused, in nanoseconds. */
    private static final long PAUSE_NANOS = 100_000_000L;
    /** The read timeout of the port: readWaiting waits at most this long (the tty counts in tenths of a second). */
    private static final int READ_WAIT_MS = 100;

    private static final CopyOnWriteArrayList<SerialTransport> OPEN = new CopyOnWriteArrayList<>();
    private static Thread guard;

    private final SerialPort port;
    private final String name;
    private volatile boolean closed;
    private volatile long writeStartedNanos;   // 0 while no write is in progress
    private volatile boolean writeStalled;

    private SerialTransport(SerialPort port, String name) {
        this.port = port;
        this.name = name;
    }

    /**
     * Opens a serial port by name ("/dev/ttyACM0", "COM3", a pty path). The baud rate is passed to the driver
     * (0 is accepted: native USB ignores it). Throws {@link HaplyLinkException} naming the port if it cannot
     * be opened.
     */
    public static SerialTransport open(String portName, int baud) {
        if (portName == null || portName.isEmpty()) {
            throw new IllegalArgumentException("SerialTransport.open: port name must be a non-empty string, got "
                    + (portName == null ? "null" : "\"\"") + "; available ports: " + SerialPorts.describeAll());
        }
        if (baud < 0) {
            throw new IllegalArgumentException("SerialTransport.open(\"" + portName + "\"): baud must be >= 0, got " + baud);
        }
        SerialPort port;
        try {
            port = SerialPort.getCommPort(portName);
        } catch (RuntimeException e) {
            throw new HaplyLinkException("no serial port \"" + portName + "\" (" + e.getMessage()
                    + "); available ports: " + SerialPorts.describeAll(), e);
        }
        port.setComPortParameters(baud, 8, SerialPort.ONE_STOP_BIT, SerialPort.NO_PARITY);
        port.setFlowControl(SerialPort.FLOW_CONTROL_DISABLED);
        // Semi-blocking reads put the descriptor in blocking mode (jSerialComm sets O_NONBLOCK only for
        // TIMEOUT_NONBLOCKING), so a full output buffer puts the writer to sleep instead of spinning. The write
        // timeout is honoured on Windows only (with TIMEOUT_WRITE_BLOCKING, which on POSIX would also drain
        // after every write); elsewhere the guard thread bounds the write.
        boolean windows = System.getProperty("os.name", "").toLowerCase(java.util.Locale.ROOT).startsWith("windows");
        int mode = SerialPort.TIMEOUT_READ_SEMI_BLOCKING | (windows ? SerialPort.TIMEOUT_WRITE_BLOCKING : 0);
        port.setComPortTimeouts(mode, READ_WAIT_MS, WRITE_TIMEOUT_MS);
        if (!port.openPort(0)) {
            throw new HaplyLinkException("cannot open serial port \"" + portName + "\" (error "
                    + port.getLastErrorCode() + "): check that the board is plugged in, that no other program "
                    + "(another sketch, a serial monitor) has the port open, and that you may use it "
                    + "(Linux: the 'dialout' group)");
        }
        SerialTransport t = new SerialTransport(port, portName);
        OPEN.add(t);
        startGuard();
        return t;
    }

    /**
     * Registers a JVM shutdown hook that runs before jSerialComm closes the open ports from its own shutdown
     * hook (with {@code Runtime.addShutdownHook} the two would run in no set order). Not API: for
     * {@link tactus.haptics.Board}.
     */
    public static void runBeforePortsClose(Thread hook) {
        SerialPort.addShutdownHook(hook);
    }

    /**
     * Writes the bytes. Fails with an IOException, and closes the port, if the write has not completed after
     * {@link #WRITE_TIMEOUT_MS} (the board stopped reading and the driver's buffer is full).
     */
    @Override
    public void write(byte[] data, int offset, int length) throws IOException {
        if (closed) {
            throw new IOException(closedMessage());
        }
        int done = 0;
        writeStartedNanos = System.nanoTime();
        try {
            while (done < length) {
                int n = port.writeBytes(data, length - done, offset + done);
                if (n <= 0) {
                    if (writeStalled) {
                        throw new IOException(stalledMessage());
                    }
                    if (n < 0) {
                        throw new IOException("write to " + name + " failed (error " + port.getLastErrorCode() + ")");
                    }
                    LockSupport.parkNanos(100_000);   // nothing taken: try again (the guard bounds the time)
                }
                done += Math.max(0, n);
            }
        } finally {
            writeStartedNanos = 0;
        }
    }

    /** Why the port is closed: the stalled write that closed it, if one did. */
    private String closedMessage() {
        return writeStalled ? stalledMessage() : "port " + name + " is closed";
    }

    private String stalledMessage() {
        return "write to " + name + " did not complete within " + WRITE_TIMEOUT_MS
                + " ms (the board stopped reading); the port was closed";
    }

    @Override
    public int available() throws IOException {
        if (closed) {
            throw new IOException(closedMessage());
        }
        int n = port.bytesAvailable();
        if (n < 0) {
            throw new IOException("port " + name + " is gone (error " + port.getLastErrorCode() + ")");
        }
        return n;
    }

    /** Reads up to length bytes of what has arrived; returns 0 at once when nothing has. */
    @Override
    public int read(byte[] buffer, int offset, int length) throws IOException {
        int avail = available();
        if (avail == 0 || length == 0) {
            return 0;
        }
        return readPort(buffer, offset, Math.min(length, avail));
    }

    /**
     * Reads what has arrived, or waits for the first byte up to 100 ms (the tty driver counts in tenths of a
     * second) and wakes as soon as one arrives.
     */
    @Override
    public int readWaiting(byte[] buffer, int offset, int length) throws IOException {
        if (closed) {
            throw new IOException(closedMessage());
        }
        return readPort(buffer, offset, length);
    }

    private int readPort(byte[] buffer, int offset, int length) throws IOException {
        int n = port.readBytes(buffer, length, offset);
        if (n < 0) {
            throw new IOException("read from " + name + " failed (error " + port.getLastErrorCode() + ")");
        }
        return n;
    }

    /** Closes the port; a write blocked in it returns at once and fails. Never waits for the board. */
    @Override
    public void close() {
        if (!closed) {
            closed = true;
            OPEN.remove(this);
            port.closePort();
        }
    }

    /** The baud rate the port was opened with. Not API: for the motor guard in {@code tactus.haptics.safety}. */
    public int baudRate() {
        return port.getBaudRate();
    }

    @Override
    public String describe() {
        return name;
    }

    // ------------------------------------------------------------------------------------ the write guard

    private static synchronized void startGuard() {
        if (guard != null) {
            LockSupport.unpark(guard);   // it may be in its long idle sleep: watch the new port from now
            return;
        }
        Thread t = new Thread(SerialTransport::guardLoop, "tactus-serial-write-guard");
        t.setDaemon(true);
        guard = t;
        t.start();
    }

    /**
     * Closes the port of every write that has lasted longer than the write timeout: looks every 20 ms while a
     * port is open, every half second otherwise. Time while this JVM was paused (this thread woke over 100 ms
     * late) does not count: a write that was in progress when a debugger suspended every thread, or SIGSTOP
     * stopped the process, has had no time to end.
     */
    private static void guardLoop() {
        long limit = WRITE_TIMEOUT_MS * 1_000_000L;
        long lastWake = System.nanoTime();
        long resumedAt = 0;
        while (true) {
            long sleep = OPEN.isEmpty() ? 25 * GUARD_PERIOD_NANOS : GUARD_PERIOD_NANOS;
            LockSupport.parkNanos(sleep);
            long now = System.nanoTime();
            if (now - lastWake - sleep > PAUSE_NANOS) {
                // this thread did not run for a while: the JVM was paused (a debugger, SIGSTOP) or starved, and so
                // was the writer, whose write may have ended just before; time a write from here, not from its start
                resumedAt = now;
            }
            lastWake = now;
            for (SerialTransport t : OPEN) {
                long started = t.writeStartedNanos;
                if (started != 0 && resumedAt != 0 && started - resumedAt < 0) {
                    started = resumedAt;
                }
                if (started != 0 && now - started > limit) {
                    t.writeStalled = true;
                    t.close();   // unblocks the write: the descriptor goes, the write returns -1
                }
            }
        }
    }
}
