package tactus.haptics.inverse;

import java.io.IOException;
import java.lang.invoke.VarHandle;
import java.net.ConnectException;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.net.SocketTimeoutException;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpTimeoutException;
import java.net.http.WebSocket;
import java.net.http.WebSocketHandshakeException;
import java.nio.ByteBuffer;
import java.time.Duration;
import java.util.Arrays;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CompletionStage;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.concurrent.atomic.AtomicBoolean;

import tactus.haptics.HaplyLinkException;

/**
 * A connection to Haply's Inverse Service over the JDK's {@link WebSocket}: it sends the session handshake,
 * waits for the service's full snapshot, then sends one {@code set_cursor_force} per call to
 * {@link #sendForce} (the service answers each message with one state frame) and parses every frame on the
 * socket's own thread into a state that any thread can read with {@link #read} (a sequence lock: readers never
 * block the socket, nor each other).
 *
 * <p>Which Inverse3: the one an {@link Inverse3Choice} names (the first listed by default), followed by its
 * {@code device_id} from the snapshot on; forces go to that id.
 *
 * <p>Endings: a service that is absent, refuses the upgrade, sends no snapshot in time, sends frames that are not
 * JSON, lists no Inverse3 (at once, on the first empty list), does not list the chosen one, or gives it a type
 * this client does not know makes {@link #connect} throw a {@link HaplyLinkException} that says what arrived
 * and what to check. A socket that closes or
 * fails later marks the client lost ({@link #lostReason()}); the next {@link #sendForce} throws. Every ending the
 * client controls sends zero force first: {@link #close()}, and a JVM shutdown hook (System.exit, SIGTERM,
 * Ctrl-C) while it is open. Where the JVM ends with no hook (SIGKILL, a crash) the operating system closes the
 * socket, and what the force does then is up to the service, or to an {@link InverseGuard} (see
 * {@link Inverse3Device#openGuarded} and {@code docs/haptics.md}).
 */
public final class InverseServiceClient implements AutoCloseable {
    /** The service's simulation channel on this machine. */
    public static final URI DEFAULT_URI = URI.create("ws://localhost:10001");
    /** The profile name sent in the session handshake. */
    public static final String PROFILE = "tactus";
    /** How many round trips are kept for the percentiles. */
    public static final int WINDOW = 1 << 16;

    private final URI uri;
    private final String profile;
    private final ForceMessage out = new ForceMessage();
    private final AtomicBoolean sending = new AtomicBoolean();
    private final Receiver receiver = new Receiver();
    private volatile WebSocket socket;
    private volatile CompletableFuture<WebSocket> pending;
    private volatile String lost;
    private volatile boolean closed;
    private volatile boolean closedAfterZero;
    private volatile boolean peerClosed;   // the service closed its side (or the connection failed)
    private volatile boolean peerClosedBeforeAbort;   // close() saw the service's own close before it aborted
    private volatile long sentNanos;
    private volatile long sent;
    private volatile long busy;
    private Thread hook;

    // published state (sequence lock: odd while the socket thread writes)
    private volatile int seq;
    private final InverseState published = new InverseState();

    // round trips, written by the socket thread
    private final long[] roundTrips = new long[WINDOW];
    private volatile long roundTripCount;

    private final Inverse3Choice choice;

    private InverseServiceClient(URI uri, String profile, Inverse3Choice choice) {
        this.uri = uri;
        this.profile = profile;
        this.choice = choice;
        receiver.parser.choose(choice);
    }

    /** Connects to the service at {@link #DEFAULT_URI}, waiting up to 2 s; see {@link #connect(URI, long)}. */
    public static InverseServiceClient connect() {
        return connect(DEFAULT_URI, 2000);
    }

    /**
     * Connects, sends the session handshake and waits for the snapshot of an Inverse3, all within
     * timeoutMillis (>= 1).
     *
     * @throws HaplyLinkException with a message that names the address and what to check
     */
    public static InverseServiceClient connect(URI uri, long timeoutMillis) {
        return connect(uri, timeoutMillis, PROFILE, Inverse3Choice.FIRST);
    }

    /**
     * As {@link #connect(URI, long)}, driving the Inverse3 this choice names (by id, index or handedness) among
     * those the service lists.
     *
     * @throws HaplyLinkException if the service lists no such device (the message lists those it has)
     */
    public static InverseServiceClient connect(URI uri, long timeoutMillis, Inverse3Choice which) {
        return connect(uri, timeoutMillis, PROFILE, which);
    }

    /** As {@link #connect(URI, long)}, with this profile name in the session handshake (the guard's own session). */
    static InverseServiceClient connect(URI uri, long timeoutMillis, String profile) {
        return connect(uri, timeoutMillis, profile, Inverse3Choice.FIRST);
    }

    /** As {@link #connect(URI, long, Inverse3Choice)}, with this profile name in the session handshake. */
    static InverseServiceClient connect(URI uri, long timeoutMillis, String profile, Inverse3Choice which) {
        if (uri == null || timeoutMillis < 1 || which == null) {
            throw new IllegalArgumentException("InverseServiceClient.connect: need an address, a timeout >= 1 ms and a "
                    + "choice of Inverse3, got " + uri + ", " + timeoutMillis + ", " + which);
        }
        InverseServiceClient c = new InverseServiceClient(uri, profile, which);
        c.open(timeoutMillis);
        return c;
    }

    private void open(long timeoutMillis) {
        long deadline = System.nanoTime() + timeoutMillis * 1_000_000L;
        probe(timeoutMillis);
        HttpClient http = HttpClient.newBuilder().connectTimeout(Duration.ofMillis(timeoutMillis)).build();
        CompletableFuture<WebSocket> f = http.newWebSocketBuilder().connectTimeout(Duration.ofMillis(timeoutMillis))
                .buildAsync(uri, receiver);
        try {
            socket = f.get(timeoutMillis + 500, TimeUnit.MILLISECONDS);
        } catch (ExecutionException e) {
            throw new HaplyLinkException(whyNoConnection(e.getCause()), e.getCause());
        } catch (TimeoutException e) {
            f.cancel(true);
            throw new HaplyLinkException("no answer from the Haply Inverse Service at " + uri + " within " + timeoutMillis
                    + " ms: is the Haply Hub (or the service) running?", e);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new HaplyLinkException("interrupted while connecting to the Haply Inverse Service at " + uri, e);
        }
        try {
            socket.sendText(out.handshake(profile), true).get(Math.max(1, (deadline - System.nanoTime()) / 1_000_000L),
                    TimeUnit.MILLISECONDS);
        } catch (Exception e) {
            socket.abort();
            throw new HaplyLinkException("the Haply Inverse Service at " + uri + " accepted the connection but the "
                    + "handshake could not be sent: " + e, e);
        }
        InverseState s = new InverseState();
        while (true) {
            read(s);
            String refused = refusal(s);
            if (refused != null) {
                socket.abort();
                throw new HaplyLinkException(refused);
            }
            if (s.snapshotSeen && s.chosenListed && s.deviceId != null) {
                break;
            }
            if (lost != null) {
                throw new HaplyLinkException("the Haply Inverse Service at " + uri + " dropped the connection before "
                        + "sending its devices: " + lost);
            }
            if (System.nanoTime() - deadline > 0) {
                socket.abort();
                throw new HaplyLinkException("the Haply Inverse Service at " + uri + " sent no snapshot of its devices within "
                        + timeoutMillis + " ms" + (s.frames > 0 ? " (" + s.frames + " messages without an Inverse3)" : ""));
            }
            try {
                Thread.sleep(1);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                socket.abort();
                throw new HaplyLinkException("interrupted while waiting for the Haply Inverse Service at " + uri, e);
            }
        }
        // The service sends a snapshot on connect and answers the handshake with another: wait (250 ms at most)
        // for that answer too, so that from here on each frame answers the message before it.
        long settle = Math.min(deadline, System.nanoTime() + 250_000_000L);
        while (read(s) < 2 && lost == null && System.nanoTime() - settle < 0) {
            try {
                Thread.sleep(1);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                break;
            }
        }
        out.setDevice(s.deviceId);
        Thread h = new Thread(this::closeFromHook, "tactus-inverse-shutdown");
        try {
            Runtime.getRuntime().addShutdownHook(h);
            hook = h;
        } catch (IllegalStateException e) {
            // the JVM is already shutting down
        }
    }

    /** The device types this client drives, as the service names them in each Inverse3's configuration. */
    static final java.util.List<String> KNOWN_TYPES = java.util.List.of("inverse3", "inverse3x", "minverse");

    /**
     * Why the connection must not go on, from what has arrived so far (null: nothing wrong yet): unreadable
     * frames, an empty device list, a snapshot without the chosen device, a device type this client does not know.
     */
    private String refusal(InverseState s) {
        if (receiver.badRun > 0 && !s.snapshotSeen) {   // its snapshot cannot be read: nothing to drive
            return badFramesReport();
        }
        if (s.inverse3Listed && s.inverse3Count == 0) {
            return "the Haply Inverse Service at " + uri + " lists no Inverse3: plug the device in and power it; "
                    + "the Haply Hub shows the devices it sees";
        }
        if (s.snapshotSeen && !s.chosenListed) {
            return "the Haply Inverse Service at " + uri + " lists " + s.listing + " but not " + choice
                    + ": choose one of those (Inverse3Choice.byId, byIndex or byHandedness)";
        }
        if (s.snapshotSeen && s.deviceType != null && !KNOWN_TYPES.contains(s.deviceType)) {
            return "the Haply Inverse Service at " + uri + " lists the device " + s.deviceId + " as type \"" + s.deviceType
                    + "\", which Tactus does not know how to drive (it drives " + String.join(", ", KNOWN_TYPES)
                    + "): choose another device or update Tactus";
        }
        return null;
    }

    /** Frames in a row that could not be read after which the connection is given up as unreadable. */
    public static final int BAD_RUN = 3;

    /** How many frames in a row, up to now, could not be read (0 once one is read). */
    public long badFramesInARow() {
        return receiver.badRun;
    }

    /** What arrived that could not be read and what to check, for a message (null if every frame was read). */
    public String badFramesReport() {
        String why = receiver.lastBad;
        if (why == null) {
            return null;
        }
        return "the Haply Inverse Service at " + uri + " sends frames Tactus cannot read (" + receiver.bad + " so far, "
                + receiver.badRun + " in a row; the last: " + why + "): check that it is the Haply Inverse Service, "
                + "version 3.5 or later, and that nothing rewrites its messages (NaN and Infinity are not JSON)";
    }

    /**
     * A plain TCP connection first: where nothing listens (the common case without a Haply Hub) it is refused in
     * a millisecond, without starting an HTTP client and its threads.
     */
    private void probe(long timeoutMillis) {
        String host = uri.getHost() == null ? "localhost" : uri.getHost();
        int port = uri.getPort() > 0 ? uri.getPort() : 80;
        try (Socket s = new Socket()) {
            s.connect(new InetSocketAddress(host, port), (int) Math.min(Integer.MAX_VALUE, timeoutMillis));
        } catch (IOException e) {
            throw new HaplyLinkException(whyNoConnection(e), e);
        }
    }

    private String whyNoConnection(Throwable cause) {
        Throwable c = cause;
        while (c != null && !(c instanceof ConnectException) && !(c instanceof WebSocketHandshakeException)
                && !(c instanceof HttpTimeoutException)) {
            c = c.getCause();
        }
        if (c instanceof ConnectException) {
            return "no Haply Inverse Service at " + uri + " (connection refused): start the Haply Hub, which runs the "
                    + "service, or the service itself; Tactus falls back to a 2DIY board or the emulator";
        }
        if (c instanceof WebSocketHandshakeException) {
            return "something answers at " + uri + " but refused the WebSocket upgrade (HTTP "
                    + ((WebSocketHandshakeException) c).getResponse().statusCode() + "): is it the Haply Inverse Service "
                    + "(version 3.5 or later)?";
        }
        if (cause instanceof SocketTimeoutException) {
            return "no answer from " + uri + " in time (" + cause.getMessage() + "): is the Haply Inverse Service running?";
        }
        if (c instanceof HttpTimeoutException) {
            return "no answer from the Haply Inverse Service at " + uri + " in time (" + c.getMessage() + ")";
        }
        return "could not connect to the Haply Inverse Service at " + uri + ": " + cause;
    }

    /** The address of the service. */
    public URI uri() {
        return uri;
    }

    /** Why the connection ended (closed by the service, failed), or null while it is open. */
    public String lostReason() {
        return lost;
    }

    /** True if {@link #close()} ran and the service's socket took its zero force. */
    public boolean closedAfterZero() {
        return closedAfterZero;
    }

    /**
     * True if {@link #close()} saw the service close its side before it aborted the socket: the service then read
     * every message up to the zero force. False if it aborted first (the service still busy with earlier messages
     * after 250 ms): the reset may discard the messages it had not read, the zero force among them, and the service's
     * own zero on disconnect is what stops the force. For tests.
     */
    boolean peerClosedBeforeAbort() {
        return peerClosedBeforeAbort;
    }

    /** True once {@link #close()} ran. */
    public boolean isClosed() {
        return closed;
    }

    /**
     * Sends one set_cursor_force (newtons, the service's axes) to the Inverse3, without waiting. Returns false,
     * sending nothing, while the previous message is still being written (the socket takes one at a time).
     *
     * @throws HaplyLinkException if the connection is lost or closed
     */
    public boolean sendForce(double fx, double fy, double fz) {
        String why = lost;
        if (why != null) {
            throw new HaplyLinkException(why);
        }
        if (closed) {
            throw new HaplyLinkException("the connection to the Haply Inverse Service at " + uri + " is closed");
        }
        return trySend(fx, fy, fz);
    }

    private boolean trySend(double fx, double fy, double fz) {
        return trySend(fx, fy, fz, false, false);
    }

    /**
     * Sends an empty message, {@code {}} (what the haply crate's {@code send_ping} sends "to keep the WebSocket
     * connection alive"), which the service answers with a state frame; no command. Returns false, sending
     * nothing, while the previous message is still being written or once the connection is lost or closed.
     */
    boolean ping() {
        return lost == null && !closed && trySend(0, 0, 0, true, false);
    }

    /**
     * Sends one message unless another is being written; {@code closing}: the zero force of {@link #close()}, the only
     * message sent once closed. The closed flag is read after taking the sending flag, so a force whose caller saw
     * the client open just before {@link #close()} either goes out before the zero force or not at all.
     */
    private boolean trySend(double fx, double fy, double fz, boolean empty, boolean closing) {
        if (!sending.compareAndSet(false, true)) {
            busy++;
            return false;
        }
        try {
            if (closed && !closing) {
                return false;
            }
            CompletableFuture<WebSocket> p = pending;
            if (p != null) {
                if (!p.isDone()) {
                    busy++;
                    return false;
                }
                if (p.isCompletedExceptionally()) {
                    lose("a message to the Haply Inverse Service at " + uri + " could not be sent (" + failureOf(p)
                            + "): was the service stopped or restarted?");
                    return false;
                }
            }
            WebSocket ws = socket;
            sentNanos = System.nanoTime();
            pending = ws.sendText(empty ? "{}" : out.force(fx, fy, fz), true);
            sent++;
            return true;
        } catch (RuntimeException e) {
            lose("a message to the Haply Inverse Service at " + uri + " could not be sent (" + e
                    + "): was the service stopped or restarted?");
            return false;
        } finally {
            sending.set(false);
        }
    }

    private static String failureOf(CompletableFuture<WebSocket> p) {
        try {
            p.getNow(null);
            return "unknown";
        } catch (Exception e) {
            return String.valueOf(e.getCause() != null ? e.getCause() : e);
        }
    }

    /**
     * Sends zero force from any thread, waiting at most 100 ms for the socket to take it (and for a message still
     * being written to go first); never throws. Returns true if the zero force was written.
     */
    public boolean zeroForce() {
        long deadline = System.nanoTime() + 100_000_000L;
        while (lost == null && socket != null) {
            if (trySend(0, 0, 0, false, true)) {
                CompletableFuture<WebSocket> p = pending;
                try {
                    p.get(Math.max(1, (deadline - System.nanoTime()) / 1_000_000L), TimeUnit.MILLISECONDS);
                    return true;
                } catch (Exception e) {
                    return false;
                }
            }
            if (System.nanoTime() - deadline > 0) {
                return false;
            }
            try {
                Thread.sleep(1);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return false;
            }
        }
        return false;
    }

    /**
     * Copies the newest state into {@code into}, from any thread, without blocking the socket; returns the number
     * of frames parsed so far (a new number means a new frame). No allocation.
     */
    public long read(InverseState into) {
        while (true) {
            int s1 = seq;
            if ((s1 & 1) != 0) {
                Thread.onSpinWait();
                continue;
            }
            into.copyFrom(published);
            VarHandle.loadLoadFence();
            if (seq == s1) {
                return into.frames;
            }
        }
    }

    /** Messages sent since the connection opened (the handshake not counted). */
    public long messagesSent() {
        return sent;
    }

    /** Sends skipped because the previous message was still being written. */
    public long sendsSkipped() {
        return busy;
    }

    /** Frames that were not valid JSON objects (counted, skipped). */
    public long badFrames() {
        return receiver.bad;
    }

    /** Round trips measured (send of a force to the parsed state frame that followed). */
    public long roundTripCount() {
        return roundTripCount;
    }

    /**
     * The round trip (a force sent to the state frame that answered it, parsed and readable) at quantile q
     * (0..1) over the last {@value #WINDOW}, in nanoseconds; -1 if none was measured.
     */
    public long roundTripNanos(double q) {
        long n = Math.min(roundTripCount, WINDOW);
        if (n == 0) {
            return -1;
        }
        long[] copy = Arrays.copyOf(roundTrips, (int) n);
        Arrays.sort(copy);
        int i = (int) Math.min(n - 1, Math.max(0, Math.round(q * (n - 1))));
        return copy[i];
    }

    private void lose(String why) {
        if (lost == null && !closed) {
            lost = why;
            System.err.println("tactus: " + why);
        }
    }

    /** Sends zero force (waiting at most 100 ms), closes the socket (at most 250 ms more) and removes the hook. */
    @Override
    public void close() {
        if (closed) {
            return;
        }
        closed = true;    // from here sendForce refuses, so nothing can follow the zero force
        closedAfterZero = zeroForce();
        WebSocket ws = socket;
        if (ws != null) {
            try {
                ws.sendClose(WebSocket.NORMAL_CLOSURE, "tactus closed").get(250, TimeUnit.MILLISECONDS);
                // wait (at most 250 ms) for the service's own close: aborting while its answers are still unread
                // resets the connection, and a reset can discard our zero force before the service has read it
                long until = System.nanoTime() + 250_000_000L;
                while (!peerClosed && System.nanoTime() - until < 0) {
                    Thread.sleep(1);
                }
                peerClosedBeforeAbort = peerClosed;
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            } catch (Exception e) {
                // the socket may already be gone: abort below
            }
            ws.abort();
        }
        Thread h = hook;
        if (h != null && Thread.currentThread() != h) {
            try {
                Runtime.getRuntime().removeShutdownHook(h);
            } catch (IllegalStateException e) {
                // shutting down: the hook runs or ran
            }
        }
    }

    private void closeFromHook() {
        close();
    }

    @Override
    public String toString() {
        return "InverseServiceClient[" + uri + (lost != null ? ", lost: " + lost : closed ? ", closed" : ", open") + "]";
    }

    /** The socket's listener: gathers each text message, parses it and publishes the state. */
    private final class Receiver implements WebSocket.Listener {
        private final StringBuilder inbox = new StringBuilder(4096);
        private final InverseMessageParser parser = new InverseMessageParser();
        private final InverseState scratch = new InverseState();
        private final InverseState good = new InverseState();
        private char[] chars = new char[4096];
        volatile long bad;
        volatile long badRun;
        volatile String lastBad;

        @Override
        public void onOpen(WebSocket ws) {
            ws.request(1);
        }

        @Override
        public CompletionStage<?> onText(WebSocket ws, CharSequence data, boolean last) {
            inbox.append(data);
            if (last) {
                handle();
                inbox.setLength(0);
            }
            ws.request(1);
            return null;
        }

        private void handle() {
            int n = inbox.length();
            if (chars.length < n) {
                chars = new char[Math.max(n, chars.length * 2)];
            }
            inbox.getChars(0, n, chars, 0);
            try {
                parser.parse(chars, n, scratch);
            } catch (IOException | RuntimeException e) {
                scratch.copyFrom(good);
                String m = String.valueOf(e.getMessage());
                int eol = m.indexOf('\n');
                lastBad = (eol < 0 ? m : m.substring(0, eol)) + "; it began: " + new String(chars, 0, Math.min(n, 80));
                bad++;
                badRun++;
                return;
            }
            badRun = 0;
            good.copyFrom(scratch);
            int s = seq;
            seq = s + 1;
            VarHandle.storeStoreFence();
            published.copyFrom(good);
            seq = s + 2;
            long t = sentNanos;
            if (t != 0) {
                sentNanos = 0;
                long c = roundTripCount;
                roundTrips[(int) (c & (WINDOW - 1))] = System.nanoTime() - t;
                roundTripCount = c + 1;
            }
        }

        @Override
        public CompletionStage<?> onBinary(WebSocket ws, ByteBuffer data, boolean last) {
            ws.request(1);
            return null;
        }

        @Override
        public CompletionStage<?> onClose(WebSocket ws, int statusCode, String reason) {
            peerClosed = true;
            lose("the Haply Inverse Service at " + uri + " closed the connection (code " + statusCode
                    + (reason == null || reason.isEmpty() ? "" : ", " + reason) + "): was it stopped or restarted?");
            return null;
        }

        @Override
        public void onError(WebSocket ws, Throwable error) {
            peerClosed = true;
            lose("the connection to the Haply Inverse Service at " + uri + " failed: " + error);
        }
    }
}
