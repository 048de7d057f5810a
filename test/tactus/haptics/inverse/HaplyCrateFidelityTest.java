package tactus.haptics.inverse;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

import tactus.haptics.emulator.InverseServiceEmulator;

/**
 * Haply's own client (the {@code haply} crate, in the probe program of test-resources/haply-probe) against our
 * emulator: it must find the Inverse3 in the snapshot, and the forces it sends must be the forces our emulator
 * receives, and the positions it reads must be positions our emulator sent, in order; the crate's HTTP client must
 * read the emulator's GET /version, GET /devices and GET /sessions on the same port. The probe prints every warning
 * and error the crate logs (its parser falls back to partial parsing after logging a schema error, which would
 * otherwise pass unseen): there must be none.
 */
@Timeout(value = 25, unit = TimeUnit.MINUTES)   // the first build of the probe compiles about 200 crates
class HaplyCrateFidelityTest {
    static final int N = 200;

    @Test
    void haplysClientAgreesWithOurEmulator() throws Exception {
        Path probe = HaplyCrate.buildProbe();
        try (InverseServiceEmulator emu = InverseServiceEmulator.start(0)) {
            emu.setLockstep(1e-3);
            emu.setRecording(true);
            String out = HaplyCrate.run(probe.getParent(), 120, probe.toString(), String.valueOf(emu.port()),
                    String.valueOf(N));
            assertTrue(out != null, "the probe failed");
            List<float[]> sent = new ArrayList<>();
            List<float[]> read = new ArrayList<>();
            boolean device = false;
            boolean done = false;
            boolean version = false;
            boolean httpDevice = false;
            boolean session = false;
            List<String> logged = new ArrayList<>();
            for (String line : out.split("\n")) {
                if (line.startsWith("CRATE-")) {
                    logged.add(line);
                }
                String[] w = line.trim().split(" ");
                if (w[0].equals("DEVICE")) {
                    device |= w[1].equals(InverseServiceEmulator.DEVICE_ID) && w[2].equals("Inverse3");
                } else if (w[0].equals("SENT")) {
                    sent.add(floats(w));
                } else if (w[0].equals("POS")) {
                    read.add(floats(w));
                } else if (w[0].equals("VERSION")) {
                    version = w[1].equals("haply-inverse-service") && w[2].equals(InverseServiceEmulator.VERSION);
                } else if (w[0].equals("HTTPDEVICE")) {
                    httpDevice |= w[1].equals(InverseServiceEmulator.DEVICE_ID) && w[2].equals("Inverse3");
                } else if (w[0].equals("SESSION")) {
                    session |= w.length == 3 && w[2].equals("haply-probe");
                } else if (w[0].equals("DONE")) {
                    done = true;
                }
            }
            assertTrue(logged.isEmpty(), "the crate logged warnings or errors reading the emulator (a schema error its "
                    + "fallback parsing would hide):\n" + String.join("\n", logged));
            assertTrue(device, "the crate lists the emulated Inverse3 from the snapshot:\n" + out);
            assertTrue(done, out);
            assertTrue(version, "the crate's HTTP client reads the emulator's GET /version:\n" + out);
            assertTrue(httpDevice, "the crate's HTTP client lists the Inverse3 from GET /devices:\n" + out);
            assertTrue(session, "the crate's HTTP client finds its own session, by profile, in GET /sessions:\n" + out);
            assertEquals(N, sent.size());
            assertEquals(N, read.size());
            // forces: what the crate sent is what the emulator received, one for one, in order
            List<double[]> received = emu.receivedForces();
            assertEquals(N, received.size(), "one set_cursor_force per message of the crate");
            for (int k = 0; k < N; k++) {
                for (int i = 0; i < 3; i++) {
                    assertEquals(sent.get(k)[i], (float) received.get(k)[i], 0, "force " + k + " axis " + i);
                }
            }
            // positions: each one the crate read is one the emulator sent (to the crate's f32), in order
            List<double[]> positions = emu.sentPositions();
            int j = 0;
            int matched = 0;
            for (int k = 0; k < N; k++) {
                float[] p = read.get(k);
                int found = -1;
                for (int m = j; m < positions.size(); m++) {
                    double[] q = positions.get(m);
                    if ((float) q[0] == p[0] && (float) q[1] == p[1] && (float) q[2] == p[2]) {
                        found = m;
                        break;
                    }
                }
                assertTrue(found >= 0, "position " + k + " read by the crate was never sent by the emulator (after frame "
                        + j + "): " + java.util.Arrays.toString(p));
                j = found;
                matched++;
            }
            // the handle moved under those forces (+x, -y, +z), and the crate saw it move
            float[] first = read.get(0);
            float[] last = read.get(N - 1);
            assertTrue(last[0] > first[0] && last[1] < first[1] && last[2] > first[2], "the crate saw the handle move");
            System.out.println("haply crate " + HaplyCrate.version() + " against the emulator: " + N + " forces sent = received, "
                    + matched + " positions read = sent (f32), device " + InverseServiceEmulator.DEVICE_ID + " listed (snapshot "
                    + "and GET /devices), GET /version and GET /sessions read");
        }
    }

    private static float[] floats(String[] w) {
        return new float[] {Float.parseFloat(w[2]), Float.parseFloat(w[3]), Float.parseFloat(w[4])};
    }

}
