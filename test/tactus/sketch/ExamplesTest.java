package tactus.sketch;

import static org.junit.jupiter.api.Assertions.assertFalse;

import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.List;
import java.util.Locale;
import java.util.stream.Stream;

import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.TestFactory;

/**
 * Runs every example sketch under {@code examples/} (found at any depth, {@code examples/<Group>/<Sketch>/
 * <Sketch>.pde}) as the Processing editor would: the editor's preprocessor, {@code javac} against the built
 * library, then {@value #FRAMES} frames under Xvfb. Each sketch is one test; it passes when the sketch exits
 * cleanly with nothing like an exception on standard error, has drawn all its frames, and its last frame (saved
 * as {@code build/sketches/<Sketch>/frame.png}) is not blank.
 */
class ExamplesTest {
    /** Frames each example draws: three seconds at 60 frames per second. */
    static final int FRAMES = 180;
    /** The longest one example may run, JVM start and Xvfb included, in seconds. */
    static final double TIMEOUT_SECONDS = 60;

    static Path examplesRoot() {
        return Paths.get(System.getProperty("tactus.sketch.examples", "examples"));
    }

    @TestFactory
    Stream<DynamicTest> everyExampleRunsLikeInTheEditor() {
        List<Path> sketches = SketchHarness.findSketches(examplesRoot());
        assertFalse(sketches.isEmpty(), "no sketch found under " + examplesRoot().toAbsolutePath());
        return sketches.stream().map(dir -> DynamicTest.dynamicTest(
                examplesRoot().relativize(dir).toString(), dir.toUri(), () -> runExample(dir)));
    }

    private static void runExample(Path dir) {
        String classpath = SketchHarness.sketchClasspath();
        SketchHarness.requireXvfb();
        SketchHarness.JavaSketch sketch = SketchHarness.preprocess(dir);
        Path work = SketchHarness.workDir(sketch.className);
        Path classes = SketchHarness.compile(sketch, work, classpath);
        SketchHarness.Run run = SketchHarness.run(sketch.className, classes, classpath, FRAMES,
                work.resolve("frame.png"), TIMEOUT_SECONDS);
        SketchHarness.check(run, FRAMES);
        System.out.printf(Locale.ROOT, "%s: %d frames in %.1f s (JVM and Xvfb start included), frame %s%n",
                sketch.className, run.frames, run.seconds, work.resolve("frame.png"));
    }
}
