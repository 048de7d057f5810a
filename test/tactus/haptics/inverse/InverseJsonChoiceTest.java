package tactus.haptics.inverse;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.CharArrayReader;
import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.util.Locale;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

import com.google.gson.stream.JsonReader;
import com.google.gson.stream.JsonToken;

/**
 * Why Jackson: the time and the bytes allocated to parse one state frame (an Inverse3 and a wireless VerseGrip,
 * as our emulator sends them) with Jackson's streaming parser (InverseMessageParser, what the client uses) and with
 * Gson's streaming JsonReader walking the same fields the same way. Printed; the figures are in docs/haptics.md.
 */
@Timeout(value = 120, unit = TimeUnit.SECONDS)
class InverseJsonChoiceTest {
    static final String FRAME = "{\"session_id\":100,\"inverse3\":[{\"device_id\":\"7E31\",\"state\":{"
            + "\"cursor_position\":{\"x\":0.012345678901234567,\"y\":-0.12003456789012345,\"z\":0.15012345678901234},"
            + "\"cursor_velocity\":{\"x\":0.0012345678901234567,\"y\":-0.023456789012345678,\"z\":0.003456789012345678},"
            + "\"angular_position\":{\"a0\":0.0,\"a1\":0.0,\"a2\":0.0},\"angular_velocity\":{\"a0\":0.0,\"a1\":0.0,\"a2\":0.0},"
            + "\"body_orientation\":{\"w\":1.0,\"x\":0.0,\"y\":0.0,\"z\":0.0},"
            + "\"current_cursor_force\":{\"x\":0.1,\"y\":0.2,\"z\":0.30000000000000004},"
            + "\"mode\":\"idle\",\"control_domain\":\"cartesian\",\"control_mode\":\"force\"},"
            + "\"status\":{\"calibrated\":true,\"in_use\":true,\"power_supply\":true,\"ready\":true,\"started\":true}}],"
            + "\"verse_grip\":[],\"wireless_verse_grip\":[{\"device_id\":\"6B02\",\"state\":{"
            + "\"orientation\":{\"w\":0.7071067811865476,\"x\":0.0,\"y\":0.7071067811865476,\"z\":0.0},\"hall\":0,"
            + "\"buttons\":{\"a\":true,\"b\":false,\"c\":false},\"battery_level\":0.9},"
            + "\"status\":{\"ready\":true,\"connected\":true,\"awake\":true}}]}";

    interface Parse {
        void run(char[] text, InverseState s) throws IOException;
    }

    @Test
    void jacksonAgainstGsonPerStateFrame() throws IOException {
        com.sun.management.ThreadMXBean mx = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        mx.setThreadAllocatedMemoryEnabled(true);
        char[] text = FRAME.toCharArray();
        InverseMessageParser jackson = new InverseMessageParser();
        Parse j = (t, s) -> jackson.parse(t, t.length, s);
        Parse g = InverseJsonChoiceTest::gson;
        InverseState a = new InverseState();
        InverseState b = new InverseState();
        j.run(text, a);
        g.run(text, b);
        assertEquals(a.px, b.px, 0);
        assertEquals(a.vz, b.vz, 0);
        assertEquals(a.gripY, b.gripY, 0);
        assertEquals(a.buttonA, b.buttonA);
        StringBuilder report = new StringBuilder("JSON parse of one state frame (" + text.length + " chars):");
        for (int round = 0; round < 3; round++) {
            for (String name : new String[] {"jackson", "gson"}) {
                Parse p = name.equals("jackson") ? j : g;
                InverseState s = new InverseState();
                for (int i = 0; i < 20_000; i++) {
                    p.run(text, s);   // warm-up
                }
                int n = 100_000;
                long bytes0 = mx.getThreadAllocatedBytes(Thread.currentThread().getId());
                long t0 = System.nanoTime();
                for (int i = 0; i < n; i++) {
                    p.run(text, s);
                }
                long t1 = System.nanoTime();
                long bytes1 = mx.getThreadAllocatedBytes(Thread.currentThread().getId());
                if (round == 2) {
                    report.append(String.format(Locale.ROOT, " %s %.2f us and %d B per frame;", name, (t1 - t0) / 1e3 / n,
                            (bytes1 - bytes0) / n));
                }
            }
        }
        System.out.println(report);
        assertTrue(report.length() > 0);
    }

    /** The same walk as InverseMessageParser, with Gson's streaming reader. */
    static void gson(char[] text, InverseState s) throws IOException {
        try (JsonReader r = new JsonReader(new CharArrayReader(text))) {
            r.beginObject();
            while (r.hasNext()) {
                String name = r.nextName();
                if (name.equals("inverse3")) {
                    r.beginArray();
                    int n = 0;
                    while (r.hasNext()) {
                        if (n++ == 0) {
                            inverse3(r, s);
                        } else {
                            r.skipValue();
                        }
                    }
                    r.endArray();
                    s.inverse3Count = n;
                } else if (name.equals("wireless_verse_grip") || name.equals("verse_grip")) {
                    r.beginArray();
                    while (r.hasNext()) {
                        grip(r, s);
                    }
                    r.endArray();
                } else if (name.equals("session_id")) {
                    s.sessionId = r.nextLong();
                } else {
                    r.skipValue();
                }
            }
            r.endObject();
            s.frames++;
        }
    }

    private static void inverse3(JsonReader r, InverseState s) throws IOException {
        r.beginObject();
        while (r.hasNext()) {
            String name = r.nextName();
            if (name.equals("device_id")) {
                s.deviceId = r.nextString();
            } else if (name.equals("state")) {
                r.beginObject();
                while (r.hasNext()) {
                    String k = r.nextName();
                    if (k.equals("cursor_position")) {
                        double[] v = vec(r);
                        s.px = v[0];
                        s.py = v[1];
                        s.pz = v[2];
                    } else if (k.equals("cursor_velocity")) {
                        double[] v = vec(r);
                        s.vx = v[0];
                        s.vy = v[1];
                        s.vz = v[2];
                    } else if (k.equals("current_cursor_force")) {
                        double[] v = vec(r);
                        s.fx = v[0];
                        s.fy = v[1];
                        s.fz = v[2];
                    } else {
                        r.skipValue();
                    }
                }
                r.endObject();
            } else if (name.equals("status")) {
                r.beginObject();
                while (r.hasNext()) {
                    String k = r.nextName();
                    if (r.peek() == JsonToken.BOOLEAN) {
                        boolean v = r.nextBoolean();
                        if (k.equals("ready")) {
                            s.ready = v;
                        } else if (k.equals("calibrated")) {
                            s.calibrated = v;
                        }
                    } else {
                        r.skipValue();
                    }
                }
                r.endObject();
            } else {
                r.skipValue();
            }
        }
        r.endObject();
    }

    private static void grip(JsonReader r, InverseState s) throws IOException {
        r.beginObject();
        while (r.hasNext()) {
            String name = r.nextName();
            if (name.equals("device_id")) {
                s.gripId = r.nextString();
            } else if (name.equals("state")) {
                r.beginObject();
                while (r.hasNext()) {
                    String k = r.nextName();
                    if (k.equals("orientation")) {
                        r.beginObject();
                        while (r.hasNext()) {
                            String c = r.nextName();
                            double v = r.nextDouble();
                            if (c.equals("w")) {
                                s.gripW = v;
                            } else if (c.equals("x")) {
                                s.gripX = v;
                            } else if (c.equals("y")) {
                                s.gripY = v;
                            } else {
                                s.gripZ = v;
                            }
                        }
                        r.endObject();
                    } else if (k.equals("buttons")) {
                        r.beginObject();
                        while (r.hasNext()) {
                            String c = r.nextName();
                            boolean v = r.nextBoolean();
                            if (c.equals("a")) {
                                s.buttonA = v;
                            } else if (c.equals("b")) {
                                s.buttonB = v;
                            } else {
                                s.buttonC = v;
                            }
                        }
                        r.endObject();
                    } else {
                        r.skipValue();
                    }
                }
                r.endObject();
            } else {
                r.skipValue();
            }
        }
        r.endObject();
    }

    private static double[] vec(JsonReader r) throws IOException {
        double[] v = new double[3];
        r.beginObject();
        while (r.hasNext()) {
            String c = r.nextName();
            double d = r.nextDouble();
            v[c.equals("x") ? 0 : c.equals("y") ? 1 : 2] = d;
        }
        r.endObject();
        return v;
    }
}
