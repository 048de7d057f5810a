package tactus.sketch;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.Locale;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.jupiter.api.Test;

/**
 * Issue 17's first "Done when": sketches of our own, written in the style of the paper's example sketches with the
 * mistakes the paper's engine silently ignored (loops that link a module to itself, subsets named but never created,
 * MIDI controllers on a link name, a TopoGenerator subset that holds its boundary grounds, the mass of a ground),
 * run for 10 s (600 frames at their 60 frames per second) as the Processing editor runs them (its preprocessor,
 * javac, a child JVM under Xvfb: {@link SketchHarness}), then play every key they react to
 * ({@link ExamplesTest#inputScript}). Each passes when it runs without an exception and prints exactly one warning
 * per kind of problem it meets, however many times it meets it (the draw() loops meet some 600 times).
 * The sketches are in {@code test/tactus/sketch/forgiven/}.
 */
class ForgivenSketchesTest {
    /** 10 s at the sketches' 60 frames per second. */
    static final int FRAMES = 600;
    /** Start of the JVM and of Xvfb, 600 frames of a small JAVA2D sketch and its keys, on a loaded 2-core machine. */
    static final double TIMEOUT_SECONDS = 150;
    /** The end of every warning of {@code tactus.PaperLeniency}. */
    static final String WARNING = "as the paper's engine did (printed once per model for this kind of problem";

    static Path sketches() {
        return Paths.get("test", "tactus", "sketch", "forgiven");
    }

    @Test
    void loopsThatLinkAModuleToItselfAndSubsetsNeverCreated() throws IOException {
        String err = run("ForgivenLoops");
        assertWarnedOnce(err, "addBubble3D(\"bub0\"): cannot link mass \"gnd\" to itself");
        assertWarnedOnce(err, "controller(\"col\"): no such subset");
        assertEquals(2, count(err, WARNING), err);
    }

    @Test
    void aTopoGeneratorSubsetWithItsGroundsAndTheMassOfAGround() throws IOException {
        String err = run("ForgivenBeam");
        assertWarnedOnce(err, "getMatMassAt(\"mass_0_0_0\"): a Ground3D has no mass parameter");
        assertEquals(1, count(err, WARNING), err);
    }

    /** Runs one sketch with its keys; fails on an exception; returns its standard error. */
    private static String run(String name) throws IOException {
        Path dir = sketches().resolve(name);
        String classpath = SketchHarness.sketchClasspath();
        SketchHarness.requireXvfb();
        SketchHarness.JavaSketch sketch = SketchHarness.preprocess(dir);
        Path work = SketchHarness.workDir(sketch.className);
        Path classes = SketchHarness.compile(sketch, work, classpath);
        String source = new String(Files.readAllBytes(dir.resolve(name + ".pde")), StandardCharsets.UTF_8);
        String input = ExamplesTest.inputScript(source);
        assertTrue(!input.isEmpty(), name + " reacts to keys");
        SketchHarness.Run run = SketchHarness.run(sketch.className, classes, classpath, FRAMES,
                work.resolve("frame.png"), TIMEOUT_SECONDS, dir, Map.of(SketchRunner.INPUT_PROPERTY, input));
        SketchHarness.check(run, FRAMES);
        int expectedEvents = SketchRunner.inputEvents(input, 100, 100).size();
        assertTrue(run.stdout.contains(SketchRunner.INPUT_MARKER + expectedEvents),
                name + " did not play its " + expectedEvents + " input events (" + input + ")\n" + run.logs());
        System.out.printf(Locale.ROOT, "%s: %d frames and %d input events in %.1f s, %d warning(s)%n", name,
                run.frames, expectedEvents, run.seconds, count(run.stderr, WARNING));
        return run.stderr;
    }

    private static void assertWarnedOnce(String err, String text) {
        assertEquals(1, count(err, text), "expected exactly once: " + text + "\n--- stderr ---\n" + err);
    }

    private static int count(String s, String text) {
        Matcher m = Pattern.compile(Pattern.quote(text)).matcher(s);
        int n = 0;
        while (m.find()) {
            n++;
        }
        return n;
    }
}
