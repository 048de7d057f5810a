package tactus.haptics.inverse;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

import com.google.gson.JsonArray;
import com.google.gson.JsonElement;
import com.google.gson.JsonObject;
import com.google.gson.JsonParser;

/**
 * Our parser reads every sample message of the {@code haply} crate's sources and tests that concerns an
 * Inverse3 or a VerseGrip (read from the Cargo registry at test time, never copied here), and gets the same
 * values as an independent reading of the same text with Gson's tree model.
 */
@Timeout(value = 15, unit = TimeUnit.MINUTES)   // a first cargo fetch
class CrateSamplesTest {
    private static final String[] LISTS = {"inverse3", "verse_grip", "wireless_verse_grip", "custom_verse_grip"};

    @Test
    void everyInverse3AndVerseGripSampleOfTheCrateParses() throws Exception {
        Path crate = HaplyCrate.sources();
        List<String[]> literals = HaplyCrate.jsonLiterals(crate);
        int samples = 0;
        int withPosition = 0;
        int withGrip = 0;
        for (String[] lit : literals) {
            JsonElement tree = JsonParser.parseString(lit[1]);
            if (!tree.isJsonObject() || !concernsDevices(tree.getAsJsonObject())) {
                continue;
            }
            samples++;
            JsonObject o = tree.getAsJsonObject();
            InverseState s = new InverseState();
            char[] text = lit[1].toCharArray();
            // a parser per sample: each is a service's first message (a parser follows the Inverse3 its first
            // snapshot gave by id, so one parser for every sample would follow the first sample's device)
            new InverseMessageParser().parse(text, text.length, s);
            assertEquals(1, s.frames, lit[0]);
            JsonArray inv = o.has("inverse3") && o.get("inverse3").isJsonArray() ? o.getAsJsonArray("inverse3") : null;
            if (inv != null) {
                assertEquals(inv.size(), s.inverse3Count, lit[0]);
            }
            if (inv != null && inv.size() > 0) {
                JsonObject d = inv.get(0).getAsJsonObject();
                assertEquals(d.get("device_id").getAsString(), s.deviceId, lit[0]);
                JsonObject st = d.has("state") && d.get("state").isJsonObject() ? d.getAsJsonObject("state") : null;
                if (st != null && st.has("cursor_position") && st.get("cursor_position").isJsonObject()) {
                    JsonObject p = st.getAsJsonObject("cursor_position");
                    if (isNumber(p, "x") && isNumber(p, "y") && isNumber(p, "z")) {
                        withPosition++;
                        assertEquals(p.get("x").getAsDouble(), s.px, 0, lit[0]);
                        assertEquals(p.get("y").getAsDouble(), s.py, 0, lit[0]);
                        assertEquals(p.get("z").getAsDouble(), s.pz, 0, lit[0]);
                    }
                }
                if (st != null && st.has("cursor_velocity") && st.get("cursor_velocity").isJsonObject()
                        && isNumber(st.getAsJsonObject("cursor_velocity"), "x")) {
                    assertEquals(st.getAsJsonObject("cursor_velocity").get("x").getAsDouble(), s.vx, 0, lit[0]);
                }
                if (st != null && st.has("body_orientation") && st.get("body_orientation").isJsonObject()
                        && isNumber(st.getAsJsonObject("body_orientation"), "w")) {
                    assertEquals(st.getAsJsonObject("body_orientation").get("w").getAsDouble(), s.bodyW, 0, lit[0]);
                }
                JsonObject status = d.has("status") && d.get("status").isJsonObject() ? d.getAsJsonObject("status") : null;
                if (status != null && status.has("ready") && status.get("ready").isJsonPrimitive()
                        && status.getAsJsonPrimitive("ready").isBoolean()) {
                    assertEquals(status.get("ready").getAsBoolean(), s.ready, lit[0]);
                }
                if (d.has("config") && d.get("config").isJsonObject() && d.getAsJsonObject("config").has("type")) {
                    assertEquals(d.getAsJsonObject("config").get("type").getAsString(), s.deviceType, lit[0]);
                }
            }
            JsonObject grip = firstGrip(o);
            if (grip != null) {
                withGrip++;
                assertNotNull(s.gripId, lit[0]);
                assertEquals(grip.get("device_id").getAsString(), s.gripId, lit[0]);
                JsonObject st = grip.has("state") && grip.get("state").isJsonObject() ? grip.getAsJsonObject("state") : null;
                if (st != null && st.has("orientation") && st.get("orientation").isJsonObject()
                        && isNumber(st.getAsJsonObject("orientation"), "w")) {
                    JsonObject q = st.getAsJsonObject("orientation");
                    assertEquals(q.get("w").getAsDouble(), s.gripW, 0, lit[0]);
                    assertEquals(q.get("x").getAsDouble(), s.gripX, 0, lit[0]);
                }
                if (st != null && st.has("buttons") && st.get("buttons").isJsonObject()) {
                    JsonObject b = st.getAsJsonObject("buttons");
                    if (b.has("a") && b.get("a").isJsonPrimitive()) {
                        assertEquals(b.get("a").getAsBoolean(), s.buttonA, lit[0]);
                    }
                    if (b.has("b") && b.get("b").isJsonPrimitive()) {
                        assertEquals(b.get("b").getAsBoolean(), s.buttonB, lit[0]);
                    }
                } else if (st != null && st.has("button") && st.get("button").isJsonPrimitive()) {
                    assertEquals(st.get("button").getAsBoolean(), s.buttonA, lit[0]);
                }
            } else {
                assertEquals(null, s.gripId, lit[0]);
            }
        }
        System.out.println("haply crate " + HaplyCrate.version() + ": " + literals.size() + " JSON literals, " + samples
                + " concern an Inverse3 or a VerseGrip and parse (" + withPosition + " with a cursor position, " + withGrip
                + " with a VerseGrip), values equal to Gson's reading");
        assertTrue(samples >= 10, "found only " + samples + " samples in " + crate);
        assertTrue(withPosition >= 3 && withGrip >= 3, withPosition + " with a position, " + withGrip + " with a grip");
    }

    private static boolean concernsDevices(JsonObject o) {
        for (String k : LISTS) {
            if (o.has(k)) {
                return true;
            }
        }
        return false;
    }

    private static JsonObject firstGrip(JsonObject o) {
        for (int i = 1; i < LISTS.length; i++) {
            if (o.has(LISTS[i]) && o.get(LISTS[i]).isJsonArray()) {
                for (JsonElement e : o.getAsJsonArray(LISTS[i])) {
                    if (e.isJsonObject()) {
                        return e.getAsJsonObject();
                    }
                }
            }
        }
        return null;
    }

    private static boolean isNumber(JsonObject o, String k) {
        return o.has(k) && o.get(k).isJsonPrimitive() && o.getAsJsonPrimitive(k).isNumber();
    }
}
