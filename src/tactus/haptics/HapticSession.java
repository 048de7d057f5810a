package tactus.haptics;

import processing.core.PApplet;
import processing.event.MouseEvent;
import tactus.PhysicalModel;
import tactus.Vect3D;
import tactus.haptics.emulator.BoardEmulator;
import tactus.haptics.emulator.HaplyConnection;
import tactus.haptics.emulator.SimulatedInverse3;
import tactus.haptics.inverse.Inverse3Device;
import tactus.haptics.inverse.PlanarInverse3;
import tactus.haptics.pantograph.PantographDevice;
import tactus.haptics.pantograph.PantographKinematics;
import tactus.haptics.session.SessionHand;
import tactus.haptics.session.StatusBand;

/**
 * Everything a haptic sketch needs in a few lines: a Haply board (the first one found) or, when there is none,
 * the in-process board emulator with the mouse as the hand; the device set up from a {@link HaplyPreset}; and
 * a {@link HapticLoop} on a model's avatar, with a mapping that fits the device's workspace to the window.
 *
 * <pre>
 * haptics = HapticSession.open(this);                          // in setup(), after size()
 * mdl.addHapticInput3D("avatar", haptics.home(), 10);           // the avatar starts where the handle is
 * ...
 * haptics.attach(mdl, "avatar").start();                        // 1 kHz, HAPTICS_ONLY: the loop steps the model
 * ...
 * haptics.drawStatus();                                         // in draw(): which board, or "the mouse is the hand"
 * </pre>
 *
 * <p>Mapping: model units are pixels. The device's comfortable workspace ({@link #workspace(double[])}, a
 * rectangle below the calibration pose) is scaled to fill 90 % of the window and centred in it, x mirrored as
 * in the paper's sketches (the device seen from the user). {@link #attach} sets this on each new loop
 * (position gain and origin); change them on the returned loop before {@code start()} if the sketch draws with
 * another scale, and tell the session with {@link #setView(double, double, double)} so that the mouse still
 * lands on the avatar.
 *
 * <p>With a PApplet, the session registers itself with Processing: {@code pre()} moves the emulated hand
 * towards the mouse once the mouse has moved over the window; until then the hand takes the handle on a slow
 * idle tour through the middle of the workspace ({@link #setIdleTour(boolean)}, on by default), so that a
 * scene shows what the device does before anyone touches the mouse. {@code dispose()} stops the loop and
 * closes the board, which sends zero torques. The board also does so from a JVM shutdown hook. The loop asks for real-time scheduling ({@link HapticLoop#setRealtimePriority},
 * priority {@value #REALTIME_PRIORITY}) and runs at normal priority where that is not allowed.
 */
public final class HapticSession implements AutoCloseable {
    /** The device id the session gives its device (the one of hAPI's examples). */
    public static final byte DEVICE_ID = 5;
    /** The real-time priority each loop asks for (Linux SCHED_FIFO; refused quietly where not allowed). */
    public static final int REALTIME_PRIORITY = 50;
    /** Window size used for the mapping without a PApplet, in pixels. */
    static final int DEFAULT_WIDTH = 800;
    static final int DEFAULT_HEIGHT = 600;
    /** Period of the idle tour's horizontal swing, in seconds. */
    public static final double TOUR_PERIOD_X = 6.0;
    /** Period of the idle tour's vertical swing, in seconds (a 3:2 Lissajous figure: one lap takes 12 s). */
    public static final double TOUR_PERIOD_Y = 4.0;
    /** Time over which the idle tour blends from the handle's home position onto its path, in seconds. */
    public static final double TOUR_RAMP = 2.0;
    /**
     * When the idle tour first crosses the middle of the workspace, in seconds after it started (then every 6 s):
     * soon, so that a scene built in the middle is touched within the first seconds.
     */
    public static final double TOUR_CENTRE_TIME = 2.5;
    /**
     * How long a session waits for the Inverse Service to answer once something listens on its port, in
     * milliseconds: a cold JVM on a loaded machine took over a second for the WebSocket upgrade and the snapshot.
     * Where nothing listens, the connection is refused in a few milliseconds whatever this is.
     */
    public static final long CONNECT_MS = 5_000;
    /**
     * How long a session on an Inverse3 keeps reconnecting when the Inverse Service drops the connection (stopped,
     * restarted), in milliseconds; then the loop stops with the reason.
     */
    public static final long RECONNECT_MS = 30_000;
    /** Half-size of the idle tour against the workspace's half-size (each axis). */
    public static final double TOUR_EXTENT = 0.7;

    private final PApplet app;
    private final HaplyPreset preset;
    private final HaplyConnection connection;     // null on an Inverse3
    private final Device device;                  // null on an Inverse3
    private final PlanarInverse3 inverse;         // an Inverse3 through the Inverse Service, or null
    private final String boardStatus;
    private final double[] box = new double[4];   // comfortable workspace: xmin, xmax, ymin, ymax (metres)
    private final double homeX;                    // handle at open (metres)
    private final double homeY;
    private final double alpha;
    private final double ox;
    private final double oy;
    private final int windowHeight;
    private volatile boolean yUp;
    private final double[] tmp = new double[2];

    private volatile HapticLoop loop;
    private final SessionHand hand = new SessionHand();
    private final double[] tourTarget = new double[2];
    private double viewScale = 1;
    private double viewX;
    private double viewY;
    private boolean closed;

    private HapticSession(PApplet app, HaplyPreset preset, HaplyConnection c, String fallbackReason) {
        this.app = app;
        this.preset = preset;
        HaplyConnection conn = c;
        Device dev;
        String why = fallbackReason;
        try {
            dev = setUp(conn.board(), preset);
        } catch (HaplyLinkException | IllegalStateException e) {
            // a port that looked like a Haply but failed at set-up: use the emulator instead
            conn.close();
            why = "the board on " + conn.board().describe() + " did not answer (" + e.getMessage() + ")";
            conn = HaplyConnection.emulated(preset, why);
            dev = setUp(conn.board(), preset);
        }
        this.connection = conn;
        this.device = dev;
        this.inverse = null;
        this.boardStatus = !conn.isEmulated() ? "Haply board: " + conn.status()
                : why != null ? capitalised(why) + ": emulated board, the mouse is your hand"
                : "No Haply board found: emulated board, the mouse is your hand";
        workspaceOf(preset.newKinematics(), box);
        PantographKinematics k = preset.newKinematics();
        double hx = 0.5 * (box[0] + box[1]);
        double hy = box[2];
        if (firstReply(device) && k.forward(Math.toRadians(device.angle(1)), Math.toRadians(device.angle(2)))) {
            hx = k.x();
            hy = k.y();
        }
        homeX = hx;
        homeY = hy;
        int w = app != null && app.width > 0 ? app.width : DEFAULT_WIDTH;
        int h = app != null && app.height > 0 ? app.height : DEFAULT_HEIGHT;
        windowHeight = h;
        alpha = 0.9 * Math.min(w / (box[1] - box[0]), h / (box[3] - box[2]));
        ox = 0.5 * w + alpha * 0.5 * (box[0] + box[1]);     // x mirrored: model x = -alpha x + ox
        oy = 0.5 * h - alpha * 0.5 * (box[2] + box[3]);
        if (app != null) {
            app.registerMethod("pre", this);
            app.registerMethod("mouseEvent", this);
            app.registerMethod("dispose", this);
        }
    }

    /** A session on an Inverse3 through the Inverse Service, presented as a 2DIY (its depth free). */
    private HapticSession(PApplet app, Inverse3Device inv, String banner) {
        this.app = app;
        this.preset = HaplyPreset.HAPLY_2018;
        this.connection = null;
        this.device = null;
        double[] c = SimulatedInverse3.HOME;
        double[] half = SimulatedInverse3.HALF_EXTENT;
        this.inverse = new PlanarInverse3(inv, c[0], c[2]);
        this.boardStatus = banner + " (a 2-D sketch: the depth is free)";
        PlanarInverse3.box(0.8 * half[0], 0.8 * half[2], box);
        double hx = 0.5 * (box[0] + box[1]);
        double hy = 0.5 * (box[2] + box[3]);
        inverse.begin();
        long deadline = System.nanoTime() + 200_000_000L;
        while (System.nanoTime() - deadline < 0) {
            if (inverse.update()) {
                double[] p = new double[3];
                inverse.position(p);
                hx = p[0];
                hy = p[1];
                break;
            }
            java.util.concurrent.locks.LockSupport.parkNanos(1_000_000);
        }
        homeX = hx;
        homeY = hy;
        int w = app != null && app.width > 0 ? app.width : DEFAULT_WIDTH;
        int h = app != null && app.height > 0 ? app.height : DEFAULT_HEIGHT;
        windowHeight = h;
        alpha = 0.9 * Math.min(w / (box[1] - box[0]), h / (box[3] - box[2]));
        ox = 0.5 * w + alpha * 0.5 * (box[0] + box[1]);     // x mirrored: model x = -alpha x + ox
        oy = 0.5 * h - alpha * 0.5 * (box[2] + box[3]);
        if (app != null) {
            app.registerMethod("pre", this);
            app.registerMethod("mouseEvent", this);
            app.registerMethod("dispose", this);
        }
    }

    /**
     * An Inverse3 through the Inverse Service at ws://localhost:10001 (or the system property
     * {@code tactus.haptics.inverse.uri}), or null if there is none; {@code tactus.haptics.inverse=off} skips it.
     */
    private static HapticSession onInverse3(PApplet app) {
        if ("off".equals(System.getProperty("tactus.haptics.inverse", "on"))) {
            return null;
        }
        java.net.URI uri = java.net.URI.create(System.getProperty("tactus.haptics.inverse.uri", "ws://localhost:10001"));
        try {
            Inverse3Device d = Inverse3Device.openGuarded(uri, HapticSession.CONNECT_MS);
            d.setReconnect(RECONNECT_MS);
            return new HapticSession(app, d, "Haply " + d.kind() + " through the Inverse Service at " + uri);
        } catch (HaplyLinkException e) {
            return null;
        }
    }

    private static String capitalised(String s) {
        return s.isEmpty() ? s : Character.toUpperCase(s.charAt(0)) + s.substring(1);
    }

    /** Waits up to 200 ms for the reply to the request sent at set-up; true if it came. */
    private static boolean firstReply(Device d) {
        long deadline = System.nanoTime() + 200_000_000L;
        while (true) {
            if (d.poll_data()) {
                return true;
            }
            if (System.nanoTime() - deadline > 0) {
                return false;
            }
            java.util.concurrent.locks.LockSupport.parkNanos(1_000_000);
        }
    }

    private static Device setUp(Board board, HaplyPreset preset) {
        Device d = new Device(DEVICE_ID, board);
        preset.configure(d);
        d.device_set_parameters();
        d.device_read_request();          // so that the handle's starting pose can be read
        return d;
    }

    /**
     * Opens a session on a 2018 Haply (the paper's device, {@link HaplyPreset#HAPLY_2018}): the first board
     * found, or the emulator with the mouse as the hand. Call it in {@code setup()}, after {@code size()}.
     *
     * @param app the sketch ({@code this}); null for a JVM program (no mouse, no Processing hooks)
     * @return the session, device set up, no loop yet
     */
    public static HapticSession open(PApplet app) {
        return open(app, HaplyPreset.HAPLY_2018);
    }

    /**
     * Opens a session on the given hardware: for the 2018 preset (the default), first an Inverse3 through Haply's
     * Inverse Service, if one is there, used in its vertical plane with its depth free (a 2-D sketch runs
     * unchanged on it; {@link #device()} is then null); else the first Haply board found; else the emulator of
     * that hardware with the mouse as the hand. A board that is found but fails at set-up also falls back to the emulator;
     * {@link #status()} says so. (A board that stays silent stops the loop after
     * its link timeout, and {@link #status()} says that too.)
     *
     * @param app    the sketch ({@code this}); null for a JVM program
     * @param preset the hardware
     * @return the session, device set up, no loop yet
     */
    public static HapticSession open(PApplet app, HaplyPreset preset) {
        if (preset == null) {
            throw new IllegalArgumentException("HapticSession.open: preset must not be null");
        }
        if (preset == HaplyPreset.HAPLY_2018) {
            HapticSession s = onInverse3(app);
            if (s != null) {
                return s;
            }
        }
        return new HapticSession(app, preset, HaplyConnection.open(preset), null);
    }

    /**
     * Opens a session on the emulator even if a board is plugged in (for tests, or to try a sketch away from
     * the device).
     *
     * @param app    the sketch ({@code this}); null for a JVM program
     * @param preset the emulated hardware
     * @return the session, device set up, no loop yet
     */
    public static HapticSession openEmulated(PApplet app, HaplyPreset preset) {
        if (preset == null) {
            throw new IllegalArgumentException("HapticSession.openEmulated: preset must not be null");
        }
        return new HapticSession(app, preset, HaplyConnection.emulated(preset, "emulated board (asked for)"), null);
    }

    /**
     * Stops the current loop, if any (the board stays open, the motors get zero torque), and makes a new one
     * on the model's avatar (a HapticInput3D), with the session's mapping and real-time request. It is not
     * started: change its settings (rate, gains, mode) and call {@link HapticLoop#start()}.
     *
     * @param model  the model
     * @param avatar the name of its HapticInput3D
     * @return the new loop, not started
     */
    public HapticLoop attach(PhysicalModel model, String avatar) {
        return attach(new PhysicalModelAvatar(model, avatar));
    }

    /**
     * As {@link #attach(PhysicalModel, String)}, for any {@link AvatarLink}.
     *
     * @param avatar the avatar link
     * @return the new loop, not started
     */
    public synchronized HapticLoop attach(AvatarLink avatar) {
        if (closed) {
            throw new IllegalStateException("HapticSession.attach: the session is closed");
        }
        HapticLoop old = loop;
        if (old != null) {
            old.stop();
        }
        HapticLoop l = inverse != null ? new HapticLoop(inverse, avatar) : new HapticLoop(device, preset.newKinematics(), avatar);
        if (yUp) {
            // model y = height - pixel y: a negative gain flips y, and x, which the mirror then no longer does
            l.setPositionGain(-alpha);
            l.setOrigin(ox, windowHeight - oy, 0);
            l.setMirrorX(false);
        } else {
            l.setPositionGain(alpha);
            l.setOrigin(ox, oy, 0);
            l.setMirrorX(true);
        }
        l.setRealtimePriority(REALTIME_PRIORITY);
        loop = l;
        return l;
    }

    /** The current loop, or null before {@link #attach}. */
    public HapticLoop loop() {
        return loop;
    }

    /** The device (set up), or null when the session drives an Inverse3 ({@link #hapticDevice()}). */
    public Device device() {
        return device;
    }

    /** The device as a {@link HapticDevice}: a {@link PantographDevice} on a 2DIY, a {@link PlanarInverse3} on an Inverse3. */
    public HapticDevice hapticDevice() {
        return inverse != null ? inverse : new PantographDevice(device, preset.newKinematics());
    }

    /** The hardware preset. */
    public HaplyPreset preset() {
        return preset;
    }

    /** True if the board is the emulator (no Haply found). */
    public boolean isEmulated() {
        return connection != null && connection.isEmulated();
    }

    /** The emulator, or null on real hardware. */
    public BoardEmulator emulator() {
        return connection == null ? null : connection.emulator();
    }

    /**
     * One line for the screen: which board (or that the mouse is the hand, and, while the idle tour runs, that
     * the hand tours on its own until the mouse moves), and why the loop stopped if it stopped by itself.
     */
    public String status() {
        return SessionHand.status(SessionHand.withReconnection(boardStatus, inverse == null ? null : inverse.inverse()),
                isTouring(), loop);
    }

    /**
     * Switches the idle tour on (the default) or off. While it is on, the board is emulated, the session has a
     * PApplet and the mouse has not moved over the window yet, each {@code pre()} moves the emulated hand along
     * {@link #idleTourTarget(double, double[])}; off, the hand holds the handle still until the mouse moves. The
     * first mouse move, drag or press ends the tour for good. Switching it off leaves the hand where the tour
     * was; switching it on again resumes the path from where its clock stands.
     */
    public void setIdleTour(boolean on) {
        hand.setIdleTour(on);
    }

    /** True if the idle tour is switched on (see {@link #setIdleTour(boolean)}); it may have ended already. */
    public boolean isIdleTour() {
        return hand.idleTour();
    }

    /**
     * True while the idle tour drives the emulated hand: switched on, the board emulated, a PApplet to call
     * {@code pre()}, and no mouse event yet.
     */
    public boolean isTouring() {
        return hand.touring(isEmulated(), app != null);
    }

    /**
     * Where the idle tour puts the hand t seconds after it started, in device coordinates (metres, x from motor 1
     * towards motor 2, y away from the motors): a 3:2 Lissajous figure centred in the comfortable workspace,
     * {@value #TOUR_EXTENT} of its half-width and half-height wide and tall, x swinging with period
     * {@value #TOUR_PERIOD_X} s and y with period {@value #TOUR_PERIOD_Y} s, through the middle at
     * {@value #TOUR_CENTRE_TIME} s and every 6 s after. Over the first {@value #TOUR_RAMP} s
     * the target blends smoothly (zero velocity at t = 0) from the handle's home position onto the figure, so the
     * tour starts where the handle is, without a jump (from the nearest point of the workspace if home is outside
     * it). Every point is inside the workspace.
     *
     * @param t   seconds since the tour started (negative counts as 0)
     * @param out receives x, y in metres
     */
    public void idleTourTarget(double t, double[] out) {
        double tt = Math.max(0, t);
        double cx = 0.5 * (box[0] + box[1]);
        double cy = 0.5 * (box[2] + box[3]);
        double ax = TOUR_EXTENT * 0.5 * (box[1] - box[0]);
        double ay = TOUR_EXTENT * 0.5 * (box[3] - box[2]);
        double tc = tt - TOUR_CENTRE_TIME;
        double px = cx + ax * Math.sin(2 * Math.PI * tc / TOUR_PERIOD_X);
        double py = cy + ay * Math.sin(2 * Math.PI * tc / TOUR_PERIOD_Y);
        // the tour starts at home; a calibration pose outside the workspace (the 2DIY v2's) is brought to its edge
        double hx = Math.max(box[0], Math.min(box[1], homeX));
        double hy = Math.max(box[2], Math.min(box[3], homeY));
        double u = Math.min(1, tt / TOUR_RAMP);
        double s = u * u * (3 - 2 * u);                                       // smoothstep: 0 -> 1, flat ends
        // home and the figure are both inside the (convex) workspace, so every blend of them is too
        out[0] = hx + s * (px - hx);
        out[1] = hy + s * (py - hy);
    }

    /**
     * Where the handle was when the session opened, in model units under the session's mapping: a good
     * starting position for the avatar ({@code mdl.addHapticInput3D("avatar", haptics.home(), 10)}).
     */
    public Vect3D home() {
        return new Vect3D(-alpha * homeX + ox, modelY(alpha * homeY + oy), 0);
    }

    /**
     * The comfortable workspace in model units under the session's mapping (x mirrored): writes xmin, xmax,
     * ymin, ymax into out[0..3].
     */
    public void workspace(double[] out) {
        double a = -alpha * box[1] + ox;
        double b = -alpha * box[0] + ox;
        out[0] = Math.min(a, b);
        out[1] = Math.max(a, b);
        double c = modelY(alpha * box[2] + oy);
        double d = modelY(alpha * box[3] + oy);
        out[2] = Math.min(c, d);
        out[3] = Math.max(c, d);
    }

    /**
     * The comfortable workspace in device coordinates, metres (x from motor 1 towards motor 2, y away from the
     * motors): writes xmin, xmax, ymin, ymax into out[0..3]. For a sketch that sets its own mapping on the loop
     * ({@link HapticLoop#setPositionGain}, {@link HapticLoop#setOrigin}) and wants its scene in the middle of it,
     * where the idle tour goes.
     */
    public void deviceWorkspace(double[] out) {
        System.arraycopy(box, 0, out, 0, 4);
    }

    private double modelY(double pixelY) {
        return yUp ? windowHeight - pixelY : pixelY;
    }

    /**
     * Chooses the model's y axis for the loops attached from now on: down the window, as Processing draws (false,
     * the default: model units are pixels), or up (true: model y = window height - pixel y, as in a sketch that
     * draws with {@code translate(0, height); scale(1, -1);}), for scenes with gravity and floors. Also changes
     * {@link #home()}, {@link #workspace(double[])} and how the mouse is read.
     */
    public void setModelYUp(boolean up) {
        yUp = up;
    }

    /** True if the model's y axis points up the window (see {@link #setModelYUp(boolean)}). */
    public boolean isModelYUp() {
        return yUp;
    }

    /** The position gain the session gives each loop: pixels (model units) per metre. */
    public double positionGain() {
        return alpha;
    }

    /**
     * Tells the session how the sketch draws the model, so that the mouse lands on the avatar: a model point
     * (x, y) is drawn at pixel (offsetX + scale x, offsetY + scale y), or (offsetX + scale x, window height -
     * offsetY - scale y) when the model's y axis points up. Default: scale 1, offset 0 (model units are
     * pixels).
     */
    public void setView(double scale, double offsetX, double offsetY) {
        if (!(scale != 0) || !Double.isFinite(scale) || !Double.isFinite(offsetX) || !Double.isFinite(offsetY)) {
            throw new IllegalArgumentException("HapticSession.setView: scale must be finite and non-zero and the "
                    + "offsets finite, got " + scale + ", " + offsetX + ", " + offsetY);
        }
        viewScale = scale;
        viewX = offsetX;
        viewY = offsetY;
    }

    /**
     * Moves the emulated hand towards a pixel of the window (through the view and the current loop's mapping,
     * kept inside the workspace). Does nothing on real hardware or before {@link #attach}. {@link #pre()} calls
     * it with the mouse.
     */
    public void handTowardsPixel(double px, double py) {
        HapticLoop l = loop;
        if (!isEmulated() || l == null) {
            return;
        }
        double my = yUp ? (windowHeight - py - viewY) / viewScale : (py - viewY) / viewScale;
        l.modelToDevice((px - viewX) / viewScale, my, tmp);
        double x = Math.max(box[0], Math.min(box[1], tmp[0]));
        double y = Math.max(box[2], Math.min(box[3], tmp[1]));
        connection.setHandTarget(x, y);
    }

    /**
     * The force the hand felt at the last tick, in newtons, along the model's axes (as the current loop maps
     * them), for drawing an arrow at the avatar: writes fx, fy into out[0], out[1]; zeros before
     * {@link #attach}.
     */
    public void forceInModel(double[] out) {
        HapticLoop l = loop;
        if (l == null) {
            out[0] = 0;
            out[1] = 0;
            return;
        }
        l.deviceForce(out);
        double gx = l.isMirrorX() ? -l.positionGain() : l.positionGain();
        if (gx < 0) {
            out[0] = -out[0];
        }
        if (l.positionGain() < 0) {
            out[1] = -out[1];
        }
    }

    /**
     * A short line of telemetry for the screen ("1000 Hz, 0.02 % missed, jitter p99 40 us, real-time"),
     * refreshed at most once a second, so that the figures stay readable (the string is made only then).
     */
    public String telemetryLine() {
        return hand.telemetryLine(loop, HapticSession::telemetryText);
    }

    private static String telemetryText(HapticLoop l) {
        HapticTelemetry t = l.telemetry();
        String sched = l.scheduling();
        return String.format(java.util.Locale.ROOT,
                "haptics %.0f Hz of %.0f, %.2f %% missed, jitter p99 %.0f us, %s", t.achievedHz, t.nominalHz,
                100 * t.missedFraction(), t.jitterP99Us,
                sched.startsWith("real-time") ? "real-time" : sched.startsWith("normal") ? "normal priority" : sched);
    }

    /**
     * Processing calls this before each {@code draw()}: the emulated hand follows the mouse once it has moved;
     * until then it follows the idle tour ({@link #setIdleTour(boolean)}), whose clock starts at the first call.
     */
    public void pre() {
        if (app == null) {
            return;
        }
        if (hand.mouseSeen()) {
            handTowardsPixel(app.mouseX, app.mouseY);
        } else if (isTouring()) {
            idleTourTarget(hand.tourSeconds(System.nanoTime()), tourTarget);
            connection.setHandTarget(tourTarget[0], tourTarget[1]);
        }
    }

    /**
     * Processing calls this for mouse events: the first move, drag or press over the window ends the idle tour
     * and hands the hand to the mouse.
     */
    public void mouseEvent(MouseEvent e) {
        hand.mouseEvent(e);
    }

    /**
     * Draws {@link #status()} in the bottom-left corner of the window, on a band that keeps it readable,
     * whatever the sketch's transforms and styles (they are restored).
     */
    public void drawStatus() {
        if (app != null) {
            StatusBand.draw(app, status(), loop != null && loop.failure() != null, isEmulated());
        }
    }

    /** Stops the loop and closes the board (zero torques, then a reset) and the emulator. */
    @Override
    public synchronized void close() {
        if (closed) {
            return;
        }
        closed = true;
        HapticLoop l = loop;
        if (l != null) {
            l.close();
        }
        if (connection != null) {
            connection.close();
        }
        if (inverse != null) {
            inverse.close();
        }
    }

    /** Same as {@link #close()}; Processing calls it when the sketch ends. */
    public void dispose() {
        close();
    }

    /**
     * The comfortable workspace of a pantograph: the widest rectangle, twice as wide as tall, centred between
     * the motors, whose top edge is at the calibration pose's height, and whose every point on a 9 by 5 grid
     * is within reach. Writes xmin, xmax, ymin, ymax (metres) into out.
     */
    static void workspaceOf(PantographKinematics k, double[] out) {
        double reach = k.l() + k.bigL();
        double xc = 0.5 * k.d();
        double top = topOfWorkspace(k);
        double lo = 0;
        double hi = reach;
        double[] th = new double[2];
        for (int it = 0; it < 40; it++) {
            double h = 0.5 * (lo + hi);
            boolean ok = true;
            for (int i = 0; i <= 8 && ok; i++) {
                for (int j = 0; j <= 4 && ok; j++) {
                    ok = k.inverse(xc - h + 2 * h * i / 8, top + h * j / 4, th);
                }
            }
            if (ok) {
                lo = h;
            } else {
                hi = h;
            }
        }
        out[0] = xc - lo;
        out[1] = xc + lo;
        out[2] = top;
        out[3] = top + lo;
    }

    /** The lowest y where the point between the motors is reachable with some margin, at least a tenth of l. */
    private static double topOfWorkspace(PantographKinematics k) {
        double[] th = new double[2];
        double xc = 0.5 * k.d();
        double y = 0.1 * k.l();
        double step = 0.001;
        while (y < k.l() + k.bigL() && !k.inverse(xc, y, th)) {
            y += step;
        }
        // a little below the first reachable point, clear of the singular pose with the arms folded
        return Math.max(y + 0.02 * (k.l() + k.bigL()), 0.5 * k.l());
    }
}
