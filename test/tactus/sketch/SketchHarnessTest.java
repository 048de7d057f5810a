package tactus.sketch;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Checks the sketch harness itself: Processing's preprocessor works without its missing dependency
 * {@code org.processing:utils}, sketches are found at any depth, and each kind of failure (a syntax error, a
 * compile error, an exception while drawing, a blank frame) is caught and explained.
 */
class SketchHarnessTest {

    @TempDir
    Path tmp;

    @Test
    void thePreprocessorRunsWithoutProcessingUtils() {
        assertThrows(ClassNotFoundException.class, () -> Class.forName("processing.utils.SketchException"),
                "org.processing:utils is not on Maven Central and must not be needed");
        String pde = "int n = 3;\n"
                + "void setup() {\n"
                + "  size(320, 240);\n"
                + "  color c = #FF8000;\n"
                + "  float f = 1.5;\n"
                + "}\n"
                + "void draw() { background(n); }\n";
        SketchHarness.JavaSketch java = SketchHarness.preprocess("Tiny", pde);
        assertEquals("Tiny", java.className);
        String src = java.source;
        // What the editor's preprocessor does: a PApplet subclass, size() moved into settings(), colour
        // literals and float literals rewritten, and a main method.
        assertTrue(src.contains("public class Tiny extends PApplet"), src);
        assertTrue(src.contains("public void settings()") && src.contains("size(320, 240)"), src);
        assertTrue(src.contains("0xFFFF8000"), src);
        assertTrue(src.contains("1.5f"), src);
        assertTrue(src.contains("static public void main("), src);
        assertTrue(src.contains("import processing.core.*;"), src);
    }

    @Test
    void aSyntaxErrorIsReportedWithItsLine() {
        AssertionError e = assertThrows(AssertionError.class,
                () -> SketchHarness.preprocess("Broken", "void setup() {\n  int x = ;\n}\n"));
        assertTrue(e.getMessage().contains("Broken") && e.getMessage().contains("line 2"), e.getMessage());
    }

    @Test
    void aCompileErrorIsReportedWithTheGeneratedLine() {
        SketchHarness.JavaSketch java = SketchHarness.preprocess("Undefined",
                "void setup() {\n  noSuchFunction(42);\n}\n");
        AssertionError e = assertThrows(AssertionError.class,
                () -> SketchHarness.compile(java, tmp, SketchHarness.sketchClasspath()));
        assertTrue(e.getMessage().contains("noSuchFunction(42)"), e.getMessage());
    }

    @Test
    void sketchesAreFoundAtAnyDepthByTheirMainTab() throws Exception {
        for (String d : new String[] {"Basics/Hello", "Haptics/Deep/Chain", "NotASketch"}) {
            Files.createDirectories(tmp.resolve(d));
        }
        Files.write(tmp.resolve("Basics/Hello/Hello.pde"), new byte[0]);
        Files.write(tmp.resolve("Haptics/Deep/Chain/Chain.pde"), new byte[0]);
        Files.write(tmp.resolve("NotASketch/Other.pde"), new byte[0]);
        List<Path> found = SketchHarness.findSketches(tmp);
        assertEquals(List.of(tmp.resolve("Basics/Hello"), tmp.resolve("Haptics/Deep/Chain")), found);
    }

    @Test
    void aMissingXvfbIsAFailureThatSaysWhatToInstall() throws Exception {
        AssertionError e = assertThrows(AssertionError.class, () -> SketchHarness.requireXvfb(tmp.toString()));
        assertTrue(e.getMessage().contains("xvfb-run") && e.getMessage().contains("apt-get install"), e.getMessage());
        // xvfb-run alone is not enough: it needs xauth.
        Path fake = tmp.resolve("xvfb-run");
        Files.write(fake, "#!/bin/sh\n".getBytes(java.nio.charset.StandardCharsets.US_ASCII));
        assertTrue(fake.toFile().setExecutable(true));
        e = assertThrows(AssertionError.class, () -> SketchHarness.requireXvfb(tmp.toString()));
        assertTrue(e.getMessage().contains("xauth"), e.getMessage());
        // This machine (and CI) has both.
        assertTrue(Files.isExecutable(SketchHarness.requireXvfb()));
    }

    @Test
    void blankImagesHaveNoSpreadAndDrawnOnesDo() {
        BufferedImage img = new BufferedImage(50, 40, BufferedImage.TYPE_INT_RGB);
        assertEquals(0.0, SketchHarness.luminanceSpread(img), 1e-9);
        // One white pixel in n black ones: mean 255/n, spread 255 sqrt((n-1))/n.
        img.setRGB(3, 4, 0xFFFFFF);
        int n = 50 * 40;
        assertEquals(255 * Math.sqrt(n - 1) / n, SketchHarness.luminanceSpread(img), 1e-6);
    }

    /** One child run: a sketch that throws on its fifth frame must fail the check with its stack trace. */
    @Test
    void anExceptionWhileDrawingFailsTheRunWithTheSketchsStackTrace() {
        SketchHarness.JavaSketch java = SketchHarness.preprocess("Thrower",
                "void setup() { size(200, 100); }\n"
                + "void draw() {\n"
                + "  background(255); line(0, 0, width, height);\n"
                + "  if (frameCount == 5) throw new IllegalStateException(\"boom at frame \" + frameCount);\n"
                + "}\n");
        String cp = SketchHarness.sketchClasspath();
        Path classes = SketchHarness.compile(java, tmp, cp);
        SketchHarness.Run run = SketchHarness.run(java.className, classes, cp, 30, tmp.resolve("frame.png"), 60);
        assertEquals(SketchRunner.EXCEPTION_STATUS, run.exitCode, run.logs());
        AssertionError e = assertThrows(AssertionError.class, () -> SketchHarness.check(run, 30));
        assertTrue(e.getMessage().contains("boom at frame 5") && e.getMessage().contains("Thrower.draw"),
                e.getMessage());
    }

    /** One child run: an exception in setup() (before the runner could replace Processing's handler) also fails. */
    @Test
    void anExceptionInSetupFailsTheRun() {
        SketchHarness.JavaSketch java = SketchHarness.preprocess("SetupThrower",
                "void setup() { size(200, 100); int[] a = new int[2]; a[5] = 1; }\nvoid draw() { }\n");
        String cp = SketchHarness.sketchClasspath();
        Path classes = SketchHarness.compile(java, tmp, cp);
        SketchHarness.Run run = SketchHarness.run(java.className, classes, cp, 30, tmp.resolve("frame.png"), 60);
        assertEquals(SketchRunner.EXCEPTION_STATUS, run.exitCode, run.logs());
        AssertionError e = assertThrows(AssertionError.class, () -> SketchHarness.check(run, 30));
        assertTrue(e.getMessage().contains("ArrayIndexOutOfBoundsException")
                && e.getMessage().contains("SetupThrower.setup"), e.getMessage());
    }

    /**
     * One child run: the sketch folder given to the runner is the sketch's {@code sketchPath()}, so its
     * {@code data/} files load as in the editor; system properties reach the sketch; the frame at half time is
     * saved beside the last one.
     */
    @Test
    void theSketchFolderPropertiesAndMidFrameReachTheRun() throws Exception {
        Path folder = tmp.resolve("sketch");
        Files.createDirectories(folder.resolve("data"));
        Files.write(folder.resolve("data/greeting.txt"), "hello from data".getBytes(StandardCharsets.UTF_8));
        SketchHarness.JavaSketch sketch = SketchHarness.preprocess("Folder",
                "void setup() {\n"
                + "  size(120, 80);\n"
                + "  println(\"read: \" + loadStrings(\"greeting.txt\")[0]);\n"
                + "  println(\"property: \" + System.getProperty(\"tactus.test.word\"));\n"
                + "  saveStrings(\"written.txt\", new String[] {\"ok\"});\n"
                + "}\n"
                + "void draw() { background(frameCount < 6 ? 0 : 255); }\n");
        String cp = SketchHarness.sketchClasspath();
        Path classes = SketchHarness.compile(sketch, tmp.resolve("work"), cp);
        Path png = tmp.resolve("out/frame.png");
        SketchHarness.Run run = SketchHarness.run(sketch.className, classes, cp, 10, png, 60, folder,
                java.util.Map.of("tactus.test.word", "tactile"));
        assertEquals(0, run.exitCode, run.logs());
        assertTrue(run.stdout.contains("read: hello from data"), run.logs());
        assertTrue(run.stdout.contains("property: tactile"), run.logs());
        assertTrue(Files.isRegularFile(folder.resolve("written.txt")), "saveStrings writes into the sketch folder");
        // Frame 5 is black, frame 10 white.
        java.awt.image.BufferedImage mid = javax.imageio.ImageIO.read(SketchHarness.midFramePath(png).toFile());
        assertEquals(0x000000, mid.getRGB(60, 40) & 0xFFFFFF);
        assertEquals(0xFFFFFF, run.image.getRGB(60, 40) & 0xFFFFFF);
        assertEquals(tmp.resolve("out/frame-mid.png"), SketchHarness.midFramePath(png));
    }

    /** One child run: a sketch that only clears the screen reaches its frames but fails as blank. */
    @Test
    void aBlankFrameFailsTheRun() {
        SketchHarness.JavaSketch java = SketchHarness.preprocess("Blank",
                "void setup() { size(200, 100); }\nvoid draw() { background(40, 80, 120); }\n");
        String cp = SketchHarness.sketchClasspath();
        Path classes = SketchHarness.compile(java, tmp, cp);
        SketchHarness.Run run = SketchHarness.run(java.className, classes, cp, 10, tmp.resolve("frame.png"), 60);
        assertEquals(0, run.exitCode, run.logs());
        assertEquals(10, run.frames, run.logs());
        assertEquals(200, run.image.getWidth());
        assertEquals(100, run.image.getHeight());
        AssertionError e = assertThrows(AssertionError.class, () -> SketchHarness.check(run, 10));
        assertTrue(e.getMessage().contains("blank"), e.getMessage());
    }

    @Test
    void onlyAnOpenGlSurfaceThatNeverStartedCountsAsStarvedAndIsRunAgain() {
        String starved = "java.lang.RuntimeException: Waited 5000ms for: <9322f69, 7f5d03f>[count 2, qsz 0, owner "
                + "<main-FPSAWTAnimator#00-Timer0>] - <main-FPSAWTAnimator#00-Timer0-FPSAWTAnimator#00-Timer1>\n"
                + "\tat processing.opengl.PSurfaceJOGL.lambda$initAnimator$2(PSurfaceJOGL.java:409)\n";
        assertTrue(ExamplesTest.joglStartStarved(new SketchHarness.Run("S", 3, 3, -1, null, "", starved, 15)));
        assertTrue(!ExamplesTest.joglStartStarved(new SketchHarness.Run("S", 3, 3, 120, null, "", starved, 15)),
                "a sketch that drew frames before the wait is not retried");
        assertTrue(!ExamplesTest.joglStartStarved(new SketchHarness.Run("S", 3, 3, -1, null, "",
                "java.lang.NullPointerException\n\tat S.setup(S.java:12)\n", 15)), "any other failure is not retried");
    }
}
