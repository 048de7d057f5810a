package tactus.haptics;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.LockSupport;
import java.util.concurrent.locks.ReentrantLock;
import tactus.haptics.safety.GuardHeartbeat;
import tactus.haptics.safety.MotorGuard;
import tactus.haptics.safety.MotorGuardLink;
import tactus.haptics.safety.ResumeRamp;
import tactus.haptics.transport.SerialTransport;
import tactus.haptics.transport.Transport;
import tactus.haptics.transport.WireFormat;

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
 * a {@link MotorGuard} process started with the board sends them, and also while the JVM is paused (a
 * debugger's breakpoint, SIGSTOP): every torque write stores a heartbeat in memory shared with the guard, and
 * after the pause the board counts the replies to the guard's writes and ramps the force back in over 100 ms.
 *
 * <p>Safety net for a sketch that drives the board from its own thread (hAPI style): a torque watchdog
 * zeroes the motors when no torque write has come for {@link #setTorqueWatchdogMillis(int) a set time} (50 ms
 * by default) after a non-zero one, and the first failure of each kind (a lost link, a call on a closed
 * board, a watchdog trip) is printed once to standard error where it happens, so that it shows even when the
 * sketch's executor swallows the exception. A board that stops reading (its link open but silent) is declared
 * lost when no reply has come for {@link #setTimeoutMillis(int) timeout} x {@link #setLostAfterTimeouts(int)
 * count} (1 s by default) while writes are owed an answer, long before the driver's buffer fills; no write
 * waits without a bound (see {@link SerialTransport}).
 *
 * <p>Methods lock the board (uncontended in normal use: one haptic thread); {@link #close()} waits at most
 * half a second for the lock, so a JVM shutdown never hangs on it.
 */
public class Board implements AutoCloseable {
    /** Default time a read waits for a complete reply frame, in milliseconds. */
    public static final int DEFAULT_TIMEOUT_MS = 100;
    /** Default number of consecutive reads without a reply after which the link is declared lost. */
    public static final int DEFAULT_LOST_AFTER_TIMEOUTS = 10;
    /** Default time without a torque write, after a non-zero one, before the watchdog zeroes the motors, in ms. */
    public static final int DEFAULT_TORQUE_WATCHDOG_MS = 50;
    /** System property that overrides {@link #DEFAULT_TORQUE_WATCHDOG_MS} for every new board (0 turns it off). */
    public static final String TORQUE_WATCHDOG_PROPERTY = "tactus.haptics.torqueWatchdogMillis";
    /** How long close() waits for the board to answer its zero torques. */
    private static final long CLOSE_ACK_NANOS = 250_000_000L;
    /** How long close() waits for the board's lock (held by a read or a write in another thread). */
    private static final long CLOSE_LOCK_NANOS = 500_000_000L;
    /**
     * Longest a waiter for the board (close, zeroTorques) waits behind another thread's write that has lasted this
     * long too, in nanoseconds: a write to a board that reads takes microseconds, so such a write is stuck (the
     * board stopped reading) and a zero torque could not go out behind it anyway.
     */
    static final long STUCK_WRITE_NANOS = 50_000_000L;
    private static final int LOCKED = 0;
    private static final int BUSY = 1;
    private static final int STUCK = 2;
    /** How often the watchdog thread beats the guard's heartbeat while a torque is on, in nanoseconds. */
    private static final long HEARTBEAT_NANOS = 5_000_000L;
    /** How long the force takes to come back, linearly from zero, after the motor guard zeroed it, in nanoseconds. */
    static final long RESUME_RAMP_NANOS = 100_000_000L;
    /** The most the ramp's factor may grow from one torque write to the next (a writer late by 100 ms still ramps). */
    private static final double RESUME_RAMP_MAX_STEP = 0.05;
    /** Unread input beyond this many bytes is dropped before a write (a sketch that never reads). */
    private static final int INPUT_CAP = 4096;
    /** Largest magnitude a reply value may have (degrees or ADC counts); larger means a misaligned frame. */
    private static final float PLAUSIBLE = 1e6f;

    private final Transport transport;
    private final BoardModel model;
    private final List<Device> devices = new ArrayList<>();
    private final Thread shutdownHook;
    private final boolean hookInRuntime;
    private final MotorGuardLink guard;
    private final GuardHeartbeat heartbeat;
    private final ReentrantLock lock = new ReentrantLock();
    private final ConsoleNotices notices = new ConsoleNotices();
    private volatile int timeoutMs = DEFAULT_TIMEOUT_MS;
    private volatile int lostAfterTimeouts = DEFAULT_LOST_AFTER_TIMEOUTS;
    private int consecutiveTimeouts;
    private volatile boolean closed;
    private volatile boolean closing;
    private volatile long writeStartedNanos;   // 0 while no write is in progress

    // is the board still reading? (lock held)
    private int seenAvailable;
    private long writesUnanswered;
    private long firstUnansweredNanos;

    // the torque watchdog
    private volatile int torqueWatchdogMs = defaultTorqueWatchdogMillis();
    private volatile long lastTorqueWriteNanos;
    private volatile boolean torqueArmed;
    private volatile Thread torqueWatchdog;
    private volatile long torqueWatchdogTrips;
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

    // the motor guard's writes while this JVM was paused (lock held)
    private long seenGuardWrites;
    private final ResumeRamp resumeRamp = new ResumeRamp(RESUME_RAMP_NANOS, RESUME_RAMP_MAX_STEP);
    private long zeroingsAtRamp;     // guardZeroings when torqueRamp() last scaled the torques
    private volatile long guardZeroings;

    /**
     * Opens the serial port of a Haply board from a Processing sketch (hAPI's constructor). The baud rate is
     * ignored by the board's native USB (sketches pass 0). The board is reset at once, and is closed
     * (torques zeroed) when the sketch is disposed.
     */
    public Board(processing.core.PApplet app, String portName, int baud) {
        this(MotorGuardLink.openPort(portName, baud), BoardModel.M0);
        if (app != null) {
            app.registerMethod("dispose", this);
        }
    }

    /** Opens the serial port of a Haply M0 board from a plain JVM application (baud as for the PApplet constructor). */
    public Board(String portName, int baud) {
        this(MotorGuardLink.openPort(portName, baud), BoardModel.M0);
    }

    /** Opens the serial port of a board of the given model (M3 and Dev-Kit have ports 1-4, the M0 1-2). */
    public Board(String portName, int baud, BoardModel model) {
        this(MotorGuardLink.openPort(portName, baud), model);
    }

    private Board(MotorGuardLink.Opened opened, BoardModel model) {
        this(opened.transport, model, opened.guard);
    }

    /** Uses an already open transport to a Haply M0 board. */
    public Board(Transport transport) {
        this(transport, BoardModel.M0);
    }

    /** Uses an already open transport to a board of the given model; sends a reset at once. */
    public Board(Transport transport, BoardModel model) {
        this(transport, model, null);
    }

    /** guard: the port's motor guard, or null to start one here if the transport is a serial port. */
    private Board(Transport transport, BoardModel model, MotorGuardLink guard) {
        if (transport == null) {
            if (guard != null) {
                guard.release(true);
            }
            throw new IllegalArgumentException("Board: transport must not be null");
        }
        if (model == null) {
            if (guard != null) {
                guard.release(true);
            }
            throw new IllegalArgumentException("Board: model must not be null");
        }
        this.transport = transport;
        this.model = model;
        this.guard = guard != null ? guard : MotorGuardLink.watch(transport);
        this.heartbeat = this.guard.heartbeat();
        try {
            flushInput();
            send(WireFormat.reset((byte) 0), 2);
        } catch (RuntimeException e) {
            this.guard.release(false);   // the port is gone; the guard may try
            throw e;
        }
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

    /**
     * Sets the torque watchdog: when a torque write with a non-zero torque is followed by no torque write for
     * this many milliseconds, the board sends zero torques (and zero PWM) to every device and prints why, once.
     * The next write drives the motors again. 0 turns the watchdog off (for a sketch that writes a torque once
     * and holds it). Default {@value #DEFAULT_TORQUE_WATCHDOG_MS} ms, or the system property
     * {@value #TORQUE_WATCHDOG_PROPERTY}.
     */
    public void setTorqueWatchdogMillis(int ms) {
        if (ms < 0) {
            throw new IllegalArgumentException("Board.setTorqueWatchdogMillis: time must be >= 0 ms (0 = off), got " + ms);
        }
        torqueWatchdogMs = ms;
    }

    /** The torque watchdog's time in milliseconds (0 = off). */
    public int torqueWatchdogMillis() {
        return torqueWatchdogMs;
    }

    /** Number of times the torque watchdog zeroed the motors. */
    public long torqueWatchdogTrips() {
        return torqueWatchdogTrips;
    }

    /** hAPI: sends {@code [type][id][bData...][fData as little-endian float32...]} in one write. */
    public void transmit(byte communicationType, byte deviceID, byte[] bData, float[] fData) {
        lock.lock();
        try {
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
        } finally {
            lock.unlock();
        }
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
    public boolean data_available() {
        lock.lock();
        try {
            if (closed) {
                return false;
            }
            try {
                return availableNow() > 0;
            } catch (IOException e) {
                throw lost("reading", e);
            }
        } finally {
            lock.unlock();
        }
    }

    /**
     * Reads the newest complete reply frame of {@code floats} floats for device id into out, discarding older
     * complete frames. Waits up to the timeout for one frame. Returns false (out unchanged) on a timeout or an
     * id mismatch; both are counted, and a mismatch or an incomplete frame flushes the input to resynchronise.
     */
    public boolean readFrame(byte id, int floats, float[] out) {
        lock.lock();
        try {
            return takeFrame(id, floats, out, true);
        } finally {
            lock.unlock();
        }
    }

    /**
     * Like {@link #readFrame} but never waits: returns false at once (nothing counted) if no complete frame
     * has arrived yet. For a fixed-rate loop that must not block.
     */
    public boolean pollFrame(byte id, int floats, float[] out) {
        lock.lock();
        try {
            return takeFrame(id, floats, out, false);
        } finally {
            lock.unlock();
        }
    }

    private boolean takeFrame(byte id, int floats, float[] out, boolean wait) {
        requireOpen();
        int frame = WireFormat.replyLength(floats);
        try {
            long deadline = System.nanoTime() + timeoutMs * 1_000_000L;
            int avail = availableNow();
            syncGuardWrites();   // after the count of bytes: a guard reply in it was counted before it was written
            if (!wait && avail < frame) {
                return false;
            }
            while (avail < frame) {
                if (closing) {
                    return false;   // close() is waiting for the lock
                }
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
                avail = availableNow();
                syncGuardWrites();
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
    public long framesRead() {
        lock.lock();
        try {
            return framesRead;
        } finally {
            lock.unlock();
        }
    }

    /** Number of complete but older reply frames dropped in favour of a newer one. */
    public long framesSkipped() {
        lock.lock();
        try {
            return framesSkipped;
        } finally {
            lock.unlock();
        }
    }

    /** Number of frames whose first byte was not the expected device id (each one flushed the input). */
    public long idMismatches() {
        lock.lock();
        try {
            return idMismatches;
        } finally {
            lock.unlock();
        }
    }

    /** Number of reads that found no complete frame within the timeout. */
    public long timeouts() {
        lock.lock();
        try {
            return timeouts;
        } finally {
            lock.unlock();
        }
    }

    /** Number of bytes thrown away while resynchronising. */
    public long bytesDiscarded() {
        lock.lock();
        try {
            return bytesDiscarded;
        } finally {
            lock.unlock();
        }
    }

    /**
     * Number of bytes dropped because more had arrived than the replies still owed (a stray or foreign
     * frame); counted only with one device on the board.
     */
    public long unexpectedBytes() {
        lock.lock();
        try {
            return unexpectedBytes;
        } finally {
            lock.unlock();
        }
    }

    /** Number of frames with the right id but a non-finite or absurd value (above 1e6), dropped with a flush. */
    public long implausibleFrames() {
        lock.lock();
        try {
            return implausibleFrames;
        } finally {
            lock.unlock();
        }
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
     * call more than once and from any thread. Never waits without a bound: at most half a second for another
     * thread's read to let go of the board, and at most 50 ms ({@link #STUCK_WRITE_NANOS}) behind another
     * thread's write that has lasted as long (then the port is closed without the zero torques, which a board
     * that keeps a write waiting could not take anyway, the stuck write ends, and the motor guard tries); 250 ms
     * for the board to answer the zero torques (unanswered, they do not count as sent: the motor guard sends them
     * again once the port is closed), and each write at most {@link SerialTransport#WRITE_TIMEOUT_MS}.
     */
    @Override
    public void close() {
        closing = true;
        heartbeat.arm(false);   // the guard leaves the port to close() from here
        int got = lockWithin(CLOSE_LOCK_NANOS);
        if (got != LOCKED) {
            if (!closed) {
                closed = true;
                notices.once(ConsoleNotices.Kind.CLOSE_TIMEOUT, "tactus: the Haply board on " + transport.describe()
                        + (got == STUCK ? " was stuck in another thread's write (the board stopped reading)"
                                : " was busy for " + CLOSE_LOCK_NANOS / 1_000_000 + " ms in another thread")
                        + "; its port was closed without sending zero torques");
                transport.close();   // this also ends the stuck write
                guard.release(false); // the motors may still push: the guard zeroes them now that the port is free
            }
            removeHook();
            return;
        }
        boolean answered = false;
        try {
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
                if (!closed) {
                    answered = awaitOwedReplies(CLOSE_ACK_NANOS);
                    // then reset: the board forgets the configuration (the duty stays at the zero just sent). Not
                    // when the zeros went unanswered: the guard sends them again, and a reset board would take
                    // its write for another device and read the zeros as commands
                    if (answered) {
                        try {
                            transport.write(WireFormat.reset((byte) 0), 0, 2);
                        } catch (IOException ignored) {
                            // closing anyway
                        }
                    }
                    // Let the replies arrive, then drop them.
                    LockSupport.parkNanos(2_000_000);
                    try {
                        int n = availableNow();
                        if (n > 0) {
                            discard(n);
                        }
                    } catch (IOException ignored) {
                        // closing anyway
                    }
                }
            }
            closed = true;
            transport.close();
            // only zeros the board answered count as done; otherwise the guard sends them again now
            guard.release(lostReason == null && answered);
        } finally {
            lock.unlock();
        }
        removeHook();
    }

    private void removeHook() {
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
     * stays open. Returns false if the link is closed or failed, if another thread held the board for more
     * than half a second, or at once once another thread's write has been stuck for
     * {@value #STUCK_WRITE_NANOS} ns (50 ms) while this call waited as long: no zero can go out behind it, and the
     * port's own write timeout ends it.
     */
    public boolean zeroTorques() {
        if (lockWithin(CLOSE_LOCK_NANOS) != LOCKED) {
            return false;
        }
        try {
            if (closed) {
                return false;
            }
            for (Device d : devices) {
                d.writeZeros();
            }
            return true;
        } catch (HaplyLinkException e) {
            return false;
        } finally {
            lock.unlock();
        }
    }

    /**
     * Takes the board's lock, waiting at most maxNanos; gives up sooner, with {@link #STUCK}, when another thread
     * has been in one write for {@link #STUCK_WRITE_NANOS} and this one has waited that long too (a pause of
     * the whole JVM during a write makes the write look long, but not the wait after it).
     */
    private volatile long lastLockWaitNanos;

    private int lockWithin(long maxNanos) {
        long start = System.nanoTime();
        try {
            while (!lock.tryLock(1, TimeUnit.MILLISECONDS)) {
                long now = System.nanoTime();
                long w = writeStartedNanos;
                if (w != 0 && now - w > STUCK_WRITE_NANOS && now - start > STUCK_WRITE_NANOS) {
                    lastLockWaitNanos = now - start;
                    return STUCK;
                }
                if (now - start > maxNanos) {
                    lastLockWaitNanos = now - start;
                    return BUSY;
                }
            }
            lastLockWaitNanos = System.nanoTime() - start;
            return LOCKED;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            lastLockWaitNanos = System.nanoTime() - start;
            return lock.tryLock() ? LOCKED : BUSY;
        }
    }

    /**
     * How long the last {@link #close()} or {@link #zeroTorques()} waited for the board's lock, in nanoseconds:
     * the time it spent behind another thread's call (for tests).
     */
    long lastLockWaitNanos() {
        return lastLockWaitNanos;
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

    /** The motor guard's link ({@link MotorGuardLink#NONE} without a guard). Not API: a test hook of the safety room. */
    public MotorGuardLink guardLink() {
        return guard;
    }

    void register(Device device) {
        lock.lock();
        try {
            if (!devices.contains(device)) {
                devices.add(device);
                guard.deviceConfigured(device);
            }
        } finally {
            lock.unlock();
        }
        // Started here, from the thread that sets the device up, rather than at the first torque: that write often
        // comes from a real-time haptic thread, and a thread inherits its creator's scheduling policy on Linux.
        if (torqueWatchdogMs > 0) {
            startTorqueWatchdog();
        }
    }

    /**
     * Refuses the setup of a device while another device is set up on this board: the firmware's setup
     * clears every assignment before it makes its own, so the other device's ports would move to the new id
     * and its torques would then be read as commands.
     */
    void checkNoOtherSetup(Device device, String op) {
        lock.lock();
        try {
            for (Device d : devices) {
                if (d == device) {
                    continue;
                }
                int other = d.id() & 0xFF;
                int mine = device.id() & 0xFF;
                if (other == mine) {
                    throw new IllegalStateException(op + ": another Device with id " + mine
                            + " is already set up on this board (" + transport.describe() + ")");
                }
                String shared = Device.sharedPorts(d, device);
                throw new IllegalStateException(op + ": Device(id " + other + ") is already set up on the board on "
                        + transport.describe() + " (" + d.describePorts() + "); a setup for id " + mine + " ("
                        + device.describePorts() + ") would "
                        + (shared.isEmpty() ? "clear its assignments (the firmware's setup resets every port)"
                                : "take over its " + shared)
                        + ", and the torques of id " + other + " would then be read as commands. Use one Device "
                        + "per board, or close the board and open it again");
            }
        } finally {
            lock.unlock();
        }
    }

    /**
     * Waits, up to a time, until every reply still owed has arrived (one device: the last one answers the
     * zero torques, so the board has applied them); returns true if they did. Closing a pseudo-terminal or a USB port at once can lose
     * what the other end has not read yet; the wait makes the zeroing sure wherever the board still answers.
     */
    private boolean awaitOwedReplies(long maxNanos) {
        if (devices.isEmpty()) {
            LockSupport.parkNanos(2_000_000);
            return true;      // no device: no motor was ever driven
        }
        if (devices.size() != 1 || pendingReplies <= 0) {
            LockSupport.parkNanos(2_000_000);
            return false;     // cannot tell (one device per board is the rule, and the zeros are owed a reply)
        }
        long need = pendingReplies * devices.get(0).replyBytes();
        long deadline = System.nanoTime() + maxNanos;
        try {
            int avail = availableNow();
            while (avail < need && System.nanoTime() - deadline < 0) {
                LockSupport.parkNanos(200_000);
                avail = availableNow();
            }
            return avail >= need;
        } catch (IOException ignored) {
            return false;     // the link is gone: the zeros may not have arrived
        }
    }

    /** Sends len bytes of data in one write. */
    void send(byte[] data, int len) {
        send(data, len, null);
    }

    /**
     * Sends len bytes of data in one write; or, if the motor guard zeroed the motors since the torques in data were
     * scaled ({@link #torqueRamp} took in its writes then: this JVM was paused in between), the message ifZeroed
     * instead (when not null), so that torques computed before the pause never reach the board after it. Returns true
     * if it sent ifZeroed.
     */
    private boolean send(byte[] data, int len, byte[] ifZeroed) {
        boolean replaced = false;
        lock.lock();
        try {
            requireOpen();
            try {
                boardStillReads();
                syncGuardWrites();   // any thread may have taken the guard's writes in since torqueRamp()
                if (ifZeroed != null && guardZeroings != zeroingsAtRamp) {
                    data = ifZeroed;   // the next write's ramp starts from zero, as after any guard zeroing
                    len = ifZeroed.length;
                    replaced = true;
                }
                writeStartedNanos = System.nanoTime() | 1L;
                try {
                    transport.write(data, 0, len);
                } finally {
                    writeStartedNanos = 0;
                }
                if (len > 0 && data[0] == WireFormat.WRITE) {
                    pendingReplies++;
                    if (writesUnanswered++ == 0) {
                        firstUnansweredNanos = System.nanoTime();
                    }
                }
            } catch (IOException e) {
                throw lost("writing", e);
            }
        } finally {
            lock.unlock();
        }
        return replaced;
    }

    /**
     * Sends a device's torque write and feeds the torque watchdog: nonZero tells whether any torque in it is
     * not zero (only then does the watchdog watch); zeros (or null) is the device's write with zero torques, sent
     * instead when the motor guard zeroed the motors after the torques were scaled (see {@link #torqueRamp}).
     */
    void sendTorques(byte[] data, int len, boolean nonZero, byte[] zeros) {
        lock.lock();
        try {
            if (send(data, len, zeros)) {
                nonZero = false;
            }
            long now = System.nanoTime();
            lastTorqueWriteNanos = now;   // under the lock: the watchdog never sees a write half done
            torqueArmed = nonZero;
            heartbeat.beat(now);          // a memory store: the motor guard sees this JVM run
            heartbeat.arm(nonZero);
        } finally {
            lock.unlock();
        }
        if (nonZero && torqueWatchdog == null && (torqueWatchdogMs > 0 || heartbeat.isShared())) {
            startTorqueWatchdog();
        }
    }

    /**
     * The factor (0..1) by which a torque write is scaled now: 1, except after the motor guard zeroed the motors of
     * this paused JVM, when the force comes back linearly from zero over {@link #RESUME_RAMP_NANOS} of writing
     * instead of jumping to what the sketch computed after the pause: by the time since the last write, and by at
     * most 5 % of the force per write, so that neither a writer that runs late nor one that catches up after the
     * pause with a burst of writes shortens the ramp (see {@link ResumeRamp}).
     */
    float torqueRamp() {
        lock.lock();
        try {
            if (closed) {
                return 1f;
            }
            syncGuardWrites();
            zeroingsAtRamp = guardZeroings;
            return (float) resumeRamp.factor(System.nanoTime());
        } finally {
            lock.unlock();
        }
    }

    /**
     * Number of zero-torque writes the motor guard sent to the board because this JVM gave no heartbeat (it was
     * paused: a debugger's breakpoint, SIGSTOP) while a torque was on; each one was followed by a ramp.
     */
    public long guardZeroings() {
        return guardZeroings;
    }

    /**
     * Takes in the motor guard's writes since the last look (lock held): the board answers them too, so their
     * replies are owed and not stray bytes; the motors are at zero, so the watchdog stands down and the force
     * ramps back in. No system call: a read of the shared memory.
     */
    private void syncGuardWrites() {
        long g = heartbeat.guardWrites();
        if (g != seenGuardWrites) {
            long k = g - seenGuardWrites;
            seenGuardWrites = g;
            pendingReplies += k;
            guardZeroings += k;
            torqueArmed = false;
            heartbeat.arm(false);
            resumeRamp.start(System.nanoTime());
        }
    }

    /**
     * Before a write: drops unread input beyond a cap (a sketch that never reads), and declares the link lost
     * when writes have been owed an answer for longer than the lost-link time with nothing arriving (the board
     * stopped reading: writing on would fill the driver's buffer until a write blocks).
     */
    private void boardStillReads() throws IOException {
        int avail = availableNow();
        if (avail >= INPUT_CAP) {
            discard(avail);
            pendingReplies = 0;
        }
        if (writesUnanswered > 0) {
            long silent = System.nanoTime() - firstUnansweredNanos;
            long limit = (long) timeoutMs * lostAfterTimeouts * 1_000_000L;
            if (silent > limit) {
                throw new IOException("no reply to the last " + writesUnanswered + " writes in " + silent / 1_000_000
                        + " ms: the board stopped reading");
            }
        }
    }

    /** The transport's available count, noting whether bytes arrived since the last look. */
    private int availableNow() throws IOException {
        int n = transport.available();
        if (n > seenAvailable) {
            writesUnanswered = 0;   // the board answered
        }
        seenAvailable = n;
        return n;
    }

    // ------------------------------------------------------------------------------------------ the watchdog

    private synchronized void startTorqueWatchdog() {
        if (torqueWatchdog != null || closed) {
            return;
        }
        Thread t = new Thread(this::watchTorques, "tactus-haply-torque-watchdog");
        t.setDaemon(true);
        torqueWatchdog = t;
        t.start();
    }

    private void watchTorques() {
        boolean beats = heartbeat.isShared();
        while (!closed) {
            int ms = torqueWatchdogMs;
            long limit = ms * 1_000_000L;
            // while a torque is on: a tenth of the time (a trip comes at most 10 % late), and at least every 5 ms
            // for the motor guard's heartbeat; 50 ms otherwise
            long step = 50_000_000L;
            if (torqueArmed) {
                step = ms > 0 ? Math.max(1_000_000L, limit / 10) : step;
                step = beats ? Math.min(step, HEARTBEAT_NANOS) : step;
            }
            LockSupport.parkNanos(step);
            if (!torqueArmed) {
                continue;
            }
            heartbeat.beat(System.nanoTime());
            if (ms <= 0) {
                continue;
            }
            long since = System.nanoTime() - lastTorqueWriteNanos;
            long trippedAfter = -1;
            if (since > limit && lock.tryLock()) {
                try {
                    syncGuardWrites();   // the guard zeroed the motors of this paused JVM: no trip, a ramp
                    since = System.nanoTime() - lastTorqueWriteNanos;
                    if (!closed && torqueArmed && since > limit) {
                        torqueArmed = false;
                        torqueWatchdogTrips++;
                        trippedAfter = since;
                        for (Device d : devices) {
                            d.writeZeros();
                        }
                    }
                } catch (RuntimeException ignored) {
                    // the link failed while zeroing: lost() has said why
                } finally {
                    lock.unlock();
                }
            }
            if (trippedAfter >= 0) {
                // printed after the lock is let go: a slow console must not hold up a haptic thread that resumes
                notices.once(ConsoleNotices.Kind.WATCHDOG, "tactus: no torque was written to the Haply board on "
                        + transport.describe() + " for " + trippedAfter / 1_000_000 + " ms: the motors were set to "
                        + "zero. Did the haptic thread stop? An exception in a ScheduledExecutorService task "
                        + "ends the task without a message: catch and print it there. (Board."
                        + "setTorqueWatchdogMillis sets this time, 0 turns it off.)");
            }
        }
    }

    private static int defaultTorqueWatchdogMillis() {
        String v = System.getProperty(TORQUE_WATCHDOG_PROPERTY);
        if (v != null) {
            try {
                int ms = Integer.parseInt(v.trim());
                if (ms >= 0) {
                    return ms;
                }
            } catch (NumberFormatException ignored) {
                // fall back to the default
            }
            System.err.println("tactus: ignoring " + TORQUE_WATCHDOG_PROPERTY + "=" + v + " (not a number of ms >= 0)");
        }
        return DEFAULT_TORQUE_WATCHDOG_MS;
    }

    // ------------------------------------------------------------------------------------------ internals

    private void flushRest() throws IOException {
        int rest = availableNow();
        if (rest > 0) {
            discard(rest);
        }
        pendingReplies = 0;
    }

    private void requireOpen() {
        if (closed) {
            if (lostReason != null) {
                throw new HaplyLinkException(lostReason);
            }
            String msg = "the Haply board on " + transport.describe() + " is closed";
            notices.once(ConsoleNotices.Kind.CLOSED_USE, "tactus: " + msg + "; a call to it failed (this is printed once)");
            throw new HaplyLinkException(msg);
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
        heartbeat.arm(false);
        transport.close();
        notices.once(ConsoleNotices.Kind.LOST, "tactus: " + msg + "; zero torques were sent where the link still "
                + "took them");
        return new HaplyLinkException(msg, e);
    }

    private void flushInput() {
        try {
            int n = availableNow();
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
            seenAvailable = Math.max(0, seenAvailable - r);
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
            seenAvailable = Math.max(0, seenAvailable - r);
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
