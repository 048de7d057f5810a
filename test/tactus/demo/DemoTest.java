package tactus.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;

import javax.sound.sampled.AudioFormat;
import javax.sound.sampled.AudioInputStream;
import javax.sound.sampled.AudioSystem;

import javax.imageio.ImageIO;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Runs the headless demo once into a temporary folder (about 8 s, most of it the real-time audio-haptic
 * run) and checks what it wrote: the CSV columns and row counts, the PNG sizes, and the string's pitch,
 * which this test measures again from string.csv and compares with the discrete-scheme theory that it
 * computes itself; for the audio-haptic plucked string, the WAV (length, not silent, its pitch after the
 * last contact against theory), the pictures, and the telemetry (the force is there while the plectrum
 * touches the string and nowhere else, it is the avatar force through the gains, the loop ticks at about
 * 1 kHz).
 */
class DemoTest {
    /** Largest accepted distance between the pitch measured from string.csv and theory, in cents. */
    static final double PITCH_TOLERANCE_CENTS = 1.0;

    @TempDir
    static Path tmp;

    static Path out;
    static int status;
    static String stdout;
    static String stderr;

    @BeforeAll
    static void runDemo() {
        out = tmp.resolve("demo out");
        ByteArrayOutputStream o = new ByteArrayOutputStream();
        ByteArrayOutputStream e = new ByteArrayOutputStream();
        status = Demo.run(new String[] {out.toString()}, new PrintStream(o, true, StandardCharsets.UTF_8),
                new PrintStream(e, true, StandardCharsets.UTF_8));
        stdout = o.toString(StandardCharsets.UTF_8);
        stderr = e.toString(StandardCharsets.UTF_8);
    }

    @Test
    void exitsWithZeroAndSaysWhereTheFilesAre() {
        assertEquals(0, status, "exit status; error stream:\n" + stderr + "\noutput:\n" + stdout);
        assertEquals("", stderr);
        assertTrue(stdout.contains(out.toAbsolutePath().normalize().toString()), stdout);
        assertTrue(stdout.contains("Demo finished"), stdout);
        for (String f : new String[] {"figure4.csv", "figure4.png", "string.csv", "string.png", "string-shape.png",
            "pluck.wav", "pluck-scene.png", "pluck-path.png", "pluck-waveform.png", "pluck-telemetry.csv",
            "pluck-telemetry.txt"}) {
            Path p = out.resolve(f);
            assertTrue(Files.isRegularFile(p), "missing " + p);
            assertTrue(stdout.contains(p.toAbsolutePath().normalize().toString()), "not reported: " + f);
        }
    }

    @Test
    void figure4CsvHasTimeAndThreeCoordinatesAtEveryStep() throws IOException {
        double[][] rows = readCsv(out.resolve("figure4.csv"), "t_s,mass_x,mass_y,mass_z");
        int steps = (int) Math.round(Demo.SECONDS * Demo.FIG4_SIM_RATE);
        assertEquals(steps + 1, rows.length, "one row for the start and one per step");
        checkTimeColumn(rows, Demo.FIG4_SIM_RATE);
        assertEquals(0.0, rows[0][1], 0.0);
        assertEquals(0.0, rows[0][3], 0.0);
        double minX = 0;
        for (double[] r : rows) {
            assertEquals(0.0, r[2], 1e-12, "nothing pushes the mass along y");
            minX = Math.min(minX, r[1]);
        }
        // It swings about the balance point x = -0.1 with amplitude 0.1: down to about x = -0.2.
        assertEquals(-0.2, minX, 0.01);
    }

    @Test
    void stringCsvHasTimeAndTheListenedBeads() throws IOException {
        double[][] rows = readCsv(out.resolve("string.csv"), "t_s,str5_y_m,str13_y_m,str25_y_m");
        int steps = (int) Math.round(Demo.SECONDS * Demo.STRING_RATE);
        assertEquals(steps + 1, rows.length, "one row for the start and one per step");
        checkTimeColumn(rows, Demo.STRING_RATE);
        // The triangle at the start: 3 mm in the middle (bead 25 of 49), proportionally less elsewhere.
        double half = (Demo.STRING_BEADS + 1) / 2.0;
        int[] beads = {5, 13, 25};
        for (int j = 0; j < beads.length; j++) {
            double expected = Demo.PLUCK_HEIGHT * (1 - Math.abs(beads[j] - half) / half);
            assertEquals(expected, rows[0][j + 1], 1e-9, "initial y of str" + beads[j]);
        }
    }

    @Test
    void plotsArePngImagesOfTheAnnouncedSize() throws IOException {
        for (String f : new String[] {"figure4.png", "string.png", "string-shape.png"}) {
            byte[] bytes = Files.readAllBytes(out.resolve(f));
            assertEquals((byte) 0x89, bytes[0], f + " is not a PNG");
            assertEquals('P', bytes[1], f + " is not a PNG");
            BufferedImage img = ImageIO.read(out.resolve(f).toFile());
            assertNotNull(img, f + " does not decode");
            assertEquals(Demo.PLOT_WIDTH, img.getWidth(), f);
            assertEquals(Demo.PLOT_HEIGHT, img.getHeight(), f);
            int coloured = 0;
            for (int y = 0; y < img.getHeight(); y += 2) {
                for (int x = 0; x < img.getWidth(); x += 2) {
                    int rgb = img.getRGB(x, y);
                    int r = (rgb >> 16) & 0xFF, g = (rgb >> 8) & 0xFF, b = rgb & 0xFF;
                    if (Math.max(r, Math.max(g, b)) - Math.min(r, Math.min(g, b)) > 60) {
                        coloured++;
                    }
                }
            }
            assertTrue(coloured > 200, f + " shows almost no coloured curve pixels: " + coloured);
        }
    }

    @Test
    void measuredFundamentalMatchesTheDiscreteTheory() throws IOException {
        double[][] rows = readCsv(out.resolve("string.csv"), "t_s,str5_y_m,str13_y_m,str25_y_m");
        // Upward zero crossings of the middle bead, located by linear interpolation.
        double first = Double.NaN;
        double last = Double.NaN;
        int crossings = 0;
        for (int i = 1; i < rows.length; i++) {
            double a = rows[i - 1][3];
            double b = rows[i][3];
            if (a < 0 && b >= 0) {
                double t = rows[i - 1][0] + (rows[i][0] - rows[i - 1][0]) * a / (a - b);
                if (crossings == 0) {
                    first = t;
                }
                last = t;
                crossings++;
            }
        }
        assertTrue(crossings > 400, "crossings: " + crossings);
        double measured = (crossings - 1) / (last - first);

        // Lowest transverse mode of N beads between fixed ends, explicit scheme, per-step units:
        // sin(w/2) = sqrt(Kt/M) sin(pi / (2 (N + 1))), Kt = K/fs^2 (1 - l0/d).
        double fs = Demo.STRING_RATE;
        double kt = Demo.SPRING_K / (fs * fs) * (1 - Demo.SPRING_REST / Demo.BEAD_SPACING);
        double w = 2 * Math.asin(Math.sqrt(kt / Demo.BEAD_MASS)
                * Math.sin(Math.PI / (2 * (Demo.STRING_BEADS + 1))));
        double theory = w * fs / (2 * Math.PI);

        double cents = 1200 * Math.log(measured / theory) / Math.log(2);
        assertTrue(Math.abs(cents) <= PITCH_TOLERANCE_CENTS, String.format(
                "measured %.4f Hz, theory %.4f Hz: %+.3f cents (tolerance %.1f)", measured, theory, cents,
                PITCH_TOLERANCE_CENTS));
        assertEquals(theory, Demo.chainFundamental(Demo.STRING_BEADS, Demo.BEAD_MASS, Demo.SPRING_K / (fs * fs),
                Demo.SPRING_REST, Demo.BEAD_SPACING, fs), 1e-9 * theory, "Demo's own theory");
        assertTrue(stdout.contains(String.format(java.util.Locale.ROOT, "%.3f Hz", theory)), stdout);
    }

    @Test
    void failsWithAClearMessageWhenTheOutputFolderIsAFile() throws IOException {
        Path file = Files.writeString(tmp.resolve("not-a-folder"), "x");
        ByteArrayOutputStream e = new ByteArrayOutputStream();
        int code = Demo.run(new String[] {file.toString()}, new PrintStream(new ByteArrayOutputStream()),
                new PrintStream(e, true, StandardCharsets.UTF_8));
        assertEquals(1, code);
        String msg = e.toString(StandardCharsets.UTF_8);
        assertTrue(msg.startsWith("Demo failed:") && msg.contains("is a file"), msg);
    }

    @Test
    void rejectsExtraArgumentsWithUsage() {
        ByteArrayOutputStream e = new ByteArrayOutputStream();
        int code = Demo.run(new String[] {"a", "b"}, new PrintStream(new ByteArrayOutputStream()),
                new PrintStream(e, true, StandardCharsets.UTF_8));
        assertEquals(2, code);
        assertTrue(e.toString(StandardCharsets.UTF_8).startsWith("usage:"));
    }

    // ================================================================ the audio-haptic plucked string

    @Test
    void pluckWavHasTheScriptsLengthAndIsNotSilent() throws Exception {
        float[] x = readMonoWav(out.resolve("pluck.wav"));
        assertEquals(Math.round(PluckPath.DURATION * PluckScene.AUDIO_RATE), x.length, "samples in pluck.wav");
        double rmsBefore = rms(x, 0, (int) (0.5 * PluckScene.AUDIO_RATE));
        double rmsAfter = rms(x, (int) (3.0 * PluckScene.AUDIO_RATE), (int) (3.5 * PluckScene.AUDIO_RATE));
        // before the first pluck the string is at rest: silence; after the strum it rings
        assertTrue(rmsBefore < 1e-4, "silent before the first pluck: rms " + rmsBefore);
        assertTrue(rmsAfter > 0.01, "rings after the strum: rms " + rmsAfter);
        double peak = 0;
        for (float v : x) {
            peak = Math.max(peak, Math.abs(v));
        }
        assertTrue(peak < 1, "not clipped: peak " + peak);
    }

    @Test
    void pluckPitchAfterTheLastContactMatchesTheDiscreteTheory() throws Exception {
        float[] x = readMonoWav(out.resolve("pluck.wav"));
        double[][] rows = readCsv(out.resolve("pluck-telemetry.csv"), AudioHapticPluck.TELEMETRY_HEADER);
        // the last tick at which the model pushed the plectrum, and the audio steps done by then
        long released = -1;
        for (double[] r : rows) {
            if (r[7] != 0 || r[8] != 0) {
                released = (long) r[1];
            }
        }
        assertTrue(released > 0, "the plectrum touched the string");
        int rate = PluckScene.AUDIO_RATE;
        // one audio buffer may be computed ahead of the tick, plus 50 ms for the contact to fade
        int from = (int) (released + AudioHapticPluck.BUFFER + 0.05 * rate);
        int count = x.length - from;
        assertTrue(count > rate / 2, "at least half a second of free ringing: " + count + " samples");

        // N masses M, links K with length parameter l0 at spacing d: kt = K (1 - l0/d), explicit scheme
        double kt = PluckScene.STIFFNESS * (1 - PluckScene.REST / PluckScene.SPACING);
        Pitch spectrum = new Pitch(x, from, count, rate);
        double f1 = 0;
        for (int m = 1; m <= 3; m++) {
            double s = Math.sin(m * Math.PI / (2.0 * (PluckScene.MASSES + 1)));
            double theory = Math.acos(1 - 2 * kt / PluckScene.MASS * s * s) * rate / (2 * Math.PI);
            if (m == 1) {
                f1 = theory;
            }
            double measured = spectrum.peakHz(theory - 0.4 * f1, theory + 0.4 * f1);
            // the peak of a Hann-windowed tone is found to much better than half the resolution rate/count
            double toleranceCents = Demo.cents(theory + 0.5 * rate / (double) count, theory);
            double cents = Demo.cents(measured, theory);
            assertTrue(Math.abs(cents) <= toleranceCents, String.format(Locale.ROOT,
                    "partial %d: measured %.3f Hz, theory %.3f Hz: %+.2f cents (tolerance %.2f)", m, measured,
                    theory, cents, toleranceCents));
        }
        assertTrue(stdout.contains(String.format(Locale.ROOT, "theory %.3f Hz", f1)), stdout);
    }

    @Test
    void pluckForceIsFeltWhileTouchingAndOnlyThen() throws IOException {
        double[][] rows = readCsv(out.resolve("pluck-telemetry.csv"), AudioHapticPluck.TELEMETRY_HEADER);
        int contacts = 0;
        for (int i = 0; i < rows.length; i++) {
            double[] r = rows[i];
            double t = r[0];
            double fx = r[9];
            double fy = r[10];
            // what the loop sent is the avatar force through the gains, x mirrored (the CSV keeps 7 digits)
            assertEquals(-DeviceMapping.BETA * r[7], fx, 1e-12 + 2e-6 * Math.abs(fx), "force x at tick " + i);
            assertEquals(DeviceMapping.BETA * r[8], fy, 1e-12 + 2e-6 * Math.abs(fy), "force y at tick " + i);
            boolean touching = r[7] != 0 || r[8] != 0;
            if (touching) {
                contacts++;
                // the plectrum is near the string: within its sphere of action plus the string's sway
                assertTrue(Math.abs(r[6]) < PluckScene.SPHERE + 0.15, "force at y = " + r[6] + ", tick " + i);
            }
            // the glide before the first pluck and the ringing after the strum are far from the string
            if (t < 0.3 || t > PluckPath.STRUM_END + 0.1) {
                assertEquals(0.0, Math.hypot(fx, fy), 0.0, "no force far from the string, t = " + t);
            }
        }
        assertTrue(contacts > 50, "ticks in contact: " + contacts);
        // every time the plectrum crosses the string's rest line it pushes the string: force around it
        int crossings = 0;
        for (int i = 1; i < rows.length; i++) {
            double y0 = rows[i - 1][6];
            double y1 = rows[i][6];
            double xm = rows[i][5];
            if (Math.signum(y0) != Math.signum(y1) && y0 != 0 && xm > 0 && xm < PluckScene.length()) {
                crossings++;
                double strongest = 0;
                for (int j = Math.max(0, i - 30); j < Math.min(rows.length, i + 30); j++) {
                    strongest = Math.max(strongest, Math.hypot(rows[j][9], rows[j][10]));
                }
                assertTrue(strongest > 0.05, "force felt around the crossing at t = " + rows[i][0] + ": "
                        + strongest + " N");
            }
        }
        assertEquals(3, crossings, "down, up and the strum cross the string once each");
    }

    @Test
    void pluckRunsWithTheSchedulingASketchGetsAndSaysWhichItGot() throws IOException {
        // asked for by default, as a HapticSession does: granted ("real-time (SCHED_...") or refused with the reason
        String line = stdout.lines().filter(l -> l.contains("scheduling of the haptic loop: ")).findFirst()
                .orElseThrow(() -> new AssertionError("no scheduling line in:\n" + stdout));
        String policy = line.substring(line.indexOf(": ") + 2);
        assertTrue(policy.startsWith("real-time (SCHED_DEADLINE") || policy.startsWith("real-time (SCHED_FIFO")
                || policy.startsWith("normal priority (real-time refused: "), line);
        List<String> txt = Files.readAllLines(out.resolve("pluck-telemetry.txt"), StandardCharsets.UTF_8);
        assertTrue(txt.contains("scheduling " + policy.substring(0, policy.indexOf("; it ticked"))),
                String.join("\n", txt));
        // the hand's script starts once the loop ticks, however long the loop's set-up took: the first tick is
        // recorded at the script's time 0, not seconds into it
        double[][] rows = readCsv(out.resolve("pluck-telemetry.csv"), AudioHapticPluck.TELEMETRY_HEADER);
        assertTrue(rows[0][0] <= 0 && rows[0][0] > -0.5, "first tick at t = " + rows[0][0] + " s");
    }

    @Test
    void pluckTelemetryShowsTheLoopAtAboutOneKilohertz() throws IOException {
        double[][] rows = readCsv(out.resolve("pluck-telemetry.csv"), AudioHapticPluck.TELEMETRY_HEADER);
        double[] periods = new double[rows.length - 1];
        for (int i = 1; i < rows.length; i++) {
            periods[i - 1] = rows[i][0] - rows[i - 1][0];
        }
        java.util.Arrays.sort(periods);
        double median = periods[periods.length / 2];
        // the median tick is on time even on a loaded machine (missed ticks are counted, not asserted)
        assertEquals(1e-3, median, 1e-4, "median tick period");
        List<String> txt = Files.readAllLines(out.resolve("pluck-telemetry.txt"), StandardCharsets.UTF_8);
        assertTrue(txt.contains("nominal_hz 1000.0"), String.join("\n", txt));
        // the audio steps the ticks account for add up: each tick reports the steps since the previous one
        long spanned = 0;
        for (double[] r : rows) {
            spanned += (long) r[2];
        }
        long total = (long) rows[rows.length - 1][1];
        assertTrue(spanned <= total && spanned > total - 2 * AudioHapticPluck.BUFFER - PluckScene.AUDIO_RATE / 10,
                "steps in ticks " + spanned + " against " + total + " audio steps");
    }

    @Test
    void pluckPicturesAreImages() throws IOException {
        for (String f : new String[] {"pluck-scene.png", "pluck-path.png", "pluck-waveform.png"}) {
            BufferedImage img = ImageIO.read(out.resolve(f).toFile());
            assertNotNull(img, f + " does not decode");
            java.util.Set<Integer> colours = new java.util.HashSet<>();
            for (int y = 0; y < img.getHeight(); y += 3) {
                for (int x = 0; x < img.getWidth(); x += 3) {
                    colours.add(img.getRGB(x, y));
                }
            }
            assertTrue(colours.size() > 20, f + " has only " + colours.size() + " colours");
        }
        // the scene frame shows the orange-red plectrum disc drawn by the renderer
        BufferedImage scene = ImageIO.read(out.resolve("pluck-scene.png").toFile());
        int reddish = 0;
        for (int y = 0; y < scene.getHeight(); y++) {
            for (int x = 0; x < scene.getWidth(); x++) {
                int rgb = scene.getRGB(x, y);
                int r = (rgb >> 16) & 0xFF, g = (rgb >> 8) & 0xFF, b = rgb & 0xFF;
                if (r > 90 && r > 2 * g && r > 2 * b) {
                    reddish++;
                }
            }
        }
        assertTrue(reddish > 300, "the plectrum's disc is drawn: " + reddish + " red pixels");
    }

    private static float[] readMonoWav(Path wav) throws Exception {
        try (AudioInputStream in = AudioSystem.getAudioInputStream(wav.toFile())) {
            AudioFormat f = in.getFormat();
            assertEquals(1, f.getChannels());
            assertEquals(16, f.getSampleSizeInBits());
            assertEquals(PluckScene.AUDIO_RATE, f.getSampleRate(), 0);
            byte[] bytes = in.readAllBytes();
            ByteBuffer b = ByteBuffer.wrap(bytes).order(f.isBigEndian() ? ByteOrder.BIG_ENDIAN : ByteOrder.LITTLE_ENDIAN);
            float[] x = new float[bytes.length / 2];
            for (int i = 0; i < x.length; i++) {
                x[i] = b.getShort(2 * i) / 32767f;
            }
            return x;
        }
    }

    private static double rms(float[] x, int from, int to) {
        double s = 0;
        for (int i = from; i < to; i++) {
            s += x[i] * (double) x[i];
        }
        return Math.sqrt(s / (to - from));
    }

    /** Reads a CSV of numbers, checking its header and that every row has as many finite values. */
    private static double[][] readCsv(Path file, String header) throws IOException {
        List<String> lines = Files.readAllLines(file, StandardCharsets.UTF_8);
        assertEquals(header, lines.get(0), "header of " + file.getFileName());
        int columns = header.split(",").length;
        double[][] rows = new double[lines.size() - 1][];
        for (int i = 1; i < lines.size(); i++) {
            String[] cells = lines.get(i).split(",");
            assertEquals(columns, cells.length, file.getFileName() + " line " + (i + 1));
            rows[i - 1] = new double[columns];
            for (int c = 0; c < columns; c++) {
                double v = Double.parseDouble(cells[c]);
                assertTrue(Double.isFinite(v), file.getFileName() + " line " + (i + 1));
                rows[i - 1][c] = v;
            }
        }
        return rows;
    }

    private static void checkTimeColumn(double[][] rows, double rate) {
        for (int i = 0; i < rows.length; i++) {
            assertEquals(i / rate, rows[i][0], 1e-7, "time of row " + i);
        }
    }
}
