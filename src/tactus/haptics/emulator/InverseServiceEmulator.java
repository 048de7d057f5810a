package tactus.haptics.emulator;

import java.io.IOException;
import java.io.StringWriter;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.SocketException;
import java.net.URI;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;

import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonGenerator;
import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonToken;

/**
 * An emulator of Haply's Inverse Service: a WebSocket server on localhost that speaks the service's documented
 * JSON, with one simulated Inverse3 ({@link SimulatedInverse3}) and optionally a VerseGrip. As the service
 * (docs.haply.co, "WebSocket Protocol"): on connect it sends a full snapshot (config, state and status of every
 * device); it answers every message it receives with exactly one frame: the full snapshot if the message asks
 * for it ({@code session.force_render_full_state}), else the state and status of every device. A
 * {@code set_cursor_force} for its Inverse3 sets the force on the simulated handle; the simulation advances by
 * the real time since the previous message (or a fixed step: {@link #setLockstep(double)}).
 *
 * <p>What happens to a commanded force follows the documentation where it speaks, and is configurable to the worst
 * case where it does not (see {@code docs/haptics.md}, "What the service does when its client vanishes"):
 * <ul>
 * <li>the documentation ("Control Commands") says a {@code set_cursor_force} is per tick, "applied once and
 * forgotten — if you stop sending them, the device returns to idle", without saying after how long: here a force
 * lapses to zero {@link #setCommandHold hold} after the last force command of the session that sent it
 * ({@value #DOCUMENTED_HOLD_MS} ms by default; forever in the worst case);</li>
 * <li>"one connection = one session; when the connection closes, the session is destroyed": here the force of a
 * session whose connection ends goes to zero at once, unless {@link #setKeepForceOnClose} (the worst case);</li>
 * <li>"multiple sessions can coexist", and the events channel has a {@code device-busy} event ("device is in use
 * by another session"): here a force from any session replaces the force (last writer wins), unless
 * {@link #setExclusive} makes the first session that sends a force the device's owner until its connection
 * ends, the forces of the others being ignored (the worst case for a guard in a second session).</li>
 * </ul>
 * A 1 kHz device thread applies the hold; {@link #forceZeroedAtNanos()} says when the force last went to zero.
 *
 * <p>HTTP on the same port (docs.haply.co, "HTTP"): {@code GET /version}, {@code GET /devices} (raw, as the
 * {@code haply} crate reads them; {@code ?format=json} wraps them in the {@code {ok, data}} envelope),
 * {@code GET /sessions} and {@code GET /sessions/{id}} (in the envelope, as the crate reads them); anything else
 * is answered 404 with {@code {"ok":false,"error":…}}.
 *
 * <p>In-process: {@code InverseServiceEmulator.start(0)} (any free port; {@link #uri()} says which). Standalone,
 * on the service's own port: {@code java -cp Tactus.jar:jackson-core-2.17.2.jar tactus.haptics.emulator.InverseServiceEmulator}
 * (or {@code gradle inverseEmulator}); see {@link #main(String[])}.
 */
public final class InverseServiceEmulator implements AutoCloseable {
    /** The service's port. */
    public static final int SERVICE_PORT = 10001;
    /** The emulated Inverse3's id. */
    public static final String DEVICE_ID = "7E31";
    /** The emulated VerseGrip's id. */
    public static final String GRIP_ID = "6B02";
    /**
     * How long a force stays on after its session's last force command by default, in milliseconds: the
     * documentation says only that commands are "applied once and forgotten"; 10 ms (ten of the service's ticks at
     * 1 kHz) is this emulator's reading of it.
     */
    public static final int DOCUMENTED_HOLD_MS = 10;
    /** The version the emulator reports on {@code GET /version}. */
    public static final String VERSION = "3.5.0";

    private final ServerSocket server;
    private final SimulatedInverse3 device;
    private final JsonFactory json = new JsonFactory();
    private final List<WebSocketServerConnection> connections = new CopyOnWriteArrayList<>();
    private final Thread acceptor;
    private volatile boolean closed;
    private volatile double lockstep;
    private long lastNanos;
    private long sessionId = 100;

    private volatile String gripKind;   // null, "verse_grip" or "wireless_verse_grip"
    private volatile double gripW = 1;
    private volatile double gripX;
    private volatile double gripY;
    private volatile double gripZ;
    private volatile boolean buttonA;
    private volatile boolean buttonB;
    private volatile boolean buttonC;

    private volatile long holdNanos = DOCUMENTED_HOLD_MS * 1_000_000L;
    private volatile boolean keepOnClose;
    private volatile boolean exclusive;
    private WebSocketServerConnection owner;          // the session whose force is on (guarded by this)
    private volatile long ownerLingerNanos;           // how long a closed owner session still owns the device
    private long ownerReleasedAtNanos;                // when a closed owner's ownership ends (guarded by this)
    private volatile long lastForceNanos;             // its last force command (written holding this)
    private volatile long forceZeroedAtNanos;
    private volatile long forcesRefused;
    private volatile long forcesLapsed;
    private final Thread ticker;
    private final java.util.Map<WebSocketServerConnection, Long> sessionIds = new java.util.concurrent.ConcurrentHashMap<>();
    private final java.util.Map<WebSocketServerConnection, String> profiles = new java.util.concurrent.ConcurrentHashMap<>();

    private volatile long messages;
    private volatile long forceCommands;
    private volatile long connectionsOpened;
    private volatile long zeroedOnDisconnect;
    private volatile String lastProfile;
    private volatile boolean firstMessagesHadSession = true;
    private volatile boolean laterMessagesHadSession;
    private volatile boolean recording;
    private volatile boolean mute;
    private final List<double[]> receivedForces = new ArrayList<>();
    private final List<double[]> sentPositions = new ArrayList<>();
    private final double[] tmpP = new double[3];
    private final double[] tmpV = new double[3];
    private final double[] tmpF = new double[3];
    private final List<Listed> listed = new CopyOnWriteArrayList<>();   // in the order the service lists them
    private volatile java.util.function.UnaryOperator<String> rewrite;

    /** One Inverse3 the emulator lists: its id, handedness and simulation. */
    private static final class Listed {
        final String id;
        final String handedness;
        final SimulatedInverse3 sim;

        Listed(String id, String handedness, SimulatedInverse3 sim) {
            this.id = id;
            this.handedness = handedness;
            this.sim = sim;
        }
    }

    private InverseServiceEmulator(ServerSocket server, SimulatedInverse3 device) {
        this.server = server;
        this.device = device;
        this.acceptor = new Thread(this::accept, "tactus-inverse-emulator-accept");
        acceptor.setDaemon(true);
        this.ticker = new Thread(this::tick, "tactus-inverse-emulator-device");
        ticker.setDaemon(true);
        listed.add(new Listed(DEVICE_ID, "right", device));
    }

    /**
     * Lists another Inverse3 beside the first ({@link #DEVICE_ID}, right-handed): with this id (not yet listed),
     * handedness ("left" or "right") and simulation, before the others if first is true, else after them. Its
     * forces are applied as they come (the hold, exclusivity and lapse settings concern the first device only).
     */
    public void addInverse3(String id, String handedness, SimulatedInverse3 sim, boolean first) {
        if (id == null || id.isEmpty() || sim == null || !("left".equals(handedness) || "right".equals(handedness))) {
            throw new IllegalArgumentException("InverseServiceEmulator.addInverse3: need an id, \"left\" or \"right\" "
                    + "and a simulated device, got " + id + ", " + handedness + ", " + sim);
        }
        for (Listed l : listed) {
            if (l.id.equals(id)) {
                throw new IllegalArgumentException("InverseServiceEmulator.addInverse3: the id " + id + " is listed already");
            }
        }
        if (first) {
            listed.add(0, new Listed(id, handedness, sim));
        } else {
            listed.add(new Listed(id, handedness, sim));
        }
    }

    /** The simulated Inverse3 listed with this id, or null. */
    public SimulatedInverse3 device(String id) {
        for (Listed l : listed) {
            if (l.id.equals(id)) {
                return l.sim;
            }
        }
        return null;
    }

    /**
     * Passes every message the emulator sends over the WebSocket (snapshots and state frames) through this function
     * first (null: none), to inject faults a real service might show: text that is not JSON, null fields, absurd
     * numbers, unknown device types.
     */
    public void setRewrite(java.util.function.UnaryOperator<String> f) {
        rewrite = f;
    }

    /** Starts an emulator with a fresh {@link SimulatedInverse3} on this port of localhost (0: any free port). */
    public static InverseServiceEmulator start(int port) {
        return start(port, new SimulatedInverse3());
    }

    /**
     * Starts an emulator with this simulated device on this port of localhost (0: any free port).
     *
     * @throws IllegalStateException if the port is taken (for example by the real service)
     */
    public static InverseServiceEmulator start(int port, SimulatedInverse3 device) {
        if (device == null) {
            throw new IllegalArgumentException("InverseServiceEmulator.start: device must not be null");
        }
        ServerSocket s;
        try {
            s = new ServerSocket(port, 8, InetAddress.getLoopbackAddress());
        } catch (IOException e) {
            throw new IllegalStateException("InverseServiceEmulator: cannot listen on localhost:" + port + " (" + e.getMessage()
                    + "); is the Haply Inverse Service or another emulator running?", e);
        }
        InverseServiceEmulator emu = new InverseServiceEmulator(s, device);
        emu.acceptor.start();
        emu.ticker.start();
        return emu;
    }

    /** The port it listens on. */
    public int port() {
        return server.getLocalPort();
    }

    /** Its address, {@code ws://localhost:port}. */
    public URI uri() {
        return URI.create("ws://localhost:" + port());
    }

    /** The simulated Inverse3. */
    public SimulatedInverse3 device() {
        return device;
    }

    /**
     * Advances the simulation by this fixed step (seconds, > 0) per message instead of the real time between
     * messages (0: real time, the default), for deterministic tests.
     */
    public void setLockstep(double dtSeconds) {
        if (!(dtSeconds >= 0) || !Double.isFinite(dtSeconds)) {
            throw new IllegalArgumentException("InverseServiceEmulator.setLockstep: need a step >= 0 s, got " + dtSeconds);
        }
        lockstep = dtSeconds;
    }

    /**
     * How long a commanded force stays on after the last force command of the session that sent it, in
     * milliseconds (>= 0; {@link Long#MAX_VALUE}: until another command, the worst case). Default
     * {@value #DOCUMENTED_HOLD_MS} ms.
     */
    public void setCommandHold(long millis) {
        if (millis < 0) {
            throw new IllegalArgumentException("InverseServiceEmulator.setCommandHold: need a hold >= 0 ms, got " + millis);
        }
        holdNanos = millis >= Long.MAX_VALUE / 1_000_000L ? Long.MAX_VALUE : millis * 1_000_000L;
    }

    /** Keeps the force of a session whose connection ends (true: the worst case) instead of zeroing it (default). */
    public void setKeepForceOnClose(boolean keep) {
        keepOnClose = keep;
    }

    /**
     * Makes the first session that sends a force the device's owner until its connection ends, ignoring the forces
     * of every other session (true: the worst case), instead of applying the last force received (default).
     */
    public void setExclusive(boolean on) {
        exclusive = on;
    }

    /**
     * Keeps an exclusive owner's ownership for this long after its connection ends, in milliseconds (0, the
     * default: it ends with the connection): a service that notices a vanished client late.
     */
    public void setOwnerLinger(long ms) {
        if (ms < 0) {
            throw new IllegalArgumentException("owner linger " + ms + " ms: give 0 or more milliseconds");
        }
        ownerLingerNanos = ms * 1_000_000L;
    }

    /**
     * The worst case the documentation leaves open, all at once: a force is held until another command, kept
     * when its session's connection ends, and only the owner session's forces count.
     */
    public void setWorstCase() {
        setCommandHold(Long.MAX_VALUE);
        setKeepForceOnClose(true);
        setExclusive(true);
    }

    /** The {@link System#nanoTime()} at which the device's force last went from non-zero to zero (0: never). */
    public long forceZeroedAtNanos() {
        return forceZeroedAtNanos;
    }

    /** Force commands ignored because another session owned the device ({@link #setExclusive}). */
    public long forcesRefused() {
        return forcesRefused;
    }

    /** Times a force lapsed to zero because its session sent no force command for the hold time. */
    public long forcesLapsed() {
        return forcesLapsed;
    }

    /** The device's force now (N, the service's axes). */
    public double[] force() {
        double[] f = new double[3];
        device.force(f);
        return f;
    }

    /** WebSocket connections open now. */
    public int openConnections() {
        return connections.size();
    }

    /**
     * Lists a VerseGrip beside the Inverse3: "verse_grip" (wired: one button, reported as {@code button}),
     * "wireless_verse_grip" (buttons a, b, c, a battery) or null for none (the default).
     */
    public void setVerseGrip(String kind) {
        if (kind != null && !kind.equals("verse_grip") && !kind.equals("wireless_verse_grip")) {
            throw new IllegalArgumentException("InverseServiceEmulator.setVerseGrip: \"verse_grip\", \"wireless_verse_grip\" "
                    + "or null, got " + kind);
        }
        gripKind = kind;
    }

    /** Sets the VerseGrip's orientation quaternion (normalised here). */
    public void setGripOrientation(double w, double x, double y, double z) {
        double n = Math.sqrt(w * w + x * x + y * y + z * z);
        if (!(n > 0)) {
            throw new IllegalArgumentException("InverseServiceEmulator.setGripOrientation: zero quaternion");
        }
        gripW = w / n;
        gripX = x / n;
        gripY = y / n;
        gripZ = z / n;
    }

    /** Presses or releases the VerseGrip's buttons (the wired grip reports a only). */
    public void setButtons(boolean a, boolean b, boolean c) {
        buttonA = a;
        buttonB = b;
        buttonC = c;
    }

    /** Messages received from all clients. */
    public long messagesReceived() {
        return messages;
    }

    /** set_cursor_force commands received for the Inverse3. */
    public long forceCommands() {
        return forceCommands;
    }

    /** WebSocket connections accepted. */
    public long connectionsOpened() {
        return connectionsOpened;
    }

    /**
     * Times a client's connection ended while ending a session zeroes its force (the default; not with
     * {@link #setKeepForceOnClose}); the force is zeroed if that session's force was on.
     */
    public long zeroedOnDisconnect() {
        return zeroedOnDisconnect;
    }

    /** The profile name of the last session handshake, or null. */
    public String lastProfile() {
        return lastProfile;
    }

    /** True if every connection's first message carried a session object. */
    public boolean firstMessagesHadSession() {
        return firstMessagesHadSession;
    }

    /** True if a message after a connection's first carried a session configure (a profile) again. */
    public boolean laterMessagesHadProfile() {
        return laterMessagesHadSession;
    }

    /** Starts or stops recording every force received and every position sent (for fidelity checks). */
    public synchronized void setRecording(boolean on) {
        recording = on;
    }

    /** The forces received while recording (N), in order. */
    public synchronized List<double[]> receivedForces() {
        return new ArrayList<>(receivedForces);
    }

    /** The positions sent while recording (m), in order. */
    public synchronized List<double[]> sentPositions() {
        return new ArrayList<>(sentPositions);
    }

    /** Stops answering messages (true) while keeping the connections open, as a hung service; or answers again. */
    public void setMute(boolean on) {
        mute = on;
    }

    /** Closes every client connection at once, with no closing handshake, as a crashed or restarted service. */
    public void dropConnections() {
        for (WebSocketServerConnection c : connections) {
            c.close();
        }
    }

    /** Stops listening and closes every connection (with a closing handshake, code 1001). */
    @Override
    public void close() {
        closed = true;
        ticker.interrupt();
        try {
            server.close();
        } catch (IOException e) {
            // nothing to do
        }
        for (WebSocketServerConnection c : connections) {
            c.close(1001, "emulator stopped");
        }
        try {
            acceptor.join(1000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    // ------------------------------------------------------------------------------------------------ serving

    private void accept() {
        while (!closed) {
            Socket s;
            try {
                s = server.accept();
            } catch (IOException e) {
                return;
            }
            Thread t = new Thread(() -> serve(s), "tactus-inverse-emulator-connection");
            t.setDaemon(true);
            t.start();
        }
    }

    private void serve(Socket s) {
        WebSocketServerConnection c;
        try {
            c = new WebSocketServerConnection(s);
            if (!c.handshake(this::answerHttp)) {
                c.close();
                return;
            }
        } catch (IOException e) {
            closeQuietly(s);
            return;
        }
        synchronized (this) {
            sessionIds.put(c, ++sessionId);
        }
        connections.add(c);
        connectionsOpened++;
        try {
            c.sendText(rewritten(frame(sessionIds.getOrDefault(c, 0L), true, true)));
            boolean first = true;
            for (String m = c.readText(); m != null; m = c.readText()) {
                String reply = handle(c, m, first);
                if (!mute) {
                    c.sendText(rewritten(reply));
                }
                first = false;
            }
        } catch (SocketException e) {
            // dropped
        } catch (IOException e) {
            // ended inside a frame
        } finally {
            connections.remove(c);
            c.close();
            ended(c);
        }
    }

    private String rewritten(String frame) {
        java.util.function.UnaryOperator<String> f = rewrite;
        return f == null ? frame : f.apply(frame);
    }

    /** A session's connection ended: its force goes to zero (unless kept), and it owns the device no more. */
    private synchronized void ended(WebSocketServerConnection c) {
        sessionIds.remove(c);
        profiles.remove(c);
        if (!keepOnClose) {
            if (owner == c || owner == null) {
                applyForce(0, 0, 0);
            }
            zeroedOnDisconnect++;
        }
        if (owner == c) {
            if (ownerLingerNanos > 0) {
                ownerReleasedAtNanos = System.nanoTime() + ownerLingerNanos;
            } else {
                owner = null;
            }
        }
    }

    /** Whether a session other than {@code from} owns the device at {@code now}. Called holding this. */
    private boolean ownedByAnother(WebSocketServerConnection from, long now) {
        if (owner == null || owner == from) {
            return false;
        }
        return connections.contains(owner) || now - ownerReleasedAtNanos < 0;
    }

    /** Sets the device's force, noting when it goes from non-zero to zero. Called holding this. */
    private void applyForce(double fx, double fy, double fz) {
        device.force(tmpF);
        boolean wasOn = tmpF[0] != 0 || tmpF[1] != 0 || tmpF[2] != 0;
        device.setForce(fx, fy, fz);
        if (wasOn && fx == 0 && fy == 0 && fz == 0) {
            forceZeroedAtNanos = System.nanoTime();
        }
    }

    /**
     * The device thread: a force whose session sent no force command for the hold lapses. It wakes when the hold
     * of the last command runs out (at least 1 ms, at most 10 ms apart; every 50 ms with an endless hold), so a
     * client that sends every millisecond costs about a hundred wake-ups a second, not a thousand; a force lapses
     * at most 10 ms after its hold.
     */
    private void tick() {
        double[] tick = new double[3];
        long wait = 1_000_000L;
        while (!closed) {
            java.util.concurrent.locks.LockSupport.parkNanos(wait);
            if (Thread.interrupted()) {
                return;
            }
            long hold = holdNanos;
            if (hold == Long.MAX_VALUE) {
                wait = 50_000_000L;
                continue;
            }
            long left = lastForceNanos + hold - System.nanoTime();
            device.force(tick);   // the device's own lock only: the serving threads are not held up
            boolean on = tick[0] != 0 || tick[1] != 0 || tick[2] != 0;
            if (on && left < 0) {
                synchronized (this) {   // look again under the lock: a command may have come meanwhile
                    if (lastForceNanos + hold - System.nanoTime() < 0) {
                        device.force(tmpF);
                        if (tmpF[0] != 0 || tmpF[1] != 0 || tmpF[2] != 0) {
                            applyForce(0, 0, 0);
                            forcesLapsed++;
                        }
                    }
                }
            }
            wait = on && left > 0 ? Math.max(1_000_000L, Math.min(10_000_000L, left + 100_000L)) : 10_000_000L;
        }
    }

    private static void closeQuietly(Socket s) {
        try {
            s.close();
        } catch (IOException e) {
            // nothing to do
        }
    }

    /** Handles one message and returns the frame that answers it. */
    synchronized String handle(WebSocketServerConnection from, String message, boolean first) throws IOException {
        messages++;
        String[] commandFor = new String[1];
        boolean full = false;
        boolean session = false;
        boolean profile = false;
        boolean force = false;
        double fx = 0;
        double fy = 0;
        double fz = 0;
        try (JsonParser p = json.createParser(message)) {
            if (p.nextToken() == JsonToken.START_OBJECT) {
                while (p.nextToken() == JsonToken.FIELD_NAME) {
                    String name = p.currentName();
                    JsonToken t = p.nextToken();
                    if ("session".equals(name) && t == JsonToken.START_OBJECT) {
                        session = true;
                        while (p.nextToken() == JsonToken.FIELD_NAME) {
                            String n = p.currentName();
                            JsonToken v = p.nextToken();
                            if ("force_render_full_state".equals(n)) {
                                full = true;
                                p.skipChildren();
                            } else if ("configure".equals(n) && v == JsonToken.START_OBJECT) {
                                String prof = profileName(p);
                                if (prof != null) {
                                    profile = true;
                                    lastProfile = prof;
                                    if (from != null) {
                                        profiles.put(from, prof);
                                    }
                                }
                            } else {
                                p.skipChildren();
                            }
                        }
                    } else if ("inverse3".equals(name) && t == JsonToken.START_ARRAY) {
                        while (p.nextToken() == JsonToken.START_OBJECT) {
                            double[] cmd = inverse3Command(p, commandFor);
                            if (cmd != null && !DEVICE_ID.equals(commandFor[0])) {
                                SimulatedInverse3 other = device(commandFor[0]);
                                if (other != null) {
                                    other.setForce(cmd[0], cmd[1], cmd[2]);
                                }
                            } else if (cmd != null) {
                                force = true;
                                fx = cmd[0];
                                fy = cmd[1];
                                fz = cmd[2];
                            }
                        }
                    } else {
                        p.skipChildren();
                    }
                }
            }
        } catch (IOException e) {
            return frame(idOf(from), false, true);   // not JSON: answered with the state, as one message gets one frame
        }
        if (first && !session) {
            firstMessagesHadSession = false;
        }
        if (!first && profile) {
            laterMessagesHadSession = true;
        }
        long now = System.nanoTime();
        if (force) {
            forceCommands++;
            if (exclusive && ownedByAnother(from, now)) {
                forcesRefused++;   // device-busy: another session owns it
            } else {
                owner = from;
                lastForceNanos = now;
                applyForce(fx, fy, fz);
                if (recording) {
                    receivedForces.add(new double[] {fx, fy, fz});
                }
            }
        }
        double dt = lockstep > 0 ? lockstep : lastNanos == 0 ? 0 : Math.min(0.05, (now - lastNanos) * 1e-9);
        lastNanos = now;
        for (Listed l : listed) {
            l.sim.advance(dt);
        }
        return frame(idOf(from), full, true);
    }

    private long idOf(WebSocketServerConnection c) {
        Long id = c == null ? null : sessionIds.get(c);
        return id == null ? 0 : id;
    }

    // ------------------------------------------------------------------------------------------------ HTTP

    /**
     * Answers a plain HTTP request on the service's port (docs.haply.co, "HTTP"): {@code GET /version} and
     * {@code GET /devices} raw ({@code ?format=json}: in the envelope), {@code GET /sessions} and
     * {@code GET /sessions/{id}} in the {@code {ok, data}} envelope; else 404, or 405 for another method.
     */
    String[] answerHttp(String method, String target) {
        int q = target.indexOf('?');
        String path = q < 0 ? target : target.substring(0, q);
        String query = q < 0 ? "" : target.substring(q + 1);
        boolean envelope = ("&" + query + "&").contains("&format=json&");
        if (path.length() > 1 && path.endsWith("/")) {
            path = path.substring(0, path.length() - 1);
        }
        try {
            if (!"GET".equals(method)) {
                return new String[] {"405 Method Not Allowed", error("the Tactus emulator answers GET only, not " + method)};
            }
            if (path.equals("/version")) {
                String v = version();
                return new String[] {"200 OK", envelope ? "{\"ok\":true,\"data\":" + v + "}" : v};
            }
            if (path.equals("/devices")) {
                String d = frame(0, true, false);
                return new String[] {"200 OK", envelope ? "{\"ok\":true,\"data\":" + d + "}" : d};
            }
            if (path.equals("/sessions")) {
                return new String[] {"200 OK", sessions(-1)};
            }
            if (path.startsWith("/sessions/")) {
                long id;
                try {
                    id = Long.parseLong(path.substring("/sessions/".length()));
                } catch (NumberFormatException e) {
                    return new String[] {"400 Bad Request", error("not a session id: " + path.substring(10))};
                }
                String one = sessions(id);
                return one == null ? new String[] {"404 Not Found", error("no session " + id)} : new String[] {"200 OK", one};
            }
        } catch (IOException e) {
            return new String[] {"500 Internal Server Error", error(String.valueOf(e))};
        }
        return new String[] {"404 Not Found", error("no route " + path + " in the Tactus Inverse Service emulator")};
    }

    private String error(String why) {
        StringWriter w = new StringWriter();
        try (JsonGenerator g = json.createGenerator(w)) {
            g.writeStartObject();
            g.writeBooleanField("ok", false);
            g.writeStringField("error", why);
            g.writeEndObject();
        } catch (IOException e) {
            return "{\"ok\":false}";
        }
        return w.toString();
    }

    private String version() throws IOException {
        StringWriter w = new StringWriter();
        try (JsonGenerator g = json.createGenerator(w)) {
            g.writeStartObject();
            g.writeStringField("build_time", "1970-01-01T00:00:00Z");
            g.writeStringField("git_branch", "tactus-emulator");
            g.writeStringField("git_describe", VERSION + "-tactus-emulator");
            g.writeStringField("git_hash", "00000000");
            g.writeStringField("git_tag", VERSION);
            g.writeStringField("project_name", "haply-inverse-service");
            g.writeStringField("project_version", VERSION + ".0");
            g.writeEndObject();
        }
        return w.toString();
    }

    /** All sessions (id < 0) in the envelope, or one session's, or null if there is no such session. */
    private String sessions(long only) throws IOException {
        StringWriter w = new StringWriter();
        boolean found = false;
        try (JsonGenerator g = json.createGenerator(w)) {
            g.writeStartObject();
            g.writeBooleanField("ok", true);
            g.writeFieldName("data");
            if (only < 0) {
                g.writeStartObject();
                g.writeNumberField("session_count", sessionIds.size());
                g.writeArrayFieldStart("sessions");
            }
            List<java.util.Map.Entry<WebSocketServerConnection, Long>> open = new ArrayList<>(sessionIds.entrySet());
            open.sort(java.util.Map.Entry.comparingByValue());
            for (java.util.Map.Entry<WebSocketServerConnection, Long> e : open) {
                if (only >= 0 && e.getValue() != only) {
                    continue;
                }
                found = true;
                g.writeStartObject();
                g.writeNumberField("session_id", e.getValue());
                g.writeObjectFieldStart("config");
                String prof = profiles.get(e.getKey());
                if (prof != null) {
                    g.writeObjectFieldStart("profile");
                    g.writeStringField("name", prof);
                    g.writeEndObject();
                }
                g.writeEndObject();
                g.writeEndObject();
            }
            if (only < 0) {
                g.writeEndArray();
                g.writeEndObject();
            }
            g.writeEndObject();
        }
        return only >= 0 && !found ? null : w.toString();
    }

    private static String profileName(JsonParser p) throws IOException {
        String found = null;
        while (p.nextToken() == JsonToken.FIELD_NAME) {
            String n = p.currentName();
            JsonToken v = p.nextToken();
            if ("profile".equals(n) && v == JsonToken.START_OBJECT) {
                while (p.nextToken() == JsonToken.FIELD_NAME) {
                    String k = p.currentName();
                    JsonToken w = p.nextToken();
                    if ("name".equals(k) && w == JsonToken.VALUE_STRING) {
                        found = p.getText();
                    } else {
                        p.skipChildren();
                    }
                }
            } else {
                p.skipChildren();
            }
        }
        return found;
    }

    /** Reads one entry of the inverse3 list; returns its set_cursor_force vector (null: none), its device id in idOut[0]. */
    private static double[] inverse3Command(JsonParser p, String[] idOut) throws IOException {
        String id = null;
        double[] vector = null;
        while (p.nextToken() == JsonToken.FIELD_NAME) {
            String n = p.currentName();
            JsonToken v = p.nextToken();
            if ("device_id".equals(n) && v == JsonToken.VALUE_STRING) {
                id = p.getText();
            } else if ("commands".equals(n) && v == JsonToken.START_OBJECT) {
                while (p.nextToken() == JsonToken.FIELD_NAME) {
                    String c = p.currentName();
                    JsonToken w = p.nextToken();
                    if ("set_cursor_force".equals(c) && w == JsonToken.START_OBJECT) {
                        while (p.nextToken() == JsonToken.FIELD_NAME) {
                            String k = p.currentName();
                            JsonToken x = p.nextToken();
                            if ("vector".equals(k) && x == JsonToken.START_OBJECT) {
                                vector = new double[3];
                                while (p.nextToken() == JsonToken.FIELD_NAME) {
                                    String a = p.currentName();
                                    p.nextToken();
                                    double val = p.currentToken().isNumeric() ? p.getDoubleValue() : Double.NaN;
                                    if ("x".equals(a)) {
                                        vector[0] = val;
                                    } else if ("y".equals(a)) {
                                        vector[1] = val;
                                    } else if ("z".equals(a)) {
                                        vector[2] = val;
                                    }
                                }
                            } else {
                                p.skipChildren();
                            }
                        }
                    } else {
                        p.skipChildren();
                    }
                }
            } else {
                p.skipChildren();
            }
        }
        idOut[0] = id;
        return id == null ? null : vector;
    }

    /** The full snapshot (with each device's config) or a state frame, as JSON text. */
    synchronized String frame(long session, boolean full, boolean record) throws IOException {
        device.position(tmpP);
        device.velocity(tmpV);
        device.force(tmpF);
        if (recording && record) {
            sentPositions.add(tmpP.clone());
        }
        StringWriter w = new StringWriter(1024);
        try (JsonGenerator g = json.createGenerator(w)) {
            g.writeStartObject();
            g.writeNumberField("session_id", session);
            g.writeArrayFieldStart("inverse3");
            for (Listed l : listed) {
                l.sim.position(tmpP);
                l.sim.velocity(tmpV);
                l.sim.force(tmpF);
                inverse3Entry(g, l, full);
            }
            g.writeEndArray();
            String kind = gripKind;
            g.writeArrayFieldStart("verse_grip");
            if ("verse_grip".equals(kind)) {
                grip(g, full, false);
            }
            g.writeEndArray();
            g.writeArrayFieldStart("wireless_verse_grip");
            if ("wireless_verse_grip".equals(kind)) {
                grip(g, full, true);
            }
            g.writeEndArray();
            g.writeEndObject();
        }
        return w.toString();
    }

    /** One entry of the inverse3 list, from tmpP, tmpV and tmpF. Called holding this. */
    private void inverse3Entry(JsonGenerator g, Listed l, boolean full) throws IOException {
        g.writeStartObject();
        g.writeStringField("device_id", l.id);
        if (full) {
            inverse3Config(g, l);
        }
        g.writeObjectFieldStart("state");
        vec(g, "cursor_position", tmpP);
        vec(g, "cursor_velocity", tmpV);
        g.writeObjectFieldStart("angular_position");
        g.writeNumberField("a0", 0.0);
        g.writeNumberField("a1", 0.0);
        g.writeNumberField("a2", 0.0);
        g.writeEndObject();
        g.writeObjectFieldStart("angular_velocity");
        g.writeNumberField("a0", 0.0);
        g.writeNumberField("a1", 0.0);
        g.writeNumberField("a2", 0.0);
        g.writeEndObject();
        quat(g, "body_orientation", 1, 0, 0, 0);
        vec(g, "current_cursor_force", tmpF);
        g.writeStringField("mode", "idle");
        g.writeStringField("control_domain", "cartesian");
        g.writeStringField("control_mode", forceCommands > 0 ? "force" : "idle");
        g.writeEndObject();
        g.writeObjectFieldStart("status");
        g.writeBooleanField("calibrated", true);
        g.writeBooleanField("in_use", connections.size() > 0);
        g.writeBooleanField("power_supply", true);
        g.writeBooleanField("ready", true);
        g.writeBooleanField("started", true);
        g.writeEndObject();
        g.writeEndObject();
    }

    private static void inverse3Config(JsonGenerator g, Listed l) throws IOException {
        g.writeObjectFieldStart("config");
        g.writeStringField("type", "inverse3");
        g.writeStringField("port", "emulated");
        g.writeObjectFieldStart("device_info");
        g.writeNumberField("major_version", 7);
        g.writeNumberField("minor_version", 4);
        g.writeStringField("id", l.id);
        g.writeNumberField("device_type", 4);
        g.writeStringField("uuid", "TACTUS-EMULATED-INVERSE3-" + l.id);
        g.writeEndObject();
        g.writeStringField("extended_device_id", "TACTUS-EMULATED-INVERSE3-" + l.id);
        g.writeStringField("extended_firmware_version", "tactus-emulator");
        g.writeObjectFieldStart("gravity_compensation");
        g.writeBooleanField("enabled", true);
        g.writeNumberField("scaling_factor", 1.0);
        g.writeEndObject();
        g.writeStringField("handedness", l.handedness);
        g.writeStringField("streaming_mode", "USB");
        g.writeObjectFieldStart("torque_scaling");
        g.writeBooleanField("enabled", true);
        g.writeEndObject();
        g.writeStringField("preset", "defaults");
        g.writeObjectFieldStart("basis");
        g.writeStringField("permutation", "XYZ");
        g.writeEndObject();
        g.writeEndObject();
    }

    private void grip(JsonGenerator g, boolean full, boolean wireless) throws IOException {
        g.writeStartObject();
        g.writeStringField("device_id", GRIP_ID);
        if (full) {
            g.writeObjectFieldStart("config");
            g.writeStringField("port", "emulated");
            g.writeStringField("type", wireless ? "wireless_verse_grip" : "verse_grip");
            if (wireless) {
                g.writeNumberField("major_version", 1);
                g.writeNumberField("minor_version", 0);
                g.writeNumberField("hardware_version", 1);
            }
            g.writeEndObject();
        }
        g.writeObjectFieldStart("state");
        quat(g, "orientation", gripW, gripX, gripY, gripZ);
        g.writeNumberField("hall", 0);
        if (wireless) {
            g.writeObjectFieldStart("buttons");
            g.writeBooleanField("a", buttonA);
            g.writeBooleanField("b", buttonB);
            g.writeBooleanField("c", buttonC);
            g.writeEndObject();
            g.writeNumberField("battery_level", 0.9);
        } else {
            g.writeBooleanField("button", buttonA);
        }
        g.writeEndObject();
        g.writeObjectFieldStart("status");
        g.writeBooleanField("ready", true);
        if (wireless) {
            g.writeBooleanField("connected", true);
            g.writeBooleanField("awake", true);
        } else {
            g.writeNumberField("error", 0);
        }
        g.writeEndObject();
        g.writeEndObject();
    }

    private static void vec(JsonGenerator g, String name, double[] v) throws IOException {
        g.writeObjectFieldStart(name);
        g.writeNumberField("x", v[0]);
        g.writeNumberField("y", v[1]);
        g.writeNumberField("z", v[2]);
        g.writeEndObject();
    }

    private static void quat(JsonGenerator g, String name, double w, double x, double y, double z) throws IOException {
        g.writeObjectFieldStart(name);
        g.writeNumberField("w", w);
        g.writeNumberField("x", x);
        g.writeNumberField("y", y);
        g.writeNumberField("z", z);
        g.writeEndObject();
    }

    /**
     * Runs the emulator until the process ends: {@code [--port N] [--hand still|tour] [--grip none|wired|wireless]
     * [--worst-case]} ({@link #setWorstCase()}: to see the Inverse3 guard at work).
     * Defaults: the service's port 10001, a hand that tours the workspace on a slow Lissajous path through a
     * spring (so that forces show as a lag), no VerseGrip.
     */
    public static void main(String[] args) throws InterruptedException {
        int port = SERVICE_PORT;
        boolean worst = false;
        String hand = "tour";
        String grip = null;
        for (int i = 0; i < args.length; i++) {
            String a = args[i];
            String next = i + 1 < args.length ? args[i + 1] : null;
            if ("--port".equals(a) && next != null) {
                port = Integer.parseInt(next);
                i++;
            } else if ("--hand".equals(a) && next != null) {
                hand = next;
                i++;
            } else if ("--worst-case".equals(a)) {
                worst = true;
            } else if ("--grip".equals(a) && next != null) {
                grip = "wired".equals(next) ? "verse_grip" : "wireless".equals(next) ? "wireless_verse_grip" : null;
                i++;
            } else {
                System.err.println("usage: InverseServiceEmulator [--port N] [--hand still|tour] [--grip none|wired|wireless] "
                        + "[--worst-case]");
                System.exit(2);
            }
        }
        SimulatedInverse3 dev = new SimulatedInverse3();
        if ("tour".equals(hand)) {
            dev.setHand(Hand3D.followingScript(InverseServiceEmulator::tour, 200, 2));
        }
        InverseServiceEmulator emu = start(port, dev);
        emu.setVerseGrip(grip);
        if (worst) {
            emu.setWorstCase();
        }
        System.out.println("Tactus Inverse Service emulator on " + emu.uri() + ": one Inverse3 (" + DEVICE_ID + ")"
                + (grip != null ? " and a " + grip.replace('_', ' ') : "") + ", hand: " + hand
                + (worst ? ", worst case (forces held, kept on close, one owner session)" : "") + ". Ctrl-C stops it.");
        Runtime.getRuntime().addShutdownHook(new Thread(emu::close));
        while (true) {
            Thread.sleep(5000);
            System.out.println("emulator: " + emu.connections.size() + " client(s), " + emu.messagesReceived() + " messages, "
                    + emu.forceCommands() + " forces");
        }
    }

    /** The standalone emulator's idle tour: a 3:2:1 Lissajous path through most of the workspace, 12 s a lap. */
    static void tour(double t, double[] out) {
        double w = 2 * Math.PI / 12;
        for (int i = 0; i < 3; i++) {
            double k = i == 0 ? 3 : i == 1 ? 2 : 1;
            out[i] = SimulatedInverse3.HOME[i] + 0.6 * SimulatedInverse3.HALF_EXTENT[i] * Math.sin(k * w * t + i);
        }
    }
}
