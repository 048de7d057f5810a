package tactus.haptics.safety;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.file.Paths;
import java.nio.file.StandardOpenOption;
import java.util.concurrent.locks.LockSupport;

/**
 * The {@link MotorGuard}'s watch over a JVM that stays alive but stops running (a debugger's breakpoint that
 * suspends every thread, SIGSTOP, a long pause): while the sketch's JVM says a non-zero torque is on, the guard
 * looks at its {@link GuardHeartbeat} every millisecond, and when the heartbeat has not changed for the stale
 * time it sends each device one write with zero torques and zero PWM, through a descriptor of the port it
 * opened for writing only, before the sketch's JVM opened the port (so that an exclusive open, TIOCEXCL, would
 * not shut it out). It never reads the port: the replies to its writes are for the sketch's board, which
 * counts them through the guard-write counter, which the guard increments before each write.
 *
 * <p>Each write is one {@code write()} of a whole message (at most 64 bytes) to the tty, and the tty layer never
 * interleaves two writes, so the board receives whole messages from the guard and from the sketch, in some
 * order: the firmware cannot misread them.
 */
final class MotorGuardPauseWatch implements Runnable {
    /** How often the heartbeat is looked at while a torque is on, in nanoseconds. */
    static final long POLL_NANOS = 1_000_000L;
    /**
     * How long a sketch's JVM whose heartbeat thread waits for a CPU (runnable, not paused) may give no heartbeat
     * before the guard zeroes the motors anyway, in nanoseconds.
     */
    static final long STARVED_LIMIT_NANOS = 500_000_000L;
    /** How often the armed flag is looked at while no torque is on, in nanoseconds. */
    private static final long IDLE_POLL_NANOS = 10_000_000L;

    private final GuardHeartbeat heartbeat;
    private final long staleNanos;
    private final String portName;
    private final FileChannel port;
    private volatile byte[][] zeroMessages = new byte[0][];
    private volatile String deviceIds = "";
    private volatile boolean stopped;
    private boolean printed;
    private final HeartbeatThreads threads;

    private MotorGuardPauseWatch(GuardHeartbeat heartbeat, long staleMillis, String portName, FileChannel port) {
        this.heartbeat = heartbeat;
        this.staleNanos = staleMillis * 1_000_000L;
        this.portName = portName;
        this.port = port;
        this.threads = ProcessHandle.current().parent().map(p -> new HeartbeatThreads(p.pid())).orElse(null);
    }

    /**
     * Opens the port for writing and starts watching on a daemon thread; sets the heartbeat's state to ready, or
     * to "no port" (and returns null) where the port cannot be opened so (Windows opens a COM port for one
     * process only: there the guard must not hold it).
     */
    static MotorGuardPauseWatch start(GuardHeartbeat heartbeat, long staleMillis, String portName) {
        boolean windows = System.getProperty("os.name", "").toLowerCase(java.util.Locale.ROOT).startsWith("windows");
        FileChannel ch = null;
        if (!windows) {
            try {
                ch = FileChannel.open(Paths.get(portName), StandardOpenOption.WRITE);
            } catch (IOException | RuntimeException e) {
                System.err.println("tactus motor guard: cannot open " + portName + " for writing (" + e
                        + "): the motors of a paused sketch are not zeroed");
            }
        }
        if (ch == null) {
            heartbeat.setState(GuardHeartbeat.STATE_NO_PORT);
            return null;
        }
        MotorGuardPauseWatch w = new MotorGuardPauseWatch(heartbeat, staleMillis, portName, ch);
        Thread t = new Thread(w, "tactus-motor-guard-heartbeat");
        t.setDaemon(true);
        t.start();
        heartbeat.setState(GuardHeartbeat.STATE_READY);
        return w;
    }

    /** The zero-torque write of each device (from the parent's device lines), and their ids for messages. */
    void setDevices(byte[][] messages, String ids) {
        zeroMessages = messages;
        deviceIds = ids;
    }

    /**
     * Stops watching and closes the write descriptor (before the guard opens the port itself); never waits for a
     * write stuck in it (closing the channel ends that write).
     */
    void stop() {
        stopped = true;
        try {
            port.close();
        } catch (IOException ignored) {
            // closing anyway
        }
    }

    @Override
    public void run() {
        long last = heartbeat.heartbeat();
        long unchangedSince = System.nanoTime();
        boolean zeroed = false;
        while (!stopped) {
            boolean armed = heartbeat.armed();
            LockSupport.parkNanos(armed ? POLL_NANOS : IDLE_POLL_NANOS);
            long now = System.nanoTime();
            long beat = heartbeat.heartbeat();
            if (beat != last || !heartbeat.armed()) {
                last = beat;
                unchangedSince = now;
                zeroed = false;
                continue;
            }
            long stale = now - unchangedSince;
            if (!zeroed && stale > staleNanos && stale < STARVED_LIMIT_NANOS && threads != null && threads.waitForCpu()) {
                continue;   // the JVM runs but gets no CPU (a loaded machine): not a pause, give it longer
            }
            if (!zeroed && stale > staleNanos) {
                zeroed = true;
                String done = zero();
                if (!printed) {
                    printed = true;
                    System.err.println("tactus motor guard: no heartbeat from the sketch's JVM for " + stale / 1_000_000
                            + " ms (paused: a debugger's breakpoint, SIGSTOP?): " + done + "; when the sketch runs again it "
                            + "ramps the force back in (printed once)");
                    System.err.flush();
                }
            }
        }
    }

    /** Writes each device's zero message, counting each before it is written; says what was done. */
    private String zero() {
        byte[][] messages = zeroMessages;
        for (byte[] m : messages) {
            if (stopped) {
                return "stopped";
            }
            heartbeat.countGuardWrite();
            try {
                ByteBuffer b = ByteBuffer.wrap(m);
                port.write(b);
                if (b.hasRemaining()) {
                    return "the write of zero torques to " + portName + " was cut short";
                }
            } catch (IOException e) {
                return "the write of zero torques to " + portName + " failed (" + e + ")";
            }
        }
        return "sent zero torques to device " + deviceIds + " on " + portName;
    }
}
