package tactus.haptics;

import com.fazecast.jSerialComm.SerialPort;
import java.io.IOException;
import java.util.concurrent.locks.LockSupport;

/**
 * A {@link Transport} over a serial port through jSerialComm, in non-blocking mode ({@link Board} does the
 * waiting). Works with USB CDC boards and with pseudo-terminals (for the emulator over socat).
 */
public final class SerialTransport implements Transport {
    private static final long WRITE_STALL_NANOS = 250_000_000L;

    private final SerialPort port;
    private final String name;
    private volatile boolean closed;
    private boolean waitingReads;

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
        port.setComPortTimeouts(SerialPort.TIMEOUT_NONBLOCKING, 0, 0);
        if (!port.openPort(0)) {
            throw new HaplyLinkException("cannot open serial port \"" + portName + "\" (error "
                    + port.getLastErrorCode() + "): check that the board is plugged in, that no other program "
                    + "(another sketch, a serial monitor) has the port open, and that you may use it "
                    + "(Linux: the 'dialout' group)");
        }
        return new SerialTransport(port, portName);
    }

    /**
     * Registers a JVM shutdown hook that runs before jSerialComm closes the open ports from its own shutdown
     * hook (with {@code Runtime.addShutdownHook} the two would run in no set order).
     */
    static void runBeforePortsClose(Thread hook) {
        SerialPort.addShutdownHook(hook);
    }

    @Override
    public void write(byte[] data, int offset, int length) throws IOException {
        if (closed) {
            throw new IOException("port " + name + " is closed");
        }
        int done = 0;
        long stalledSince = 0;
        while (done < length) {
            int n = port.writeBytes(data, length - done, offset + done);
            if (n < 0) {
                throw new IOException("write to " + name + " failed (error " + port.getLastErrorCode() + ")");
            }
            if (n == 0) {
                // a vanished device (or a pty whose other end is gone) accepts nothing: give up after a while
                long now = System.nanoTime();
                if (stalledSince == 0) {
                    stalledSince = now;
                } else if (now - stalledSince > WRITE_STALL_NANOS) {
                    throw new IOException("write to " + name + " stalled for "
                            + WRITE_STALL_NANOS / 1_000_000 + " ms (error " + port.getLastErrorCode() + ")");
                }
                if (port.bytesAvailable() < 0) {
                    throw new IOException("port " + name + " is gone (error " + port.getLastErrorCode() + ")");
                }
                LockSupport.parkNanos(100_000);
            } else {
                stalledSince = 0;
            }
            done += n;
        }
    }

    @Override
    public int available() throws IOException {
        if (closed) {
            throw new IOException("port " + name + " is closed");
        }
        int n = port.bytesAvailable();
        if (n < 0) {
            throw new IOException("port " + name + " is gone (error " + port.getLastErrorCode() + ")");
        }
        return n;
    }

    @Override
    public int read(byte[] buffer, int offset, int length) throws IOException {
        if (closed) {
            throw new IOException("port " + name + " is closed");
        }
        int n = port.readBytes(buffer, length, offset);
        if (n < 0) {
            throw new IOException("read from " + name + " failed (error " + port.getLastErrorCode() + ")");
        }
        return n;
    }

    /**
     * Reads what has arrived, or waits for the first byte up to 100 ms (the tty driver counts in tenths of a
     * second) and wakes as soon as one arrives. The first call switches the port to such reads for good, so
     * that a later {@link #read} waits too when nothing has arrived: use it on a port that only one thread
     * reads and that never needs a read that returns at once (the emulator's end of a pty pair).
     */
    @Override
    public int readWaiting(byte[] buffer, int offset, int length) throws IOException {
        if (closed) {
            throw new IOException("port " + name + " is closed");
        }
        if (!waitingReads) {
            port.setComPortTimeouts(SerialPort.TIMEOUT_READ_SEMI_BLOCKING, 100, 0);
            waitingReads = true;
        }
        return read(buffer, offset, length);
    }

    @Override
    public void close() {
        if (!closed) {
            closed = true;
            port.closePort();
        }
    }

    /** The baud rate the port was opened with. */
    int baudRate() {
        return port.getBaudRate();
    }

    @Override
    public String describe() {
        return name;
    }
}
