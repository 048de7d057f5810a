package tactus.haptics.inverse;

/**
 * What the Inverse Service last said about the chosen Inverse3 (see {@link Inverse3Choice}) and the first VerseGrip it lists: plain fields,
 * filled by {@link InverseMessageParser} and copied by {@link #copyFrom}. Not thread-safe by itself:
 * {@link InverseServiceClient} hands it between threads under a sequence lock.
 *
 * <p>Units: metres, metres per second, newtons; quaternions (w, x, y, z).
 */
public final class InverseState {
    /** The Inverse3's id as the service names it (e.g. "049D"), or null while none is known. */
    public String deviceId;
    /** The Inverse3's kind from its configuration: "inverse3", "inverse3x", "minverse" (null if not sent yet). */
    public String deviceType;
    /** "left" or "right" from the configuration (null if not sent yet). */
    public String handedness;
    /** How many Inverse3 entries the last frame listed. */
    public int inverse3Count;
    /** True once a frame carried an {@code inverse3} list (even an empty one). */
    public boolean inverse3Listed;
    /** True if the last {@code inverse3} list held the chosen Inverse3. */
    public boolean chosenListed;
    /** The Inverse3s of the last list, for messages, e.g. "7E31 (inverse3, right-handed)"; null before any list. */
    public String listing;
    /** True if the chosen Inverse3's last {@code cursor_position} was null or lacked a number (the position keeps NaN). */
    public boolean positionBad;
    /** The session id the service gave this connection (0 if not sent). */
    public long sessionId;

    /** Cursor position (m). */
    public double px = Double.NaN;
    /** Cursor position (m). */
    public double py = Double.NaN;
    /** Cursor position (m). */
    public double pz = Double.NaN;
    /** Cursor velocity (m/s). */
    public double vx;
    /** Cursor velocity (m/s). */
    public double vy;
    /** Cursor velocity (m/s). */
    public double vz;
    /** The force the device is rendering, as the service reports it (N; 0 if not sent). */
    public double fx;
    /** The force the device is rendering (N). */
    public double fy;
    /** The force the device is rendering (N). */
    public double fz;
    /** The device body's orientation quaternion. */
    public double bodyW = 1;
    /** The device body's orientation quaternion. */
    public double bodyX;
    /** The device body's orientation quaternion. */
    public double bodyY;
    /** The device body's orientation quaternion. */
    public double bodyZ;
    /** Status flags of the Inverse3. */
    public boolean calibrated;
    /** Status flags of the Inverse3. */
    public boolean ready;
    /** Status flags of the Inverse3. */
    public boolean started;
    /** Status flags of the Inverse3. */
    public boolean inUse;
    /** Status flags of the Inverse3. */
    public boolean powerSupply;

    /** The VerseGrip's id, or null when the service lists none. */
    public String gripId;
    /** Which list it came from: "verse_grip", "wireless_verse_grip" or "custom_verse_grip". */
    public String gripKind;
    /** The VerseGrip's orientation quaternion. */
    public double gripW = 1;
    /** The VerseGrip's orientation quaternion. */
    public double gripX;
    /** The VerseGrip's orientation quaternion. */
    public double gripY;
    /** The VerseGrip's orientation quaternion. */
    public double gripZ;
    /** Buttons: a (the wired VerseGrip's single button is a), b, c. */
    public boolean buttonA;
    /** Button b (wireless VerseGrip). */
    public boolean buttonB;
    /** Button c (wireless VerseGrip). */
    public boolean buttonC;
    /** Hall sensor reading (0 if not sent). */
    public int hall;
    /** Battery level of a wireless VerseGrip (NaN if not sent). */
    public double battery = Double.NaN;

    /** Frames parsed into this state so far. */
    public long frames;
    /** True once a frame with the devices' configuration (a full snapshot) was parsed. */
    public boolean snapshotSeen;

    /** Copies every field of another state into this one. No allocation. */
    public void copyFrom(InverseState o) {
        deviceId = o.deviceId;
        deviceType = o.deviceType;
        handedness = o.handedness;
        inverse3Count = o.inverse3Count;
        inverse3Listed = o.inverse3Listed;
        chosenListed = o.chosenListed;
        listing = o.listing;
        positionBad = o.positionBad;
        sessionId = o.sessionId;
        px = o.px;
        py = o.py;
        pz = o.pz;
        vx = o.vx;
        vy = o.vy;
        vz = o.vz;
        fx = o.fx;
        fy = o.fy;
        fz = o.fz;
        bodyW = o.bodyW;
        bodyX = o.bodyX;
        bodyY = o.bodyY;
        bodyZ = o.bodyZ;
        calibrated = o.calibrated;
        ready = o.ready;
        started = o.started;
        inUse = o.inUse;
        powerSupply = o.powerSupply;
        gripId = o.gripId;
        gripKind = o.gripKind;
        gripW = o.gripW;
        gripX = o.gripX;
        gripY = o.gripY;
        gripZ = o.gripZ;
        buttonA = o.buttonA;
        buttonB = o.buttonB;
        buttonC = o.buttonC;
        hall = o.hall;
        battery = o.battery;
        frames = o.frames;
        snapshotSeen = o.snapshotSeen;
    }

    @Override
    public String toString() {
        return "InverseState[" + deviceType + " " + deviceId + " at (" + px + ", " + py + ", " + pz + ") m, v (" + vx + ", "
                + vy + ", " + vz + ") m/s, ready " + ready + ", grip " + gripId + (gripId == null ? "" : " q(" + gripW + ", "
                + gripX + ", " + gripY + ", " + gripZ + ") buttons " + buttonA + "/" + buttonB + "/" + buttonC)
                + ", frames " + frames + "]";
    }
}
