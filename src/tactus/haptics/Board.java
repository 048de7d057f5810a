package tactus.haptics;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.locks.LockSupport;

/**
 * The serial link to a Haply board (hAPI 2.x compatible), speaking the V2 wire protocol over a
 * {@link Transport}.
 *
 * <p>Differences from hAPI, all on the safe side: a read takes every complete reply frame that has arrived
 * and keeps the newest (hAPI reads one per tick, so every tick without data adds a frame of lag for good);
 * a read waits for exactly 1 + 4n bytes with a timeout, checks the device id and resynchronises by
 * flushing on a mismatch, on more bytes than the replies still owed, or on an absurd value (all counted,
 * never printed); each command goes out in one write; {@link #close()}
 * sends zero torques to every configured device before closing, also from a JVM shutdown hook and from
 * Processing's {@code dispose}; where the JVM ends with neither (the Processing editor's Stop button, SIGKILL),
 * a {@link MotorGuard} process started with the board sends them.
 *
 * <p>Methods are synchronized on the board (uncontended in normal use: one haptic thread).
 */
public class Board implements AutoCloseable {
    /** Default time a read waits for a complete reply frame, in milliseconds. */
    public static final int DEFAULT_TIMEOUT_MS = 100;
    /** Default number of consecutive reads without a reply after which the link is declared lost. */
    public static final int DEFAULT_LOST_AFTER_TIMEOUTS = 10;
    /** How long close() waits for the board to answer its zero torques. */
    private static final long CLOSE_ACK_NANOS = 250_000_000L;
    /** Largest magnitude a reply value may have (degrees or ADC counts); larger means a misaligned frame. */
    private static final float PLAUSIBLE = 1e6f;

    private final Transport transport;
    private final BoardModel model;
    private final List<Device> devices = new ArrayList<>();
    private final Thread shutdownHook;
    private final boolean hookInRuntime;
    private final MotorGuardLink guard;
    private volatile int timeoutMs = DEFAULT_TIMEOUT_MS;
    private volatile int lostAfterTimeouts = DEFAULT_LOST_AFTER_TIMEOUTS;
    private int consecutiveTimeouts;
    private volatile boolean closed;
    private volatile String lostReason;
    private byte[] rx = new byte[64];
    private byte[] tx = new byte[64];

    private long framesRead;
    private long framesSkipped;
    private long idMismatches;
    private long timeouts;
    private long bytesDiscarded;
    private long unexpectedBytes;
    private long implausibleFrames;
    private long pendingReplies;

    /**
     * Opens the serial port of a Haply board from a Processing sketch (hAPI's constructor). The baud rate is
     * ignored by the board's native USB (sketches pass 0). The board is reset at once, and is closed
     * (torques zeroed) when the sketch is disposed.
     */
    public Board(processing.core.PApplet app, String portName, int baud) {
        this(SerialTransport.open(portName, baud), BoardModel.M0);
        if (app != null) {
            app.registerMethod("dispose", this);
        }
    }

    /** Opens the serial port of a Haply M0 board from a plain JVM application (baud as for the PApplet constructor). */
    public Board(String portName, int baud) {
        this(SerialTransport.open(portName, baud), BoardModel.M0);
    }

    /** Opens the serial port of a board of the given model (M3 and Dev-Kit have ports 1-4, the M0 1-2). */
    public Board(String portName, int baud, BoardModel model) {
        this(SerialTransport.open(portName, baud), model);
    }

    /** Uses an already open transport to a Haply M0 board. */
    public Board(Transport transport) {
        this(transport, BoardModel.M0);
    }

    /** Uses an already open transport to a board of the given model; sends a reset at once. */
    public Board(Transport transport, BoardModel model) {
        if (transport == null) {
            throw new IllegalArgumentException("Board: transport must not be null");
        }
        if (model == null) {
            throw new IllegalArgumentException("Board: model must not be null");
        }
        this.transport = transport;
        this.model = model;
        flushInput();
        send(WireFormat.reset((byte) 0), 2);
        this.shutdownHook = new Thread(this::closeQuietly, "tactus-haply-shutdown");
        if (transport instanceof SerialTransport) {
            // jSerialComm closes every port from a shutdown hook of its own; Runtime's hooks run in no set
            // order, so ours could find the port closed and the motors would keep their last torque
            SerialTransport.runBeforePortsClose(shutdownHook);
            hookInRuntime = false;
        } else {
            Runtime.getRuntime().addShutdownHook(shutdownHook);
            hookInRuntime = true;
        }
        this.guard = MotorGuardLink.watch(transport);
    }

    /**
     * Turns the motor guard on or off for boards opened from now on (default on; the system property
     * {@code -Dtactus.motorGuard=false} turns it off). The guard is a small process, started when a board opens
     * a serial port, that zeroes the motors if this JVM ends without closing the board (see {@link MotorGuard}).
     */
    public static void setMotorGuard(boolean on) {
        MotorGuardLink.setEnabled(on);
    }

    /** Opens the first serial port that looks like a Haply board (see {@link SerialPorts#findHaply()}). */
    public static Board connect() {
        return new Board(SerialPorts.findHaply(), 0);
    }

    /** The board model (ports, PWM resolution). */
    public BoardModel model() {
        return model;
    }

    /** The transport's name (port name or "emulator"). */
    public String describe() {
        return transport.describe();
    }

    /** Sets how long a read waits for a complete reply frame, in milliseconds (>= 1). */
    public void setTimeoutMillis(int ms) {
        if (ms < 1) {
            throw new IllegalArgumentException("Board.setTimeoutMillis: timeout must be >= 1 ms, got " + ms);
        }
        timeoutMs = ms;
    }

    /**
     * Sets after how many consecutive reads without any reply (each waiting the timeout) the link is declared
     * lost and the board closed (>= 1).
     */
    public void setLostAfterTimeouts(int n) {
        if (n < 1) {
            throw new IllegalArgumentException("Board.setLostAfterTimeouts: count must be >= 1, got " + n);
        }
        lostAfterTimeouts = n;
    }

    /** hAPI: sends {@code [type][id][bData...][fData as little-endian float32...]} in one write. */
    public synchronized void transmit(byte communicationType, byte deviceID, byte[] bData, float[] fData) {
        int nb = bData == null ? 0 : bData.length;
        int nf = fData == null ? 0 : fData.length;
        int len = 2 + nb + 4 * nf;
        byte[] out = txBuffer(len);
        out[0] = communicationType;
        out[1] = deviceID;
        if (nb > 0) {
            System.arraycopy(bData, 0, out, 2, nb);
        }
        for (int i = 0; i < nf; i++) {
            WireFormat.putFloat(out, 2 + nb + 4 * i, fData[i]);
        }
        send(out, len);
    }

    /**
     * hAPI: reads the newest reply of {@code expected} floats for a device. On a timeout or an id mismatch the
     * result holds zeros (and the failure is counted); {@link Device#device_read_data()} keeps the last good
     * values instead.
     */
    public float[] receive(byte communicationType, byte deviceID, int expected) {
        float[] out = new float[Math.max(0, expected)];
        readFrame(deviceID, expected, out);
        return out;
    }

    /** hAPI: true when at least one byte from the board is waiting to be read. */
    public synchronized boolean data_available() {
        if (closed) {
            return false;
        }
        try {
            return transport.available() > 0;
        } catch (IOException e) {
            throw lost("reading", e);
        }
    }

    /**
     * Reads the newest complete reply frame of {@code floats} floats for device id into out, discarding older
     * complete frames. Waits up to the timeout for one frame. Returns false (out unchanged) on a timeout or an
     * id mismatch; both are counted, and a mismatch or an incomplete frame flushes the input to resynchronise.
     */
    public synchronized boolean readFrame(byte id, int floats, float[] out) {
        return takeFrame(id, floats, out, true);
    }

    /**
     * Like {@link #readFrame} but never waits: returns false at once (nothing counted) if no complete frame
     * has arrived yet. For a fixed-rate loop that must not block.
     */
    public synchronized boolean pollFrame(byte id, int floats, float[] out) {
        return takeFrame(id, floats, out, false);
    }

    private boolean takeFrame(byte id, int floats, float[] out, boolean wait) {
        requireOpen();
        int frame = WireFormat.replyLength(floats);
        try {
            long deadline = System.nanoTime() + timeoutMs * 1_000_000L;
            int avail = transport.available();
            if (!wait && avail < frame) {
                return false;
            }
            while (avail < frame) {
                if (System.nanoTime() - deadline > 0) {
                    timeouts++;
                    if (avail > 0) {
                        discard(avail);
                        pendingReplies = 0;
                    } else if (++consecutiveTimeouts >= lostAfterTimeouts) {
                        throw lost("reading", new IOException("no reply to " + consecutiveTimeouts
                                + " reads in a row (" + timeoutMs + " ms each)"));
                    }
                    return false;
                }
                LockSupport.parkNanos(20_000);
                avail = transport.available();
            }
            consecutiveTimeouts = 0;
            if (devices.size() == 1 && avail > pendingReplies * frame) {
                // more bytes than the replies still owed: something else is in the stream, so no frame
                // boundary can be trusted; drop everything and start again from the next reply
                unexpectedBytes += avail;
                discard(avail);
                pendingReplies = 0;
                return false;
            }
            byte[] buf = rxBuffer(frame);
            int complete = avail / frame;
            for (int i = 0; i < complete - 1; i++) {
                readFully(buf, frame);
                framesSkipped++;
            }
            readFully(buf, frame);
            pendingReplies = Math.max(0, pendingReplies - complete);
            if (buf[0] != id) {
                idMismatches++;
                bytesDiscarded += frame;
                flushRest();
                return false;
            }
            for (int i = 0; i < floats; i++) {
                float v = WireFormat.getFloat(buf, 1 + 4 * i);
                if (!(Math.abs(v) <= PLAUSIBLE)) {
                    implausibleFrames++;
                    bytesDiscarded += frame;
                    flushRest();
                    return false;
                }
            }
            for (int i = 0; i < floats; i++) {
                out[i] = WireFormat.getFloat(buf, 1 + 4 * i);
            }
            framesRead++;
            return true;
        } catch (IOException e) {
            throw lost("reading", e);
        }
    }

    /** Number of reply frames decoded. */
    public synchronized long framesRead() {
        return framesRead;
    }

    /** Number of complete but older reply frames dropped in favour of a newer one. */
    public synchronized long framesSkipped() {
        return framesSkipped;
    }

    /** Number of frames whose first byte was not the expected device id (each one flushed the input). */
    public synchronized long idMismatches() {
        return idMismatches;
    }

    /** Number of reads that found no complete frame within the timeout. */
    public synchronized long timeouts() {
        return timeouts;
    }

    /** Number of bytes thrown away while resynchronising. */
    public synchronized long bytesDiscarded() {
        return bytesDiscarded;
    }

    /**
     * Number of bytes dropped because more had arrived than the replies still owed (a stray or foreign
     * frame); counted only with one device on the board.
     */
    public synchronized long unexpectedBytes() {
        return unexpectedBytes;
    }

    /** Number of frames with the right id but a non-finite or absurd value (above 1e6), dropped with a flush. */
    public synchronized long implausibleFrames() {
        return implausibleFrames;
    }

    /** True once the board has been closed or the link was lost. */
    public boolean isClosed() {
        return closed;
    }

    /** Why the link was lost, or null while it is up (or after a normal close). */
    public String lostReason() {
        return lostReason;
    }

    /**
     * Sends zero torques (and zero PWM) to every configured device and a reset, then closes the link. Safe to
     * call more than once and from any thread.
     */
    @Override
    public void close() {
        synchronized (this) {
            if (closed) {
                return;
            }
            if (lostReason == null) {
                for (Device d : devices) {
                    try {
                        d.writeZeros();
                    } catch (RuntimeException ignored) {
                        // the link may be half gone; closing goes on
                    }
                }
                awaitOwedReplies(CLOSE_ACK_NANOS);
                // then reset: the board forgets the configuration (the duty stays at the zero just sent)
                try {
                    transport.write(WireFormat.reset((byte) 0), 0, 2);
                } catch (IOException ignored) {
                    // closing anyway
                }
                // Let the replies arrive, then drop them.
                LockSupport.parkNanos(2_000_000);
                try {
                    int n = transport.available();
                    if (n > 0) {
                        discard(n);
                    }
                } catch (IOException ignored) {
                    // closing anyway
                }
            }
            closed = true;
            transport.close();
            guard.release(lostReason == null);
        }
        try {
            if (hookInRuntime) {
                Runtime.getRuntime().removeShutdownHook(shutdownHook);
            }   // jSerialComm's list cannot be undone: the hook then finds the board closed and does nothing
        } catch (IllegalStateException ignored) {
            // already shutting down: this is the hook itself
        }
    }

    /**
     * Sends zero torques and zero PWM to every configured device now, from any thread (a watchdog); the link
     * stays open. Returns false if the link is closed or failed.
     */
    public synchronized boolean zeroTorques() {
        if (closed) {
            return false;
        }
        try {
            for (Device d : devices) {
                d.writeZeros();
            }
            return true;
        } catch (HaplyLinkException e) {
            return false;
        }
    }

    /** Processing calls this when the sketch stops; same as {@link #close()}. */
    public void dispose() {
        close();
    }

    private void closeQuietly() {
        try {
            close();
        } catch (RuntimeException ignored) {
            // nothing more can be done at JVM exit
        }
    }

    // ------------------------------------------------------------------------------------------ for Device

    synchronized void register(Device device) {
        if (!devices.contains(device)) {
            devices.add(device);
            guard.deviceConfigured(device);
        }
    }

    synchronized boolean hasDevice(byte id) {
        for (Device d : devices) {
            if (d.id() == id) {
                return true;
            }
        }
        return false;
    }

    /**
     * Waits, up to a time, until every reply still owed has arrived (one device: the last one answers the
     * zero torques, so the board has applied them). Closing a pseudo-terminal or a USB port at once can lose
     * what the other end has not read yet; the wait makes the zeroing sure wherever the board still answers.
     */
    private void awaitOwedReplies(long maxNanos) {
        if (devices.size() != 1 || pendingReplies <= 0) {
            LockSupport.parkNanos(2_000_000);
            return;
        }
        long need = pendingReplies * devices.get(0).replyBytes();
        long deadline = System.nanoTime() + maxNanos;
        try {
            while (transport.available() < need && System.nanoTime() - deadline < 0) {
                LockSupport.parkNanos(200_000);
            }
        } catch (IOException ignored) {
            // the link is gone: nothing more to wait for
        }
    }

    /** Sends len bytes of data in one write. */
    synchronized void send(byte[] data, int len) {
        requireOpen();
        try {
            transport.write(data, 0, len);
            if (len > 0 && data[0] == WireFormat.WRITE) {
                pendingReplies++;
            }
        } catch (IOException e) {
            throw lost("writing", e);
        }
    }

    // ------------------------------------------------------------------------------------------ internals

    private void flushRest() throws IOException {
        int rest = transport.available();
        if (rest > 0) {
            discard(rest);
        }
        pendingReplies = 0;
    }

    private void requireOpen() {
        if (closed) {
            throw new HaplyLinkException(lostReason != null ? lostReason
                    : "the Haply board on " + transport.describe() + " is closed");
        }
    }

    private HaplyLinkException lost(String what, IOException e) {
        String msg = "lost the link to the Haply board on " + transport.describe() + " while " + what + ": "
                + e.getMessage() + " (check the USB cable and that no other program uses the port)";
        if (!closed) {
            // the board may still listen even if it stopped answering: try to stop the motors
            for (Device d : devices) {
                byte[] zeros = d.zeroMessage();
                if (zeros != null) {
                    try {
                        transport.write(zeros, 0, zeros.length);
                    } catch (IOException ignored) {
                        break;
                    }
                }
            }
        }
        lostReason = msg;
        closed = true;
        transport.close();
        return new HaplyLinkException(msg, e);
    }

    private void flushInput() {
        try {
            int n = transport.available();
            if (n > 0) {
                discard(n);
                bytesDiscarded = 0;
            }
        } catch (IOException e) {
            throw lost("opening", e);
        }
    }

    private void discard(int n) throws IOException {
        byte[] buf = rxBuffer(Math.min(n, 4096));
        int left = n;
        while (left > 0) {
            int r = transport.read(buf, 0, Math.min(left, buf.length));
            if (r <= 0) {
                break;
            }
            left -= r;
            bytesDiscarded += r;
        }
    }

    private void readFully(byte[] buf, int len) throws IOException {
        int got = 0;
        while (got < len) {
            int r = transport.read(buf, got, len - got);
            if (r < 0) {
                throw new IOException("end of stream");
            }
            got += r;
            if (r == 0) {
                Thread.onSpinWait();
            }
        }
    }

    private byte[] rxBuffer(int len) {
        if (rx.length < len) {
            rx = new byte[Math.max(len, 2 * rx.length)];
        }
        return rx;
    }

    private byte[] txBuffer(int len) {
        if (tx.length < len) {
            tx = new byte[Math.max(len, 2 * tx.length)];
        }
        return tx;
    }
}
