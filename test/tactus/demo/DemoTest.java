package tactus.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import javax.imageio.ImageIO;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Runs the headless demo once into a temporary folder (about 2 s) and checks what it wrote: the
 * CSV columns and row counts, the PNG sizes, and the string's pitch, which this test measures
 * again from string.csv and compares with the discrete-scheme theory that it computes itself.
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
        for (String f : new String[] {"figure4.csv", "figure4.png", "string.csv", "string.png", "string-shape.png"}) {
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
