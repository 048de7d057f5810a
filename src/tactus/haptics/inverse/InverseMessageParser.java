package tactus.haptics.inverse;

import java.io.IOException;

import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonToken;
import com.fasterxml.jackson.core.StreamReadFeature;

/**
 * Reads one message of the Inverse Service (a full snapshot or a state frame) into an {@link InverseState},
 * with Jackson's streaming parser: the entry of {@code inverse3} that {@link #choose} names, found by its
 * {@code device_id} once the snapshot gave it (by default the first listed; id, configuration's type and
 * handedness, {@code cursor_position}, {@code cursor_velocity}, {@code current_cursor_force},
 * {@code body_orientation}, status flags) and the first VerseGrip of {@code verse_grip},
 * {@code wireless_verse_grip} or {@code custom_verse_grip} (orientation, buttons, hall, battery). Every other
 * field is skipped, so fields added by later service versions do no harm. Field names are not copied (Jackson
 * keeps them in its symbol table), ids are kept when unchanged and numbers are read with Jackson's fast double
 * parser, so a state frame allocates only the parser's own small objects (measured in docs/haptics.md).
 */
public final class InverseMessageParser {
    // The fast double parser reads a number from the parser's buffer (correctly rounded, as Double.parseDouble)
    // without making a String of it first: about 60 B per number instead of about 330 B.
    private final JsonFactory factory = JsonFactory.builder().enable(StreamReadFeature.USE_FAST_DOUBLE_PARSER).build();
    private boolean gripListed;

    // which Inverse3 is ours, and what the last list held (its ids, and types and handedness from the snapshot)
    private static final int POSITION = 1;
    private static final int POSITION_BAD = 2;
    private static final int VELOCITY = 4;
    private static final int FORCE = 8;
    private static final int BODY = 16;
    private static final int STATUS = 32;
    private Inverse3Choice choice = Inverse3Choice.FIRST;
    private String chosenId;
    private String entryIdHint;
    private int mask;
    private final InverseState entry = new InverseState();
    private String[] ids = new String[4];
    private String[] types = new String[4];
    private String[] hands = new String[4];
    private int listed = -1;

    /**
     * Parses {@code text[0..length)} into {@code into}; fields a message does not carry keep their values.
     *
     * @throws IOException if the text is not JSON, or not a JSON object
     */
    public void parse(char[] text, int length, InverseState into) throws IOException {
        try (JsonParser p = factory.createParser(text, 0, length)) {
            if (p.nextToken() != JsonToken.START_OBJECT) {
                throw new IOException("an Inverse Service message must be a JSON object");
            }
            boolean gripListSeen = false;
            gripListed = false;
            boolean config = false;
            while (p.nextToken() == JsonToken.FIELD_NAME) {
                String name = p.currentName();
                JsonToken t = p.nextToken();
                if ("inverse3".equals(name) && t == JsonToken.START_ARRAY) {
                    config |= inverse3List(p, into);
                } else if (("verse_grip".equals(name) || "wireless_verse_grip".equals(name)
                        || "custom_verse_grip".equals(name)) && t == JsonToken.START_ARRAY) {
                    gripListSeen = true;
                    config |= gripList(p, into, name);
                } else if ("session_id".equals(name) && t.isNumeric()) {
                    into.sessionId = p.getLongValue();
                } else {
                    p.skipChildren();
                }
            }
            if (gripListSeen && !gripListed) {
                into.gripId = null;
                into.gripKind = null;
            }
            if (config) {
                into.snapshotSeen = true;
            }
            into.frames++;
        }
    }

    /** Drives the Inverse3 this choice names (default {@link Inverse3Choice#FIRST}); call before the first parse. */
    public void choose(Inverse3Choice which) {
        if (which == null) {
            throw new IllegalArgumentException("InverseMessageParser.choose: need a choice, e.g. Inverse3Choice.FIRST");
        }
        choice = which;
        chosenId = which.id();
    }

    private boolean inverse3List(JsonParser p, InverseState s) throws IOException {
        int n = 0;
        boolean config = false;
        boolean matched = false;
        boolean changed = false;
        while (p.nextToken() != JsonToken.END_ARRAY) {
            if (p.currentToken() != JsonToken.START_OBJECT) {
                p.skipChildren();
                n++;
                continue;
            }
            if (n == ids.length) {
                ids = java.util.Arrays.copyOf(ids, 2 * n);
                types = java.util.Arrays.copyOf(types, 2 * n);
                hands = java.util.Arrays.copyOf(hands, 2 * n);
            }
            mask = 0;
            entry.deviceId = null;
            entry.deviceType = null;
            entry.handedness = null;
            entryIdHint = ids[n];
            boolean c = inverse3(p, entry);
            config |= c;
            if (entry.deviceId != ids[n]) {
                ids[n] = entry.deviceId;
                changed = true;
            }
            if (c) {
                types[n] = entry.deviceType;
                hands[n] = entry.handedness;
                changed = true;
            }
            if (!matched && chosen(n)) {
                matched = true;
                take(s, c);
                if (c && ids[n] != null) {
                    chosenId = ids[n];   // from the snapshot on, the device is followed by its id wherever it is listed
                }
            }
            n++;
        }
        if (n != listed) {
            changed = true;
        }
        listed = n;
        if (changed) {
            s.listing = describeListing();
        }
        s.inverse3Count = n;
        s.inverse3Listed = true;
        s.chosenListed = matched;
        return config;
    }

    private boolean chosen(int n) {
        if (chosenId != null) {
            return chosenId.equals(ids[n]);
        }
        return choice.handedness() != null ? choice.handedness().equals(hands[n]) : n == choice.index();
    }

    /** Copies the groups of fields the chosen entry carried into the state. */
    private void take(InverseState s, boolean config) {
        if (entry.deviceId != null) {
            s.deviceId = entry.deviceId;
        }
        if (config) {
            s.deviceType = entry.deviceType;
            s.handedness = entry.handedness;
        }
        if ((mask & POSITION) != 0) {
            s.px = entry.px;
            s.py = entry.py;
            s.pz = entry.pz;
            s.positionBad = (mask & POSITION_BAD) != 0;
        }
        if ((mask & VELOCITY) != 0) {
            s.vx = entry.vx;
            s.vy = entry.vy;
            s.vz = entry.vz;
        }
        if ((mask & FORCE) != 0) {
            s.fx = entry.fx;
            s.fy = entry.fy;
            s.fz = entry.fz;
        }
        if ((mask & BODY) != 0) {
            s.bodyW = entry.bodyW;
            s.bodyX = entry.bodyX;
            s.bodyY = entry.bodyY;
            s.bodyZ = entry.bodyZ;
        }
        if ((mask & STATUS) != 0) {
            s.calibrated = entry.calibrated;
            s.ready = entry.ready;
            s.started = entry.started;
            s.inUse = entry.inUse;
            s.powerSupply = entry.powerSupply;
        }
    }

    /** The Inverse3s of the last list, for messages: "7E31 (inverse3, right), 0A11 (inverse3, left)". */
    private String describeListing() {
        if (listed == 0) {
            return "no Inverse3";
        }
        StringBuilder b = new StringBuilder();
        for (int i = 0; i < listed; i++) {
            if (i > 0) {
                b.append(", ");
            }
            b.append(ids[i] == null ? "(no id)" : ids[i]);
            if (types[i] != null || hands[i] != null) {
                b.append(" (").append(types[i] == null ? "type not given" : types[i]);
                if (hands[i] != null) {
                    b.append(", ").append(hands[i]).append("-handed");
                }
                b.append(')');
            }
        }
        return b.toString();
    }

    private boolean inverse3(JsonParser p, InverseState s) throws IOException {
        boolean config = false;
        while (p.nextToken() == JsonToken.FIELD_NAME) {
            String name = p.currentName();
            JsonToken t = p.nextToken();
            if ("device_id".equals(name) && t == JsonToken.VALUE_STRING) {
                s.deviceId = keep(p, entryIdHint != null ? entryIdHint : chosenId);
            } else if ("config".equals(name) && t == JsonToken.START_OBJECT) {
                config = true;
                inverse3Config(p, s);
            } else if ("state".equals(name) && t == JsonToken.START_OBJECT) {
                inverse3State(p, s);
            } else if ("status".equals(name) && t == JsonToken.START_OBJECT) {
                mask |= STATUS;
                inverse3Status(p, s);
            } else {
                p.skipChildren();
            }
        }
        return config;
    }

    private void inverse3Config(JsonParser p, InverseState s) throws IOException {
        while (p.nextToken() == JsonToken.FIELD_NAME) {
            String name = p.currentName();
            JsonToken t = p.nextToken();
            if ("type".equals(name) && t == JsonToken.VALUE_STRING) {
                s.deviceType = keep(p, s.deviceType);
            } else if ("handedness".equals(name) && t == JsonToken.VALUE_STRING) {
                s.handedness = keep(p, s.handedness);
            } else if ("device_info".equals(name) && t == JsonToken.START_OBJECT) {
                while (p.nextToken() == JsonToken.FIELD_NAME) {
                    String n = p.currentName();
                    JsonToken v = p.nextToken();
                    if ("device_type".equals(n) && s.deviceType == null) {
                        if (v == JsonToken.VALUE_STRING) {
                            s.deviceType = p.getText();
                        } else if (v == JsonToken.VALUE_NUMBER_INT) {
                            int code = p.getIntValue();   // the service's numeric codes: 4 Inverse3, 6 Minverse
                            s.deviceType = code == 4 ? "inverse3" : code == 6 ? "minverse" : "device type " + code;
                        }
                    } else {
                        p.skipChildren();
                    }
                }
            } else {
                p.skipChildren();
            }
        }
    }

    private void inverse3State(JsonParser p, InverseState s) throws IOException {
        while (p.nextToken() == JsonToken.FIELD_NAME) {
            String name = p.currentName();
            JsonToken t = p.nextToken();
            if (t != JsonToken.START_OBJECT) {
                if ("cursor_position".equals(name)) {
                    mask |= POSITION | POSITION_BAD;   // null, or a number where an object belongs
                }
                p.skipChildren();
            } else if ("cursor_position".equals(name)) {
                mask |= POSITION;
                s.px = Double.NaN;
                s.py = Double.NaN;
                s.pz = Double.NaN;
                while (p.nextToken() == JsonToken.FIELD_NAME) {
                    String n = p.currentName();
                    p.nextToken();
                    double v = number(p);
                    if ("x".equals(n)) {
                        s.px = v;
                    } else if ("y".equals(n)) {
                        s.py = v;
                    } else if ("z".equals(n)) {
                        s.pz = v;
                    }
                }
                if (Double.isNaN(s.px) || Double.isNaN(s.py) || Double.isNaN(s.pz)) {
                    mask |= POSITION_BAD;   // a component missing or not a number
                }
            } else if ("cursor_velocity".equals(name)) {
                mask |= VELOCITY;
                while (p.nextToken() == JsonToken.FIELD_NAME) {
                    String n = p.currentName();
                    p.nextToken();
                    double v = number(p);
                    if ("x".equals(n)) {
                        s.vx = v;
                    } else if ("y".equals(n)) {
                        s.vy = v;
                    } else if ("z".equals(n)) {
                        s.vz = v;
                    }
                }
            } else if ("current_cursor_force".equals(name)) {
                mask |= FORCE;
                while (p.nextToken() == JsonToken.FIELD_NAME) {
                    String n = p.currentName();
                    p.nextToken();
                    double v = number(p);
                    if ("x".equals(n)) {
                        s.fx = v;
                    } else if ("y".equals(n)) {
                        s.fy = v;
                    } else if ("z".equals(n)) {
                        s.fz = v;
                    }
                }
            } else if ("body_orientation".equals(name)) {
                mask |= BODY;
                while (p.nextToken() == JsonToken.FIELD_NAME) {
                    String n = p.currentName();
                    p.nextToken();
                    double v = number(p);
                    if ("w".equals(n)) {
                        s.bodyW = v;
                    } else if ("x".equals(n)) {
                        s.bodyX = v;
                    } else if ("y".equals(n)) {
                        s.bodyY = v;
                    } else if ("z".equals(n)) {
                        s.bodyZ = v;
                    }
                }
            } else {
                p.skipChildren();
            }
        }
    }

    private void inverse3Status(JsonParser p, InverseState s) throws IOException {
        while (p.nextToken() == JsonToken.FIELD_NAME) {
            String name = p.currentName();
            JsonToken t = p.nextToken();
            if (t == JsonToken.VALUE_TRUE || t == JsonToken.VALUE_FALSE) {
                boolean b = t == JsonToken.VALUE_TRUE;
                if ("calibrated".equals(name)) {
                    s.calibrated = b;
                } else if ("ready".equals(name)) {
                    s.ready = b;
                } else if ("started".equals(name)) {
                    s.started = b;
                } else if ("in_use".equals(name)) {
                    s.inUse = b;
                } else if ("power_supply".equals(name)) {
                    s.powerSupply = b;
                }
            } else {
                p.skipChildren();
            }
        }
    }

    private boolean gripList(JsonParser p, InverseState s, String kind) throws IOException {
        boolean config = false;
        while (p.nextToken() != JsonToken.END_ARRAY) {
            if (!gripListed && p.currentToken() == JsonToken.START_OBJECT) {
                gripListed = true;
                s.gripKind = kind;
                config |= grip(p, s);
            } else {
                p.skipChildren();
            }
        }
        return config;
    }

    private boolean grip(JsonParser p, InverseState s) throws IOException {
        boolean config = false;
        while (p.nextToken() == JsonToken.FIELD_NAME) {
            String name = p.currentName();
            JsonToken t = p.nextToken();
            if ("device_id".equals(name) && t == JsonToken.VALUE_STRING) {
                s.gripId = keep(p, s.gripId);
            } else if ("state".equals(name) && t == JsonToken.START_OBJECT) {
                gripState(p, s);
            } else {
                if ("config".equals(name) && t == JsonToken.START_OBJECT) {
                    config = true;
                }
                p.skipChildren();
            }
        }
        return config;
    }

    private void gripState(JsonParser p, InverseState s) throws IOException {
        while (p.nextToken() == JsonToken.FIELD_NAME) {
            String name = p.currentName();
            JsonToken t = p.nextToken();
            if ("orientation".equals(name) && t == JsonToken.START_OBJECT) {
                while (p.nextToken() == JsonToken.FIELD_NAME) {
                    String n = p.currentName();
                    p.nextToken();
                    double v = number(p);
                    if ("w".equals(n)) {
                        s.gripW = v;
                    } else if ("x".equals(n)) {
                        s.gripX = v;
                    } else if ("y".equals(n)) {
                        s.gripY = v;
                    } else if ("z".equals(n)) {
                        s.gripZ = v;
                    }
                }
            } else if ("button".equals(name) && (t == JsonToken.VALUE_TRUE || t == JsonToken.VALUE_FALSE)) {
                s.buttonA = t == JsonToken.VALUE_TRUE;   // the wired VerseGrip's one button
            } else if ("buttons".equals(name) && t == JsonToken.START_OBJECT) {
                while (p.nextToken() == JsonToken.FIELD_NAME) {
                    String n = p.currentName();
                    JsonToken v = p.nextToken();
                    boolean b = v == JsonToken.VALUE_TRUE;
                    if ("a".equals(n)) {
                        s.buttonA = b;
                    } else if ("b".equals(n)) {
                        s.buttonB = b;
                    } else if ("c".equals(n)) {
                        s.buttonC = b;
                    } else {
                        p.skipChildren();
                    }
                }
            } else if ("hall".equals(name) && t.isNumeric()) {
                s.hall = p.getIntValue();
            } else if ("battery_level".equals(name) && t.isNumeric()) {
                s.battery = p.getDoubleValue();
            } else {
                p.skipChildren();
            }
        }
    }

    private static double number(JsonParser p) throws IOException {
        JsonToken t = p.currentToken();
        if (t != null && t.isNumeric()) {
            return p.getDoubleValue();
        }
        p.skipChildren();
        return Double.NaN;
    }

    /** The string value, reusing {@code old} when it has the same characters (no allocation then). */
    private static String keep(JsonParser p, String old) throws IOException {
        if (old != null) {
            char[] c = p.getTextCharacters();
            int off = p.getTextOffset();
            int len = p.getTextLength();
            if (len == old.length()) {
                boolean same = true;
                for (int i = 0; i < len; i++) {
                    if (c[off + i] != old.charAt(i)) {
                        same = false;
                        break;
                    }
                }
                if (same) {
                    return old;
                }
            }
        }
        return p.getText();
    }
}
