package tactus.haptics.session;

import processing.event.MouseEvent;
import tactus.haptics.HapticLoop;
import tactus.haptics.HapticSession3D;
import tactus.haptics.HapticSession;

/**
 * What {@link HapticSession} and {@link HapticSession3D} share about the hand of an emulated device: the idle
 * tour drives it until the mouse first moves, drags or presses over the window, and the mouse from then on; the
 * tour's clock; the status line that says so; and the telemetry line, made at most once a second.
 *
 * <p>Not API: public only for the two sessions in {@code tactus.haptics}.
 */
public final class SessionHand {
    private volatile boolean mouseSeen;
    private volatile boolean idleTour = true;
    private long tourStart;            // System.nanoTime() of the tour clock's first reading; 0: not yet
    private HapticLoop telemetryOf;
    private long telemetryAt;
    private String telemetryText = "";

    /** A mouse event: the first move, drag or press ends the idle tour for good. */
    public void mouseEvent(MouseEvent e) {
        int a = e.getAction();
        if (a == MouseEvent.MOVE || a == MouseEvent.DRAG || a == MouseEvent.PRESS) {
            mouseSeen = true;
        }
    }

    /** True once the mouse has moved, dragged or pressed over the window. */
    public boolean mouseSeen() {
        return mouseSeen;
    }

    /** Switches the idle tour on or off. */
    public void setIdleTour(boolean on) {
        idleTour = on;
    }

    /** True if the idle tour is switched on (it may have ended). */
    public boolean idleTour() {
        return idleTour;
    }

    /** True while the tour drives the hand: switched on, no mouse event yet, emulated, and a sketch to call pre(). */
    public boolean touring(boolean emulated, boolean hasSketch) {
        return idleTour && !mouseSeen && emulated && hasSketch;
    }

    /** Seconds on the tour's clock, which starts at its first reading (now: {@link System#nanoTime()}). */
    public double tourSeconds(long now) {
        if (tourStart == 0) {
            tourStart = now == 0 ? 1 : now;
        }
        return (now - tourStart) * 1e-9;
    }

    /** The status line: the banner, that the hand tours while it does, and why the loop stopped if it did. */
    public static String status(String banner, boolean touring, HapticLoop loop) {
        String f = loop == null ? null : loop.failure();
        String s = touring ? banner + "; the hand tours on its own until you move the mouse" : banner;
        return f == null ? s : s + ". Haptic loop stopped: " + f;
    }

    /** The banner, with what the Inverse3 is doing while it reconnects to the service (device may be null). */
    public static String withReconnection(String banner, tactus.haptics.inverse.Inverse3Device device) {
        return device != null && device.isReconnecting() ? banner + " (" + device.status() + ")" : banner;
    }

    /**
     * The loop's telemetry line as the format makes it (from the loop's {@link HapticLoop#telemetry()}), made again at
     * most once a second or for a new loop; pass a method reference that captures nothing, so that a call in
     * {@code draw()} allocates nothing between two refreshes.
     */
    public synchronized String telemetryLine(HapticLoop loop, java.util.function.Function<HapticLoop, String> format) {
        if (loop == null) {
            return "no haptic loop";
        }
        long now = System.nanoTime();
        if (loop != telemetryOf || now - telemetryAt > 1_000_000_000L) {
            telemetryText = format.apply(loop);
            telemetryOf = loop;
            telemetryAt = now;
        }
        return telemetryText;
    }
}
