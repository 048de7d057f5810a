package tactus.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

import javax.imageio.ImageIO;

import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The renderer in a real P3D (OpenGL) sketch: {@link P3DSketch} (Processing's default camera) and
 * {@link P3DCameraSketch} (the orbit camera, speed colours, the force arrow) run in a child JVM under
 * {@code xvfb-run} (Mesa's software OpenGL) and save a frame, whose pixels are checked here. Skipped only when {@code xvfb-run}
 * is not installed. With Processing's default camera, a point at depth z is drawn at
 * {@code centre + p.xy × d / (d - z)}, where {@code d = (height / 2) / tan(π / 6)} is the eye distance; at z = 0
 * that is the 2D mapping.
 */
class P3DRenderTest {
    @TempDir
    Path tmp;

    private static boolean onPath(String program) {
        for (String dir : System.getenv().getOrDefault("PATH", "").split(File.pathSeparator)) {
            if (Files.isExecutable(Path.of(dir, program))) {
                return true;
            }
        }
        return false;
    }

    private static int channelDistance(int a, int b) {
        int d = 0;
        for (int s = 0; s < 24; s += 8) {
            d = Math.max(d, Math.abs(((a >> s) & 0xFF) - ((b >> s) & 0xFF)));
        }
        return d;
    }

    private static void assertColour(int expected, BufferedImage img, double x, double y, String what) {
        int px = (int) Math.floor(P3DSketch.SIZE / 2.0 + x);
        int py = (int) Math.floor(P3DSketch.SIZE / 2.0 + y);
        int got = img.getRGB(px, py) | 0xFF000000;
        assertTrue(channelDistance(expected, got) <= 8, what + " at (" + x + ", " + y + "): expected "
                + Integer.toHexString(expected) + ", got " + Integer.toHexString(got));
    }

    /** Runs a sketch class in a child JVM under xvfb-run and returns the frame it saved. */
    private BufferedImage runSketch(Class<?> sketch) throws Exception {
        Assumptions.assumeTrue(onPath("xvfb-run"), "xvfb-run is not installed");
        Path png = tmp.resolve(sketch.getSimpleName() + ".png");
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        List<String> cmd = new ArrayList<>(List.of("env", "--default-signal=USR1", "xvfb-run", "-a", "-s", "-screen 0 640x480x24", java,
                "-cp", System.getProperty("java.class.path"), sketch.getName(), png.toString()));
        Path log = tmp.resolve(sketch.getSimpleName() + ".log");
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).redirectOutput(log.toFile()).start();
        boolean done = false;
        try {
            done = p.waitFor(120, TimeUnit.SECONDS);
        } finally {
            if (!done) {
                // also when JUnit's timeout interrupted the wait: xvfb-run, Xvfb and the sketch JVM all go
                p.descendants().forEach(ProcessHandle::destroyForcibly);
                p.destroyForcibly();
            }
        }
        String output = Files.exists(log) ? Files.readString(log, StandardCharsets.UTF_8) : "";
        assertTrue(done, "the P3D sketch did not finish in 120 s:\n" + output);
        assertTrue(Files.exists(png), "no frame saved; exit " + p.exitValue() + ":\n" + output);
        return ImageIO.read(png.toFile());
    }

    @Test
    void aP3DSketchDrawsSpheresAndLinesWhereTheCameraMapsThem() throws Exception {
        BufferedImage img = runSketch(P3DSketch.class);
        assertEquals(P3DSketch.SIZE, img.getWidth());

        int white = 0xFFFFFFFF;
        int mass3d = 0xFFB46400;
        int blue = 0xFF0000FF;
        int springDamper = 0xFF1EFAFA;
        // spheres at z = 0, unlit: their fill colour; radius 10
        assertColour(mass3d, img, -60, -40, "Mass3D sphere");
        assertColour(mass3d, img, -60 + 7, -40, "Mass3D sphere, inside radius 10");
        assertColour(white, img, -60 - 13, -40, "outside the Mass3D sphere");
        assertColour(blue, img, 60, -40, "restyled Ground3D sphere");
        // the spring-damper between them, 4 pixels wide
        for (int x = -40; x <= 40; x += 10) {
            assertColour(springDamper, img, x, -40, "spring-damper line");
        }
        assertColour(white, img, 0, -40 + 6, "beside the line");
        // the ground at z = 50, drawn in perspective: further out and larger than at z = 0
        double d = (P3DSketch.SIZE / 2.0) / Math.tan(Math.PI / 6);
        double k = d / (d - 50);
        assertColour(blue, img, 60 * k, 40 * k, "sphere at z = 50, projected");
        assertColour(white, img, 60 * k + 10 * k + 3, 40 * k, "outside the projected sphere");
        assertColour(blue, img, 60 * k + 10 * k - 3, 40 * k, "inside the projected sphere, radius 10 k");
    }

    /**
     * The orbit camera turned 90° about the vertical (eye on +x): world -z is screen right, at the target's depth
     * one pixel per unit. The still mass at z = -50 is 50 px right of the centre in the scale's first colour, the
     * fast one (10 units/s) 50 px left in its last; the avatar's force arrow, 60 units along -z, runs right from it.
     */
    @Test
    void theOrbitCameraColoursAndTheForceArrowInP3D() throws Exception {
        BufferedImage img = runSketch(P3DCameraSketch.class);
        assertEquals(P3DCameraSketch.SIZE, img.getWidth());
        int white = 0xFFFFFFFF;
        ColorScale scale = ColorScale.heat(0, 10);
        assertColour(scale.colorAt(0), img, 50, 0, "still mass, seen from the side");
        assertColour(scale.colorAt(10), img, -50, 0, "fast mass, seen from the side");
        assertColour(white, img, 0, 0, "nothing at the centre");
        int red = 0xFFFF3232;   // the avatar
        assertColour(red, img, 0, 60, "the avatar");
        int blue = 0xFF0000FF;
        for (int x = 20; x <= 40; x += 10) {
            assertColour(blue, img, x, 60, "the force arrow");
        }
        assertColour(white, img, 50, 60 - 12, "above the arrow's head");
    }
}
