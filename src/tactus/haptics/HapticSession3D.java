package tactus.haptics;

import java.net.URI;

import processing.core.PApplet;
import processing.event.MouseEvent;
import tactus.PhysicalModel;
import tactus.Vect3D;
import tactus.haptics.emulator.Hand3D;
import tactus.haptics.emulator.HaplyConnection;
import tactus.haptics.emulator.InverseServiceEmulator;
import tactus.haptics.emulator.SimulatedInverse3;
import tactus.haptics.inverse.Inverse3Choice;
import tactus.haptics.inverse.Inverse3Device;
import tactus.haptics.inverse.InverseState;
import tactus.haptics.pantograph.PantographDevice;
import tactus.haptics.session.SessionHand;
import tactus.haptics.session.StatusBand;

/**
 * A 3-D haptic sketch's device and loop in a few lines: it finds what is there, in this order, and says which
 * ({@link #status()}, {@link #drawStatus()}):
 * <ol>
 * <li>an Inverse3 (or Inverse3x, Minverse) through Haply's Inverse Service ({@code ws://localhost:10001}, or
 * the system property {@code tactus.haptics.inverse.uri}; {@code tactus.haptics.inverse=off} skips it);</li>
 * <li>else a 2DIY board on a serial port ({@link HaplyPreset#HAPLY_2018} by default): x and y move, z is fixed;</li>
 * <li>else the in-process Inverse Service emulator with the mouse as the hand (x and y on the screen; the depth
 * swings slowly on its own), and, until the mouse moves, an idle tour through the workspace.</li>
 * </ol>
 *
 * <pre>
 * haptics = HapticSession3D.open(this);                  // in setup(), after size(w, h, P3D)
 * mdl.addHapticInput3D("avatar", haptics.home(), 10);
 * haptics.attach(mdl, "avatar").start();                 // 1 kHz, the loop steps the model
 * ...
 * haptics.drawStatus();                                  // in draw()
 * </pre>
 *
 * <p>Mapping: model units are pixels of a P3D sketch (x right, y down, z towards the viewer); the device's
 * workspace fills 90 % of the window's height or width, centred, with its centre at z = 0 (for an Inverse3,
 * {@link WorkspaceMapping#inverse3Screen()}: device z up is model -y, device y away from the user is model -z).
 * {@link #setMapping(WorkspaceMapping)} replaces it. With a VerseGrip, {@link #gripOrientation(double[])} and
 * {@link #button(int)} read it.
 */
public final class HapticSession3D implements AutoCloseable {
    /** The real-time priority each loop asks for (Linux SCHED_FIFO; refused quietly where not allowed). */
    public static final int REALTIME_PRIORITY = 50;
    /**
     * The link timeout of a loop on the in-process emulator, in milliseconds: the emulator answers from threads of
     * the sketch's own JVM, which a loaded machine can hold back for hundreds of milliseconds while the loop's
     * real-time thread ticks on; that is no device switched off, so the loop waits longer than the 500 ms it gives
     * a real device.
     */
    public static final int EMULATED_LINK_TIMEOUT_MS = 5000;
    /** Period of the idle tour's lap, in seconds. */
    public static final double TOUR_PERIOD = 12.0;

    private final PApplet app;
    private final HapticDevice device;
    private final Inverse3Device inverse;           // null for a 2DIY board
    private final InverseServiceEmulator emulator;  // null on real hardware
    private final SimulatedInverse3 sim;            // this session's emulated device, or null
    private boolean ownsEmulator = true;            // false for the second hand of a pair (the first closes it)
    private boolean mirrored;                       // the emulated hand follows the mouse mirrored left-right
    private final HaplyConnection board;            // null unless a 2DIY board
    private final String banner;
    private final double[] centre = new double[3];  // device metres
    private final double[] halfSize = new double[3];
    private final int width;
    private final int height;
    private volatile WorkspaceMapping mapping;
    private volatile HapticLoop loop;
    private final SessionHand hand = new SessionHand();
    private final InverseState gripState = new InverseState();
    private boolean closed;
    private final double[] tmpModel = new double[3];
    private final double[] tmpDevice = new double[3];
    private final double[] tmpForce = new double[3];

    private HapticSession3D(PApplet app, HapticDevice device, Inverse3Device inverse, InverseServiceEmulator emulator,
                            HaplyConnection board, String banner, double[] centre, double[] halfSize) {
        this.app = app;
        this.device = device;
        this.inverse = inverse;
        this.emulator = emulator;
        this.sim = emulator == null ? null : inverse != null ? emulator.device(inverse.deviceId()) : emulator.device();
        this.board = board;
        this.banner = banner;
        System.arraycopy(centre, 0, this.centre, 0, 3);
        System.arraycopy(halfSize, 0, this.halfSize, 0, 3);
        width = app != null && app.width > 0 ? app.width : HapticSession.DEFAULT_WIDTH;
        height = app != null && app.height > 0 ? app.height : HapticSession.DEFAULT_HEIGHT;
        mapping = screenMapping();
        if (app != null) {
            app.registerMethod("pre", this);
            app.registerMethod("mouseEvent", this);
            app.registerMethod("dispose", this);
        }
    }

    /** Opens the first device found (Inverse3, else a 2DIY board, else the emulator); see the class comment. */
    public static HapticSession3D open(PApplet app) {
        String off = System.getProperty("tactus.haptics.inverse", "on");
        String why = "no Haply device found";
        if (!"off".equals(off)) {
            URI uri = URI.create(System.getProperty("tactus.haptics.inverse.uri", "ws://localhost:10001"));
            try {
                Inverse3Device d = Inverse3Device.openGuarded(uri, HapticSession.CONNECT_MS);
                d.setReconnect(HapticSession.RECONNECT_MS);
                return onInverse(app, d, null, "Haply " + d.kind() + " through the Inverse Service at " + uri);
            } catch (HaplyLinkException e) {
                why = e.getMessage();
            }
        }
        HaplyConnection c = HaplyConnection.open(HaplyPreset.HAPLY_2018);
        if (!c.isEmulated()) {
            try {
                Device dev = new Device(HapticSession.DEVICE_ID, c.board());
                HaplyPreset.HAPLY_2018.configure(dev);
                dev.device_set_parameters();
                PantographDevice pd = new PantographDevice(dev, HaplyPreset.HAPLY_2018.newKinematics());
                double[] box = new double[4];
                HapticSession.workspaceOf(HaplyPreset.HAPLY_2018.newKinematics(), box);
                double[] ctr = {0.5 * (box[0] + box[1]), 0.5 * (box[2] + box[3]), 0};
                double[] half = {0.5 * (box[1] - box[0]), 0.5 * (box[3] - box[2]), 0};
                return new HapticSession3D(app, pd, null, null, c, "Haply 2DIY board: " + c.status()
                        + " (a 3-D sketch on a 2-D device: z is fixed)", ctr, half);
            } catch (HaplyLinkException | IllegalStateException e) {
                c.close();
                why = "the board did not answer (" + e.getMessage() + ")";
            }
        } else {
            c.close();
        }
        return openEmulated(app, firstSentence(why));
    }

    /**
     * Opens the Inverse3 this choice names (by id, index or handedness) on the Inverse Service at the address of
     * the property {@code tactus.haptics.inverse.uri} (default {@code ws://localhost:10001}), guarded, with no
     * fallback: for a second device, or one hand of two.
     *
     * @throws HaplyLinkException if the service is not there or does not list that device (the message lists those
     *                            it has)
     */
    public static HapticSession3D open(PApplet app, Inverse3Choice which) {
        URI uri = URI.create(System.getProperty("tactus.haptics.inverse.uri", "ws://localhost:10001"));
        Inverse3Device d = Inverse3Device.openGuarded(uri, HapticSession.CONNECT_MS, which);
        d.setReconnect(HapticSession.RECONNECT_MS);
        return onInverse(app, d, null, "Haply " + d.kind() + " " + d.deviceId() + handed(d) + " through the Inverse "
                + "Service at " + uri);
    }

    /**
     * Opens two hands on the in-process emulator serving two Inverse3s: element 0 drives the left-handed one
     * (id {@value #LEFT_ID}), element 1 the right-handed one ({@link InverseServiceEmulator#DEVICE_ID}), each with
     * its own connection, loop and emulated hand; the mouse (or the idle tour) moves the right hand, and the left
     * hand as its mirror image. Closing element 0 closes the emulator too.
     */
    public static HapticSession3D[] openEmulatedPair(PApplet app) {
        double[] h = SimulatedInverse3.HOME;
        SimulatedInverse3 right = new SimulatedInverse3();
        right.setHand(Hand3D.following(h[0], h[1], h[2], 300, 3));
        SimulatedInverse3 left = new SimulatedInverse3();
        left.setHand(Hand3D.following(h[0], h[1], h[2], 300, 3));
        InverseServiceEmulator emu = InverseServiceEmulator.start(0, right);
        emu.addInverse3(LEFT_ID, "left", left, true);
        HapticSession3D l = null;
        try {
            Inverse3Device dl = Inverse3Device.open(emu.uri(), 5000, Inverse3Choice.byHandedness("left"));
            l = onInverse(app, dl, emu, "Emulated left-handed Inverse3 " + dl.deviceId() + ", the mouse (mirrored) is your "
                    + "left hand");
            l.mirrored = true;
            Inverse3Device dr = Inverse3Device.open(emu.uri(), 5000, Inverse3Choice.byHandedness("right"));
            HapticSession3D r = onInverse(app, dr, emu, "Emulated right-handed Inverse3 " + dr.deviceId() + ", the mouse is "
                    + "your right hand");
            r.ownsEmulator = false;
            return new HapticSession3D[] {l, r};
        } catch (RuntimeException e) {
            if (l != null) {
                l.close();
            }
            emu.close();
            throw e;
        }
    }

    /** The id of the left-handed Inverse3 of {@link #openEmulatedPair}. */
    public static final String LEFT_ID = "1EF7";

    private static String handed(Inverse3Device d) {
        return d.handedness() == null ? "" : " (" + d.handedness() + "-handed)";
    }

    /** Opens the in-process Inverse Service emulator with the mouse as the hand, even if a device is there. */
    public static HapticSession3D openEmulated(PApplet app) {
        return openEmulated(app, "emulated Inverse3 (asked for)");
    }

    private static HapticSession3D openEmulated(PApplet app, String why) {
        SimulatedInverse3 sim = new SimulatedInverse3();
        double[] h = SimulatedInverse3.HOME;
        sim.setHand(Hand3D.following(h[0], h[1], h[2], 300, 3));
        InverseServiceEmulator emu = InverseServiceEmulator.start(0, sim);
        try {
            Inverse3Device d = Inverse3Device.open(emu.uri(), 5000);
            String text = (why.startsWith("emulated") ? capitalised(why) : capitalised(why) + ": emulated Inverse3")
                    + ", the mouse is your hand";
            return onInverse(app, d, emu, text);
        } catch (RuntimeException e) {
            emu.close();
            throw e;
        }
    }

    private static HapticSession3D onInverse(PApplet app, Inverse3Device d, InverseServiceEmulator emu, String banner) {
        double[] ctr = SimulatedInverse3.HOME.clone();
        double[] half = SimulatedInverse3.HALF_EXTENT.clone();
        for (int i = 0; i < 3; i++) {
            half[i] *= 0.8;   // the comfortable part of the workspace
        }
        return new HapticSession3D(app, d, d, emu, null, banner, ctr, half);
    }

    private static String firstSentence(String s) {
        int i = s.indexOf(": ");
        int j = s.indexOf(" (");
        int k = i < 0 ? j : j < 0 ? i : Math.min(i, j);
        return k > 0 ? s.substring(0, k) : s;
    }

    private static String capitalised(String s) {
        return s.isEmpty() ? s : Character.toUpperCase(s.charAt(0)) + s.substring(1);
    }

    /** The default screen mapping: the comfortable workspace fills 90 % of the window, centred, z = 0 at its centre. */
    private WorkspaceMapping screenMapping() {
        WorkspaceMapping axes = inverse != null ? WorkspaceMapping.inverse3Screen() : WorkspaceMapping.pantograph();
        double[] extentModel = new double[3];
        for (int i = 0; i < 3; i++) {
            extentModel[i] = 2 * halfSize[axes.deviceAxis(i)];
        }
        double scale = 0.9 * Math.min(width / extentModel[0], height / extentModel[1]);
        return axes.withScale(scale).centring(centre, 0.5 * width, 0.5 * height, 0);
    }

    /** Replaces the mapping for the loops attached from now on (and for the mouse). */
    public void setMapping(WorkspaceMapping m) {
        if (m == null) {
            throw new IllegalArgumentException("HapticSession3D.setMapping: mapping must not be null");
        }
        mapping = m;
    }

    /** The mapping from the device's metres to the model (pixels by default). */
    public WorkspaceMapping mapping() {
        return mapping;
    }

    /**
     * Stops the current loop, if any, and makes a new one (not started) on the model's avatar, with this
     * session's mapping, a force gain of 1 N per model force unit ({@link HapticLoop#setForceGain}), a
     * real-time request and, on the emulator, a link timeout of {@value #EMULATED_LINK_TIMEOUT_MS} ms.
     */
    public HapticLoop attach(PhysicalModel model, String avatar) {
        return attach(new PhysicalModelAvatar(model, avatar));
    }

    /** As {@link #attach(PhysicalModel, String)}, for any {@link AvatarLink}. */
    public synchronized HapticLoop attach(AvatarLink avatar) {
        if (closed) {
            throw new IllegalStateException("HapticSession3D.attach: the session is closed");
        }
        HapticLoop old = loop;
        if (old != null) {
            old.stop();
        }
        HapticLoop l = new HapticLoop(device, avatar);
        l.setWorkspaceMapping(mapping);
        l.setForceGain(1);
        l.setRealtimePriority(REALTIME_PRIORITY);
        if (emulator != null) {
            l.setLinkTimeoutMillis(EMULATED_LINK_TIMEOUT_MS);
        }
        loop = l;
        return l;
    }

    /** The current loop, or null before {@link #attach}. */
    public HapticLoop loop() {
        return loop;
    }

    /** The device. */
    public HapticDevice device() {
        return device;
    }

    /** True when the device is the in-process emulator. */
    public boolean isEmulated() {
        return emulator != null;
    }

    /** The emulator, or null on real hardware. */
    public InverseServiceEmulator emulator() {
        return emulator;
    }

    /** Where the handle is now (the centre of the workspace before the first state), in model units. */
    public Vect3D home() {
        double[] p = new double[3];
        if (inverse != null) {
            InverseState s = new InverseState();
            inverse.readState(s);
            p[0] = Double.isNaN(s.px) ? centre[0] : s.px;
            p[1] = Double.isNaN(s.py) ? centre[1] : s.py;
            p[2] = Double.isNaN(s.pz) ? centre[2] : s.pz;
        } else {
            System.arraycopy(centre, 0, p, 0, 3);
        }
        double[] m = new double[3];
        mapping.toModel(p, m);
        return new Vect3D(m[0], m[1], m[2]);
    }

    /** The comfortable workspace in model units: min corner into lo[0..2], max corner into hi[0..2]. */
    public void workspace(double[] lo, double[] hi) {
        double[] a = new double[3];
        double[] b = new double[3];
        double[] ma = new double[3];
        double[] mb = new double[3];
        for (int i = 0; i < 3; i++) {
            a[i] = centre[i] - halfSize[i];
            b[i] = centre[i] + halfSize[i];
        }
        mapping.toModel(a, ma);
        mapping.toModel(b, mb);
        for (int i = 0; i < 3; i++) {
            lo[i] = Math.min(ma[i], mb[i]);
            hi[i] = Math.max(ma[i], mb[i]);
        }
    }

    /** True if a VerseGrip is listed by the service. */
    public boolean hasGrip() {
        if (inverse == null) {
            return false;
        }
        synchronized (gripState) {
            inverse.readState(gripState);
            return gripState.gripId != null;
        }
    }

    /** The VerseGrip's orientation quaternion (w, x, y, z) into out[0..3]; identity without a grip. */
    public void gripOrientation(double[] out) {
        if (inverse == null) {
            out[0] = 1;
            out[1] = 0;
            out[2] = 0;
            out[3] = 0;
            return;
        }
        synchronized (gripState) {
            inverse.readState(gripState);
            out[0] = gripState.gripW;
            out[1] = gripState.gripX;
            out[2] = gripState.gripY;
            out[3] = gripState.gripZ;
        }
    }

    /** True while the VerseGrip's button i is pressed (0: a, the wired grip's only button; 1: b; 2: c). */
    public boolean button(int i) {
        if (inverse == null) {
            return false;
        }
        synchronized (gripState) {
            inverse.readState(gripState);
            return i == 0 ? gripState.buttonA : i == 1 ? gripState.buttonB : i == 2 && gripState.buttonC;
        }
    }

    /** Switches the emulated hand's idle tour (on by default; the first mouse move ends it). */
    public void setIdleTour(boolean on) {
        hand.setIdleTour(on);
    }

    /** One line for the screen: which device, and why the loop stopped if it stopped by itself. */
    public String status() {
        return SessionHand.status(SessionHand.withReconnection(banner, inverse), hand.touring(isEmulated(), app != null),
                loop);
    }

    /**
     * A short line of telemetry, as {@link HapticSession#telemetryLine()}, refreshed at most once a second (a
     * telemetry snapshot copies the loop's window of 65,536 ticks).
     */
    public String telemetryLine() {
        return hand.telemetryLine(loop, HapticSession3D::telemetryText);
    }

    private static String telemetryText(HapticLoop l) {
        HapticTelemetry t = l.telemetry();
        return String.format(java.util.Locale.ROOT, "haptics %.0f Hz of %.0f, %.2f %% missed, %s", t.achievedHz,
                t.nominalHz, 100 * t.missedFraction(), l.scheduling());
    }

    /** The force the hand felt at the last tick, in newtons along the model's axes, into out[0..2] (the draw thread). */
    public synchronized void forceInModel(double[] out) {
        HapticLoop l = loop;
        if (l == null) {
            out[0] = 0;
            out[1] = 0;
            out[2] = 0;
            return;
        }
        l.deviceForce(tmpForce);
        mapping.forceToModel(tmpForce, 1, out);
    }

    /**
     * Processing calls this before each {@code draw()}: with the emulator, the hand follows the mouse once it
     * has moved (x and y; the depth swings slowly), and tours the workspace until then.
     */
    public void pre() {
        if (app == null || sim == null) {
            return;
        }
        double t = hand.tourSeconds(System.nanoTime());
        if (hand.mouseSeen()) {
            tmpModel[0] = app.mouseX;
            tmpModel[1] = app.mouseY;
            tmpModel[2] = 0;
            mapping.toDevice(tmpModel, tmpDevice);
            int depth = mapping.deviceAxis(2);
            tmpDevice[depth] = centre[depth] + 0.6 * halfSize[depth] * Math.sin(2 * Math.PI * t / 8);
        } else if (hand.idleTour()) {
            idleTourTarget(t, tmpDevice);
        } else {
            return;
        }
        for (int i = 0; i < 3; i++) {
            tmpDevice[i] = Math.max(centre[i] - halfSize[i], Math.min(centre[i] + halfSize[i], tmpDevice[i]));
        }
        if (mirrored) {
            tmpDevice[0] = 2 * centre[0] - tmpDevice[0];
        }
        sim.hand().setTarget(tmpDevice[0], tmpDevice[1], tmpDevice[2]);
    }

    /**
     * The idle tour at t seconds (device metres into out[0..2]): a 3:2:1 Lissajous figure through the comfortable
     * workspace, 0.7 of its half-size each way, {@value #TOUR_PERIOD} s a lap, through the centre at t = 0.
     */
    public void idleTourTarget(double t, double[] out) {
        double w = 2 * Math.PI / TOUR_PERIOD;
        out[0] = centre[0] + 0.7 * halfSize[0] * Math.sin(3 * w * t);
        out[1] = centre[1] + 0.7 * halfSize[1] * Math.sin(w * t);
        out[2] = centre[2] + 0.7 * halfSize[2] * Math.sin(2 * w * t);
    }

    /** Processing calls this for mouse events: the first move, drag or press ends the idle tour. */
    public void mouseEvent(MouseEvent e) {
        hand.mouseEvent(e);
    }

    /** Draws {@link #status()} in the bottom-left corner, whatever the sketch's transforms (they are restored). */
    public void drawStatus() {
        if (app != null) {
            StatusBand.draw(app, status(), loop != null && loop.failure() != null, isEmulated());
        }
    }

    /** Stops the loop, sends zero force and closes the device, then the emulator. */
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
        device.close();
        if (board != null) {
            board.close();
        }
        if (emulator != null && ownsEmulator) {
            emulator.close();
        }
    }

    /** Same as {@link #close()}; Processing calls it when the sketch ends. */
    public void dispose() {
        close();
    }
}
