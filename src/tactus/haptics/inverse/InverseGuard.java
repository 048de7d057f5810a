package tactus.haptics.inverse;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.net.URI;
import java.nio.charset.StandardCharsets;
import java.util.Locale;
import java.util.concurrent.locks.LockSupport;

import tactus.haptics.safety.GuardMemory;
import tactus.haptics.HaplyLinkException;

/**
 * The Inverse3's guard: a small process, beside the sketch's JVM, that sends zero force to the Inverse3 through a
 * session of its own with Haply's Inverse Service when that JVM can no longer do it: killed (SIGKILL, the
 * editor's Stop button, a crash) or paused (a debugger's breakpoint that suspends every thread, SIGSTOP). It is
 * the counterpart of the 2DIY's {@code MotorGuard}, and needed because the service's documentation does not say
 * how long a force lasts once its client stops sending, nor what becomes of it when the client's connection
 * ends (see {@code docs/haptics.md}, "What the service does when its client vanishes").
 *
 * <p>The sketch's side ({@link InverseGuardLink}) starts it and tells it, one line each on its standard input:
 * {@value #HELLO}; {@code heartbeat <staleMs> <path>} (a {@link GuardMemory}); {@code service <uri>}; and
 * {@code clean} when the sketch closed its connection after zero force. The guard opens its own session
 * (profile {@value #PROFILE}) at once, sends no command through it while the sketch lives (an empty message every
 * 0.5 s, as the haply crate's {@code send_ping}, keeps it alive), and reopens it when the service drops it. It
 * acts:
 * <ul>
 * <li>when the heartbeat has not changed for the stale time while the sketch says a force is on (a paused JVM;
 * on Linux it waits up to {@value #STARVED_LIMIT_MS} ms while the sketch's heartbeat thread is runnable, that is
 * starved rather than stopped): one zero force through its session, counted in the shared memory so that the
 * sketch ramps its force back in when it runs again;</li>
 * <li>when its standard input ends or the sketch's process is gone without {@code clean}: zero force, resent every
 * {@value #RETRY_PAUSE_MS} ms for up to {@value #RETRY_MS} ms until the service reports it taken (the dead sketch's
 * session may own the device until the service sees its connection end), then it closes its session and exits.
 * Every wait is bounded: it halts at the latest {@value #ACT_LIMIT_MS} ms after it starts acting.</li>
 * </ul>
 * After each zero it reads the force the service reports, and says so if the service did not take the zero
 * (another session owns the device: see the docs).
 */
public final class InverseGuard {
    /** First line the sketch's side sends. */
    static final String HELLO = "tactus-inverse-guard 1";
    /** The guard session's profile name. */
    static final String PROFILE = "tactus-guard";
    /** How long the guard may spend acting on a gone sketch before it halts, in milliseconds. */
    static final long ACT_LIMIT_MS = 3_000;
    /** How long the guard keeps resending a zero the service has not taken, in milliseconds. */
    static final long RETRY_MS = 1_500;
    /** The pause between two zeros the service has not taken, in milliseconds. */
    static final long RETRY_PAUSE_MS = 5;
    /** How long a starved (runnable) sketch JVM may give no heartbeat before the guard acts anyway, in milliseconds. */
    static final long STARVED_LIMIT_MS = 500;
    private static final long PARENT_POLL_MS = 100;
    private static final long CONNECT_TIMEOUT_MS = 2_000;

    private volatile GuardMemory memory;
    private volatile long staleNanos = 100_000_000L;
    private volatile URI service;
    private volatile String deviceId;   // the Inverse3 to zero; null: the first listed
    private volatile InverseServiceClient client;
    private volatile boolean acting;
    private final InverseState state = new InverseState();

    private InverseGuard() {
    }

    /** Runs the guard: reads the sketch's lines until its input ends, then acts or exits. */
    public static void main(String[] args) {
        GuardMemory.ignoreTerminalSignals();
        InverseGuard guard = new InverseGuard();
        ProcessHandle parent = ProcessHandle.current().parent().orElse(null);
        daemon(() -> guard.watchParent(parent), "tactus-inverse-guard-parent");
        BufferedReader in = new BufferedReader(new InputStreamReader(System.in, StandardCharsets.UTF_8));
        try {
            String line;
            while ((line = in.readLine()) != null) {
                if (line.equals("clean")) {
                    guard.quit();
                }
                guard.accept(line, parent == null ? -1 : parent.pid());
            }
        } catch (IOException e) {
            // the pipe broke: the sketch is gone
        }
        guard.act("the sketch's JVM ended without zeroing the force");
    }

    private static void daemon(Runnable r, String name) {
        Thread t = new Thread(r, name);
        t.setDaemon(true);
        t.start();
    }

    private void accept(String line, long parentPid) {
        String[] f = line.trim().split(" ", 3);
        try {
            if (f[0].equals("heartbeat") && f.length == 3) {
                long ms = Long.parseLong(f[1]);
                if (ms < 1 || ms > 10_000) {
                    throw new IllegalArgumentException("stale time out of range");
                }
                staleNanos = ms * 1_000_000L;
                memory = GuardMemory.open(f[2], parentPid);
            } else if (f[0].equals("device") && f.length == 2 && service == null) {
                deviceId = f[1];
            } else if (f[0].equals("service") && f.length == 2 && service == null) {
                service = URI.create(f[1]);
                daemon(this::keepConnected, "tactus-inverse-guard-connect");
                if (memory != null) {
                    daemon(this::watchHeartbeat, "tactus-inverse-guard-heartbeat");
                }
            } else if (!line.equals(HELLO)) {
                throw new IllegalArgumentException("unknown command");
            }
        } catch (RuntimeException | IOException e) {
            System.err.println("tactus inverse guard: ignored \"" + line + "\" (" + e.getMessage() + ")");
        }
    }

    /**
     * Keeps the guard's own session open (reopened every 0.5 s at most while the service is away); says ready once
     * it has one, and unable after a failed attempt (the sketch's side keeps waiting a little for a later one).
     */
    private void keepConnected() {
        boolean first = true;
        while (!acting) {
            InverseServiceClient c = client;
            if (c == null || c.lostReason() != null) {
                c = tryConnect();
                if (c != null) {
                    client = c;
                }
                GuardMemory m = memory;
                if (first && m != null) {
                    m.setState(c != null ? GuardMemory.STATE_READY : GuardMemory.STATE_UNABLE);
                } else if (c != null && m != null) {
                    m.setState(GuardMemory.STATE_READY);
                }
                first = false;
            } else {
                c.ping();   // an empty message, as the haply crate's send_ping: keeps an idle session alive
            }
            LockSupport.parkNanos(500_000_000L);
        }
    }

    private InverseServiceClient tryConnect() {
        try {
            String id = deviceId;
            return InverseServiceClient.connect(service, CONNECT_TIMEOUT_MS, PROFILE,
                    id == null ? Inverse3Choice.FIRST : Inverse3Choice.byId(id));
        } catch (HaplyLinkException | IllegalArgumentException e) {
            return null;
        }
    }

    private void watchParent(ProcessHandle parent) {
        while (parent != null && parent.isAlive()) {
            LockSupport.parkNanos(PARENT_POLL_MS * 1_000_000L);
        }
        act("the sketch's JVM is gone");
    }

    /** Watches the heartbeat of a sketch whose force is on; zeroes the force once per pause. */
    private void watchHeartbeat() {
        GuardMemory m = memory;
        long last = m.heartbeat();
        long unchangedSince = System.nanoTime();
        boolean zeroed = false;
        boolean printed = false;
        while (!acting) {
            LockSupport.parkNanos(m.armed() ? 1_000_000L : 10_000_000L);
            long now = System.nanoTime();
            long beat = m.heartbeat();
            if (beat != last || !m.armed()) {
                last = beat;
                unchangedSince = now;
                zeroed = false;
                continue;
            }
            long stale = now - unchangedSince;
            if (zeroed || stale <= staleNanos) {
                continue;
            }
            if (stale < STARVED_LIMIT_MS * 1_000_000L && m.parentWaitsForCpu()) {
                continue;   // the JVM runs but gets no CPU: not a pause, give it longer
            }
            zeroed = true;
            m.countAct();
            String done = zero();
            if (!printed) {
                printed = true;
                System.err.println("tactus inverse guard: no heartbeat from the sketch's JVM for " + stale / 1_000_000
                        + " ms (paused: a debugger's breakpoint, SIGSTOP?): " + done + "; when the sketch runs again it "
                        + "ramps the force back in (printed once)");
                System.err.flush();
            }
        }
    }

    /** Sends one zero force through the guard's session (reopened if needed); says what happened. */
    private synchronized String zero() {
        long t0 = System.nanoTime();
        InverseServiceClient c = client;
        if (c == null || c.lostReason() != null) {
            c = tryConnect();
            if (c == null) {
                return "could not reach the Inverse Service at " + service + " to send zero force";
            }
            client = c;
        }
        long before = c.read(state);
        if (!c.zeroForce()) {
            return "the zero force could not be sent to the Inverse Service at " + service;
        }
        long deadline = System.nanoTime() + 200_000_000L;
        while (c.read(state) == before && System.nanoTime() - deadline < 0 && c.lostReason() == null) {
            LockSupport.parkNanos(200_000L);
        }
        String took = String.format(Locale.ROOT, "sent zero force to %s in %.1f ms", state.deviceId,
                (System.nanoTime() - t0) * 1e-6);
        if (state.fx != 0 || state.fy != 0 || state.fz != 0) {
            took += String.format(Locale.ROOT, ", but the service still reports (%.3f, %.3f, %.3f) N: it did not take "
                    + "the zero (another session owns the device?)", state.fx, state.fy, state.fz);
        }
        return took;
    }

    /**
     * Sends zero force until the service reports it taken, for at most {@link #RETRY_MS} ms; says how it ended.
     * A sketch's JVM that has just died may still own the device for a few milliseconds, until the service sees its
     * connection end, and a service refuses a second session's force meanwhile.
     */
    private String zeroUntilTaken() {
        long deadline = System.nanoTime() + RETRY_MS * 1_000_000L;
        String said = zero();
        int attempts = 1;
        while (!taken() && System.nanoTime() - deadline < 0) {
            LockSupport.parkNanos(RETRY_PAUSE_MS * 1_000_000L);
            said = zero();
            attempts++;
        }
        String how = taken() ? "took it once the sketch's session had ended)"
                : "never took it within " + RETRY_MS + " ms)";
        return attempts == 1 ? said : said + " (attempt " + attempts + ": the service " + how;
    }

    /** Whether the service's last reported force is zero. */
    private boolean taken() {
        return state.fx == 0 && state.fy == 0 && state.fz == 0;
    }

    /** Zeroes the force, within {@link #ACT_LIMIT_MS}, closes the session, and ends the process. */
    private void act(String why) {
        synchronized (this) {
            if (acting) {
                return;
            }
            acting = true;
        }
        daemon(() -> {
            LockSupport.parkNanos(ACT_LIMIT_MS * 1_000_000L);
            System.err.println("tactus inverse guard: gave up after " + ACT_LIMIT_MS + " ms");
            Runtime.getRuntime().halt(2);
        }, "tactus-inverse-guard-limit");
        if (service != null) {
            GuardMemory m = memory;
            if (m != null) {
                m.countAct();
            }
            System.err.println("tactus inverse guard: " + why + "; " + zeroUntilTaken());
            System.err.flush();
        }
        quit();
    }

    /** Closes the guard's session (zero force first: the client's close sends it) and ends the process. */
    private void quit() {
        acting = true;
        InverseServiceClient c = client;
        if (c != null) {
            c.close();
        }
        Runtime.getRuntime().halt(0);
    }
}
