package tactus.audio;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import tactus.sketch.SketchHarness;

/**
 * The "done when": a sketch with a PhyUGen subclass written the paper's way (its own model in the
 * constructor, its own uGenerate stepping under a sketch-level lock, a 1 kHz thread and draw() using the same lock,
 * {@code minim.getLineOut()} as is) runs with Tactus's imports, through the real Processing preprocessor, under Xvfb
 * with no sound card: the audio thread stepped the model in real time, the string sounded, and the haptic thread
 * read forces, with nobody stuck behind anybody.
 */
class RealtimePaperSketchTest {
    private static final Pattern REPORT = Pattern.compile(
            "paper-sketch: steps=(\\d+) peak=([0-9.eE-]+) hapticReads=(\\d+) forceSum=([0-9.eE-]+)");

    @Test
    void aPaperStylePhyUGenSketchRunsWithTheImportsAlone() {
        Path dir = Paths.get("test", "tactus", "audio", "sketches", "PaperStylePhyUGen");
        String classpath = SketchHarness.sketchClasspath();
        SketchHarness.requireXvfb();
        SketchHarness.JavaSketch sketch = SketchHarness.preprocess(dir);
        Path work = SketchHarness.workDir(sketch.className);
        Path classes = SketchHarness.compile(sketch, work, classpath);
        SketchHarness.Run run = SketchHarness.run(sketch.className, classes, classpath, 160, work.resolve("frame.png"),
                90);
        SketchHarness.check(run, 160);
        Matcher m = REPORT.matcher(run.stdout);
        assertTrue(m.find(), "the sketch reports what it heard\n" + run.logs());
        long steps = Long.parseLong(m.group(1));
        double peak = Double.parseDouble(m.group(2));
        long reads = Long.parseLong(m.group(3));
        double force = Double.parseDouble(m.group(4));
        System.out.println(m.group() + " (" + run.seconds + " s with JVM and Xvfb start)");
        // 150 frames at up to 60 fps is at least 2.5 s: the audio thread ran (loosely, so that load cannot fail it)
        assertTrue(steps > 22050, "the audio thread stepped the model: " + steps + " steps\n" + run.logs());
        assertTrue(peak > 1e-4, "the string sounded: peak " + peak);
        assertTrue(reads > 100 && force > 0, "the haptic thread read forces: " + reads + " reads, sum " + force);
    }
}
