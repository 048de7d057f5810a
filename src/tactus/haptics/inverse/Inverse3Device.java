package tactus.haptics.inverse;

import java.net.URI;
import java.util.concurrent.locks.LockSupport;

import tactus.haptics.HaplyLinkException;
import tactus.haptics.HapticDevice;
import tactus.haptics.WorkspaceMapping;
import tactus.haptics.safety.ResumeRamp;

/**
 * An Inverse3 (or Inverse3x, or Minverse) through the Inverse Service, as a {@link HapticDevice}: each tick
 * takes the newest state frame the socket thread parsed (never waiting) and sends one {@code set_cursor_force},
 * which the service answers with the next frame. Positions are the service's {@code cursor_position} in metres,
 * velocities its {@code cursor_velocity}, forces newtons along the same axes. The VerseGrip's orientation and
 * buttons, when one is listed, are read with {@link #readState(InverseState)} from any thread.
 *
 * <p><b>Guarded</b> ({@link #openGuarded}): an {@link InverseGuard} process beside this JVM sends zero force
 * through its own session if this JVM is killed or paused while a force is on; when this JVM runs again after
 * the guard acted, the force ramps back in over {@value #RAMP_MS} ms.
 *
 * <p><b>Reconnecting</b> ({@link #setReconnect(long)}): when the service drops the connection (stopped,
 * restarted, crashed), the device tries again with a bounded back-off (50 ms doubling to 1 s) for the time given,
 * on its own thread; meanwhile it sends nothing (the service has no session of ours: no force), and
 * {@link #update()} reports the last position, with zero velocity, so that the avatar holds still; once
 * reconnected, the force ramps back in over {@value #RAMP_MS} ms; if the time runs out, {@link #update()}
 * throws and the loop stops with the reason. {@link #status()} says which.
 */
public final class Inverse3Device implements HapticDevice {
    /** How long the force takes to ramp back in after a reconnection or a guard's zero, in milliseconds. */
    public static final int RAMP_MS = 100;
    private static final long RAMP_NANOS = RAMP_MS * 1_000_000L;

    /** Farther than this from the service's origin, in metres, a reported position is no Inverse3's (a fault). */
    public static final double REACH_M = 1.0;

    private volatile InverseServiceClient client;
    private final URI uri;
    private final Inverse3Choice choice;
    private final InverseState state = new InverseState();   // the loop thread's copy
    private long lastFrame = -1;
    private InverseGuardLink guard = InverseGuardLink.NONE;
    private long guardActsSeen;
    private final ResumeRamp ramp = new ResumeRamp(RAMP_NANOS, 0.05);   // the loop thread's

    private volatile long reconnectMillis;
    private volatile InverseServiceClient fresh;    // a new connection, published by the reconnecting thread
    private volatile String reconnecting;           // what is going on while reconnecting, or null
    private volatile String gaveUp;                 // why reconnecting failed, or null
    private volatile Thread reconnector;
    private volatile boolean closed;
    private volatile long reconnections;
    private volatile long forcesHeld;

    /** Wraps an open client. */
    public Inverse3Device(InverseServiceClient client) {
        if (client == null) {
            throw new IllegalArgumentException("Inverse3Device: client must not be null");
        }
        this.client = client;
        this.uri = client.uri();
        client.read(state);
        this.choice = state.deviceId == null ? Inverse3Choice.FIRST : Inverse3Choice.byId(state.deviceId);
    }

    /** Connects to the service at {@link InverseServiceClient#DEFAULT_URI} (2 s at most). */
    public static Inverse3Device open() {
        return new Inverse3Device(InverseServiceClient.connect());
    }

    /** Connects to the service at this address (e.g. {@code ws://localhost:10001}), waiting at most timeoutMillis. */
    public static Inverse3Device open(URI uri, long timeoutMillis) {
        return open(uri, timeoutMillis, Inverse3Choice.FIRST);
    }

    /**
     * Connects to the service at this address and drives the Inverse3 this choice names (by id, index or
     * handedness), waiting at most timeoutMillis.
     */
    public static Inverse3Device open(URI uri, long timeoutMillis, Inverse3Choice which) {
        return new Inverse3Device(InverseServiceClient.connect(uri, timeoutMillis, which));
    }

    /**
     * Connects as {@link #open(URI, long)} and starts an {@link InverseGuard} for this connection (unless the
     * property {@code tactus.inverseGuard} is "false"), waiting up to 5 s more for the guard to open its own
     * session with the service.
     */
    public static Inverse3Device openGuarded(URI uri, long timeoutMillis) {
        return openGuarded(uri, timeoutMillis, Inverse3Choice.FIRST);
    }

    /** As {@link #openGuarded(URI, long)}, driving (and guarding) the Inverse3 this choice names. */
    public static Inverse3Device openGuarded(URI uri, long timeoutMillis, Inverse3Choice which) {
        Inverse3Device d = open(uri, timeoutMillis, which);
        if (InverseGuardLink.enabled()) {
            InverseGuardLink g = InverseGuardLink.start(uri, d.state.deviceId);
            if (g.isGuarded() && !g.awaitReady(5_000)) {
                System.err.println("Tactus: the Inverse3 guard could not open its own session with the service at " + uri
                        + " in 5 s; it keeps trying");
            }
            d.guard = g;
            d.guardActsSeen = g.guardActs();
            if (g.isGuarded()) {
                try {
                    Runtime.getRuntime().addShutdownHook(new Thread(d::close, "tactus-inverse-guard-release"));
                } catch (IllegalStateException e) {
                    // the JVM is shutting down: the guard sees it go
                }
            }
        }
        return d;
    }

    /** True if an {@link InverseGuard} watches this device ({@link #openGuarded}). */
    public boolean isGuarded() {
        return guard.isGuarded();
    }

    /** The guard process, or null (for tests). */
    Process guardProcess() {
        return guard.process();
    }

    /**
     * Reconnects by itself for up to this long when the service drops the connection (0, the default: the next
     * {@link #update()} throws instead, and the loop stops with the reason).
     */
    public void setReconnect(long giveUpMillis) {
        if (giveUpMillis < 0) {
            throw new IllegalArgumentException("Inverse3Device.setReconnect: need a time >= 0 ms, got " + giveUpMillis);
        }
        reconnectMillis = giveUpMillis;
    }

    /** True while the device is reconnecting to the service. */
    public boolean isReconnecting() {
        return reconnecting != null;
    }

    /** Times the device reconnected to the service. */
    public long reconnections() {
        return reconnections;
    }

    /** The connection (a new one after each reconnection). */
    public InverseServiceClient client() {
        return client;
    }

    /** Copies the newest state (Inverse3 and VerseGrip) into out, from any thread; returns its frame number. */
    public long readState(InverseState out) {
        return client.read(out);
    }

    /** The device's id as the service names it (e.g. "049D"). */
    public String deviceId() {
        return state.deviceId;
    }

    /** The device's handedness from its configuration, "left" or "right" (null if the service gave none). */
    public String handedness() {
        return state.handedness;
    }

    /** The device's kind as the service names it: "inverse3", "inverse3x" or "minverse". */
    public String kind() {
        return state.deviceType == null ? "inverse3" : state.deviceType;
    }

    @Override
    public int dimensions() {
        return 3;
    }

    @Override
    public boolean isReady() {
        InverseServiceClient c = client;
        return c.lostReason() == null && !c.isClosed();
    }

    @Override
    public void begin() {
        client.sendForce(0, 0, 0);   // the service answers with the first frame
    }

    @Override
    public boolean update() {
        InverseServiceClient c = client;
        String why = c.lostReason();
        if (why != null) {
            if (reconnectMillis <= 0 || closed) {
                throw new HaplyLinkException(why);
            }
            String failed = gaveUp;
            if (failed != null) {
                throw new HaplyLinkException(failed);
            }
            InverseServiceClient f = fresh;
            if (f == null) {
                if (reconnecting == null) {
                    startReconnecting(c, why);
                }
                state.vx = 0;   // the avatar holds where the hand was last seen
                state.vy = 0;
                state.vz = 0;
                return !Double.isNaN(state.px);
            }
            fresh = null;
            client = f;
            c = f;
            lastFrame = -1;
            ramp.start(System.nanoTime());
            reconnections++;
            reconnecting = null;
        }
        long f = c.read(state);
        if (f == lastFrame) {
            if (c.badFramesInARow() >= InverseServiceClient.BAD_RUN) {
                throw new HaplyLinkException(c.badFramesReport());
            }
            return false;
        }
        lastFrame = f;
        if (!state.chosenListed) {
            throw new HaplyLinkException("the Haply Inverse Service no longer lists the Inverse3 " + state.deviceId
                    + " (it lists " + state.listing + "): was it unplugged or switched off?");
        }
        if (state.positionBad) {
            throw new HaplyLinkException("the Haply Inverse Service sends frames for the Inverse3 " + state.deviceId
                    + " (" + f + " so far) whose cursor_position is null or lacks a number: is the device calibrated "
                    + "and started (the Haply Hub shows its status)?");
        }
        double px = state.px;
        double py = state.py;
        double pz = state.pz;
        if (px * px + py * py + pz * pz > REACH_M * REACH_M || Double.isInfinite(px) || Double.isInfinite(py)
                || Double.isInfinite(pz)) {
            throw new HaplyLinkException("the Haply Inverse Service reports the Inverse3 " + state.deviceId + " at ("
                    + px + ", " + py + ", " + pz + ") m, beyond any Inverse3's reach (" + REACH_M + " m from the "
                    + "service's origin): the force is stopped; check the service's basis, mount and units settings");
        }
        return !Double.isNaN(state.px);
    }

    /**
     * The bound on late answers this device declares to the haptic loop's passivity account, ticks: on the
     * emulator's WebSocket path at 1 kHz the loop read the frame answering the previous force 50-81 % of the time and
     * one three or more frames older 4-12 % ({@code InverseExchangeDelayTest}); a real service's timing is unknown.
     */
    public static final int LATE_ANSWER_BOUND = 4;

    /** {@value #LATE_ANSWER_BOUND} ticks: the service's answers often come a tick or more late. */
    @Override
    public int lateAnswerBound() {
        return LATE_ANSWER_BOUND;
    }

    @Override
    public void position(double[] out) {
        out[0] = state.px;
        out[1] = state.py;
        out[2] = state.pz;
    }

    @Override
    public void velocity(double[] out) {
        out[0] = state.vx;
        out[1] = state.vy;
        out[2] = state.vz;
    }

    @Override
    public void sendForce(double fx, double fy, double fz) {
        InverseServiceClient c = client;
        if (c.lostReason() != null && reconnectMillis > 0 && !closed && gaveUp == null) {
            forcesHeld++;         // no session with the service (the next update() reconnects): nothing to send
            guard.forceSent(0, 0, 0);
            return;
        }
        if (!Double.isFinite(fx) || !Double.isFinite(fy) || !Double.isFinite(fz)) {
            fx = 0;
            fy = 0;
            fz = 0;
        }
        long acts = guard.guardActs();
        if (acts != guardActsSeen) {
            guardActsSeen = acts;   // the guard zeroed the force while this JVM was paused: ramp back in
            ramp.start(System.nanoTime());
        }
        if (ramp.isRunning()) {
            double k = ramp.factor(System.nanoTime());
            fx *= k;
            fy *= k;
            fz *= k;
        }
        guard.forceSent(fx, fy, fz);
        c.sendForce(fx, fy, fz);
    }

    @Override
    public void zeroForce() {
        guard.forceSent(0, 0, 0);
        client.zeroForce();
    }

    private void startReconnecting(InverseServiceClient old, String why) {
        long giveUp = reconnectMillis;
        reconnecting = "reconnecting to the Haply Inverse Service at " + uri + " (" + why + ")";
        Thread t = new Thread(() -> reconnect(old, why, giveUp), "tactus-inverse-reconnect");
        t.setDaemon(true);
        reconnector = t;
        t.start();
    }

    /**
     * The reconnecting thread (all printing is here, not on the haptic thread): tries with a back-off of 50 ms
     * doubling to 1 s, until it connects or gives up.
     */
    private void reconnect(InverseServiceClient old, String why, long giveUpMillis) {
        System.err.println("tactus: " + why + " Reconnecting for up to " + giveUpMillis / 1000.0 + " s; no force "
                + "meanwhile, the avatar holds");
        old.close();
        long start = System.nanoTime();
        long delay = 50;
        int attempt = 0;
        String last = why;
        while (!closed && (System.nanoTime() - start) / 1_000_000L < giveUpMillis) {
            LockSupport.parkNanos(delay * 1_000_000L);
            attempt++;
            try {
                InverseServiceClient n = InverseServiceClient.connect(uri, Math.max(1, Math.min(1000,
                        giveUpMillis - (System.nanoTime() - start) / 1_000_000L)), choice);
                if (closed) {
                    n.close();
                    return;
                }
                fresh = n;
                System.err.println("tactus: reconnected to the Haply Inverse Service at " + uri + " (attempt " + attempt
                        + "); the force ramps back in over " + RAMP_MS + " ms");
                return;
            } catch (HaplyLinkException e) {
                last = e.getMessage();
            }
            delay = Math.min(delay * 2, 1000);
            reconnecting = "reconnecting to the Haply Inverse Service at " + uri + ": attempt " + attempt + " failed ("
                    + last + "), next in " + delay + " ms";
        }
        gaveUp = "the Haply Inverse Service at " + uri + " did not come back within " + giveUpMillis / 1000.0 + " s ("
                + attempt + " attempts; " + last + ")";
    }

    /** Force messages not sent because the device was reconnecting. */
    public long forcesHeld() {
        return forcesHeld;
    }

    @Override
    public WorkspaceMapping defaultMapping() {
        return defaultMappingOfTheFamily();
    }

    /** The default mapping of the Inverse3 family ({@link WorkspaceMapping#inverse3YUp()}): model y up. */
    public static WorkspaceMapping defaultMappingOfTheFamily() {
        return WorkspaceMapping.inverse3YUp();
    }

    @Override
    public String describe() {
        return "Haply " + kind() + " " + state.deviceId + " through the Inverse Service at " + client.uri();
    }

    @Override
    public String status() {
        String r = reconnecting;
        if (r != null) {
            return r;
        }
        String g = gaveUp;
        if (g != null) {
            return "lost: " + g;
        }
        InverseServiceClient c = client;
        String why = c.lostReason();
        return why != null ? "lost: " + why : c.isClosed() ? "closed"
                : "open, " + c.messagesSent() + " sent, " + c.sendsSkipped() + " skipped"
                + (reconnections > 0 ? ", reconnected " + reconnections + " time(s)" : "");
    }

    @Override
    public void close() {
        closed = true;
        InverseServiceClient f = fresh;
        if (f != null) {
            f.close();
        }
        InverseServiceClient c = client;
        c.close();
        guard.release(c.closedAfterZero());
    }

    @Override
    public String toString() {
        return describe();
    }
}
