package tactus.haptics.inverse;

/**
 * Writes the JSON messages Tactus sends to the Inverse Service, into one reusable {@link StringBuilder} (no
 * allocation per message once its capacity is reached): the first message's session handshake (profile name,
 * and a request for the full state), and the per-tick {@code set_cursor_force} (newtons) for one Inverse3.
 * Numbers are written with {@link StringBuilder#append(double)} (JSON accepts its exponent form); ids and the
 * profile name are escaped once, when set.
 */
final class ForceMessage {
    private final StringBuilder text = new StringBuilder(256);
    private String prefix;

    /** Sets the Inverse3 the force messages are for. */
    void setDevice(String deviceId) {
        prefix = "{\"inverse3\":[{\"device_id\":\"" + escape(deviceId) + "\",\"commands\":{\"set_cursor_force\":{\"vector\":{\"x\":";
    }

    /** The handshake: the session's profile name and a request for the full state; no device command. */
    CharSequence handshake(String profile) {
        text.setLength(0);
        text.append("{\"session\":{\"configure\":{\"profile\":{\"name\":\"").append(escape(profile))
                .append("\"}},\"force_render_full_state\":{}}}");
        return text;
    }

    /** A set_cursor_force message with this force in newtons (finite values; the caller checks). */
    CharSequence force(double fx, double fy, double fz) {
        text.setLength(0);
        text.append(prefix).append(fx).append(",\"y\":").append(fy).append(",\"z\":").append(fz).append("}}}}]}");
        return text;
    }

    static String escape(String s) {
        StringBuilder b = new StringBuilder(s.length() + 8);
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            if (c == '"' || c == '\\') {
                b.append('\\').append(c);
            } else if (c < 0x20) {
                b.append(String.format("\\u%04x", (int) c));
            } else {
                b.append(c);
            }
        }
        return b.toString();
    }
}
