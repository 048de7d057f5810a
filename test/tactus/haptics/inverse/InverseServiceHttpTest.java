package tactus.haptics.inverse;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.time.Duration;
import java.util.concurrent.TimeUnit;

import com.google.gson.JsonObject;
import com.google.gson.JsonParser;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

import tactus.haptics.emulator.InverseServiceEmulator;

/**
 * The emulator's HTTP routes on the service's port (docs.haply.co, "HTTP"), read with the JDK's HTTP client and
 * Gson: /version and /devices raw (as the haply crate reads them) or in the envelope with ?format=json, /sessions
 * and /sessions/{id} in the envelope, and a 404 envelope for anything else.
 */
@Timeout(value = 30, unit = TimeUnit.SECONDS)
class InverseServiceHttpTest {
    private static final HttpClient HTTP = HttpClient.newBuilder().connectTimeout(Duration.ofSeconds(5)).build();

    private static HttpResponse<String> get(InverseServiceEmulator emu, String path) throws Exception {
        return HTTP.send(HttpRequest.newBuilder(URI.create("http://localhost:" + emu.port() + path))
                .timeout(Duration.ofSeconds(5)).GET().build(), HttpResponse.BodyHandlers.ofString());
    }

    @Test
    void versionAndDevicesAnswerAsTheServiceDoes() throws Exception {
        try (InverseServiceEmulator emu = InverseServiceEmulator.start(0)) {
            emu.setVerseGrip("wireless_verse_grip");
            HttpResponse<String> v = get(emu, "/version");
            assertEquals(200, v.statusCode());
            JsonObject version = JsonParser.parseString(v.body()).getAsJsonObject();
            assertEquals("haply-inverse-service", version.get("project_name").getAsString());
            assertEquals(InverseServiceEmulator.VERSION, version.get("git_tag").getAsString());
            for (String k : new String[] {"build_time", "git_branch", "git_describe", "git_hash", "project_version"}) {
                assertTrue(version.has(k), k);
            }
            HttpResponse<String> d = get(emu, "/devices");
            assertEquals(200, d.statusCode());
            assertTrue(d.headers().firstValue("content-type").orElse("").contains("application/json"));
            JsonObject devices = JsonParser.parseString(d.body()).getAsJsonObject();
            JsonObject inv = devices.getAsJsonArray("inverse3").get(0).getAsJsonObject();
            assertEquals(InverseServiceEmulator.DEVICE_ID, inv.get("device_id").getAsString());
            assertEquals("inverse3", inv.getAsJsonObject("config").get("type").getAsString());
            assertTrue(inv.getAsJsonObject("state").has("cursor_position"));
            assertTrue(inv.has("status"));
            assertEquals(InverseServiceEmulator.GRIP_ID,
                    devices.getAsJsonArray("wireless_verse_grip").get(0).getAsJsonObject().get("device_id").getAsString());
            // our own parser reads the same inventory
            InverseState s = new InverseState();
            new InverseMessageParser().parse(d.body().toCharArray(), d.body().length(), s);
            assertEquals(InverseServiceEmulator.DEVICE_ID, s.deviceId);
            assertEquals(tactus.haptics.emulator.SimulatedInverse3.HOME[1], s.py, 1e-9);

            JsonObject env = JsonParser.parseString(get(emu, "/devices?format=json").body()).getAsJsonObject();
            assertTrue(env.get("ok").getAsBoolean());
            assertEquals(InverseServiceEmulator.DEVICE_ID, env.getAsJsonObject("data").getAsJsonArray("inverse3").get(0)
                    .getAsJsonObject().get("device_id").getAsString());
        }
    }

    @Test
    void sessionsListTheOpenConnectionsWithTheirProfiles() throws Exception {
        try (InverseServiceEmulator emu = InverseServiceEmulator.start(0)) {
            JsonObject none = JsonParser.parseString(get(emu, "/sessions").body()).getAsJsonObject();
            assertTrue(none.get("ok").getAsBoolean());
            assertEquals(0, none.getAsJsonObject("data").get("session_count").getAsInt());
            try (InverseServiceClient c = InverseServiceClient.connect(emu.uri(), 3000)) {
                InverseState st = new InverseState();
                c.read(st);
                JsonObject one = JsonParser.parseString(get(emu, "/sessions").body()).getAsJsonObject();
                JsonObject data = one.getAsJsonObject("data");
                assertEquals(1, data.get("session_count").getAsInt());
                JsonObject session = data.getAsJsonArray("sessions").get(0).getAsJsonObject();
                long id = session.get("session_id").getAsLong();
                assertEquals(st.sessionId, id, "the id the WebSocket snapshot gave");
                assertEquals(InverseServiceClient.PROFILE, session.getAsJsonObject("config").getAsJsonObject("profile")
                        .get("name").getAsString());
                HttpResponse<String> byId = get(emu, "/sessions/" + id);
                assertEquals(200, byId.statusCode());
                assertEquals(id, JsonParser.parseString(byId.body()).getAsJsonObject().getAsJsonObject("data")
                        .get("session_id").getAsLong());
                HttpResponse<String> missing = get(emu, "/sessions/" + (id + 1000));
                assertEquals(404, missing.statusCode());
                assertTrue(!JsonParser.parseString(missing.body()).getAsJsonObject().get("ok").getAsBoolean());
            }
        }
    }

    @Test
    void anUnknownRouteOrMethodIsAnErrorEnvelopeAndTheWebSocketStillWorks() throws Exception {
        try (InverseServiceEmulator emu = InverseServiceEmulator.start(0)) {
            HttpResponse<String> r = get(emu, "/no/such/route");
            assertEquals(404, r.statusCode());
            JsonObject e = JsonParser.parseString(r.body()).getAsJsonObject();
            assertTrue(!e.get("ok").getAsBoolean() && e.get("error").getAsString().contains("/no/such/route"), r.body());
            HttpResponse<String> post = HTTP.send(HttpRequest.newBuilder(URI.create("http://localhost:" + emu.port()
                    + "/force_scale")).POST(HttpRequest.BodyPublishers.ofString("{\"force_scale\":0.5}")).build(),
                    HttpResponse.BodyHandlers.ofString());
            assertEquals(405, post.statusCode());
            try (InverseServiceClient c = InverseServiceClient.connect(emu.uri(), 3000)) {
                assertTrue(c.sendForce(0.1, 0, 0), "the WebSocket on the same port still works");
            }
        }
    }
}
