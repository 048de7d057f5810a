package tactus.dist;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import tactus.sketch.SketchHarness;

/**
 * The classroom lesson (docs/classroom.md) and its solutions (examples/Lesson/, which ExamplesTest runs like every
 * example) stay together: 5 to 8 steps, each naming its solution sketch; every line of code a step shows is a line
 * of that sketch, so the page cannot drift from code that runs; every lesson sketch is a step's solution; and the
 * first step's code is a whole sketch that compiles against the library.
 */
class ClassroomPageTest {
    private static final Pattern STEP = Pattern.compile("(?m)^## Step (\\d+)\\. ");
    private static final Pattern SOLUTION = Pattern.compile("Solution: `(\\w+)`");
    private static final Pattern JAVA_BLOCK = Pattern.compile("(?s)```java\\n(.*?)```");

    @TempDir
    Path tmp;

    private static Path root() {
        String examples = System.getProperty("tactus.dist.examples");
        assertTrue(examples != null, "run through 'gradle test', which sets tactus.dist.examples");
        return Path.of(examples).getParent();
    }

    /** The text of each step, by step number, in page order. */
    private static Map<Integer, String> steps() throws IOException {
        String page = Files.readString(root().resolve("docs/classroom.md"), StandardCharsets.UTF_8);
        Map<Integer, String> steps = new LinkedHashMap<>();
        Matcher m = STEP.matcher(page);
        List<int[]> starts = new ArrayList<>();
        while (m.find()) {
            starts.add(new int[] {m.start(), Integer.parseInt(m.group(1))});
        }
        for (int i = 0; i < starts.size(); i++) {
            int end = page.indexOf("\n## ", starts.get(i)[0] + 1);
            steps.put(starts.get(i)[1], page.substring(starts.get(i)[0], end < 0 ? page.length() : end));
        }
        return steps;
    }

    private static String withoutComment(String line) {
        int c = line.indexOf("//");
        return (c < 0 ? line : line.substring(0, c)).trim();
    }

    @Test
    void everyStepShowsLinesOfItsSolutionSketch() throws IOException {
        Map<Integer, String> steps = steps();
        assertTrue(steps.size() >= 5 && steps.size() <= 8, "the lesson has 5 to 8 steps, not " + steps.size());
        int expectedNumber = 1;
        List<String> missing = new ArrayList<>();
        for (Map.Entry<Integer, String> step : steps.entrySet()) {
            assertEquals(expectedNumber++, step.getKey().intValue(), "steps are numbered 1, 2, ... in order");
            Matcher s = SOLUTION.matcher(step.getValue());
            assertTrue(s.find(), "step " + step.getKey() + " names no solution sketch");
            String name = s.group(1);
            assertTrue(name.startsWith(String.format("Lesson%02d_", step.getKey())),
                    "step " + step.getKey() + "'s solution should be Lesson" + String.format("%02d", step.getKey())
                    + "_...: " + name);
            Path sketch = root().resolve("examples/Lesson/" + name + "/" + name + ".pde");
            assertTrue(Files.isRegularFile(sketch), "step " + step.getKey() + ": no " + sketch);
            Set<String> lines = new HashSet<>();
            for (String l : Files.readAllLines(sketch, StandardCharsets.UTF_8)) {
                lines.add(withoutComment(l));
            }
            Matcher block = JAVA_BLOCK.matcher(step.getValue());
            int shown = 0;
            while (block.find()) {
                for (String l : block.group(1).split("\n")) {
                    String code = withoutComment(l);
                    if (code.isEmpty() || code.startsWith("...")) {
                        continue;
                    }
                    shown++;
                    if (!lines.contains(code)) {
                        missing.add("step " + step.getKey() + " shows a line that " + name + " does not have: " + code);
                    }
                }
            }
            assertTrue(shown >= 3, "step " + step.getKey() + " shows no code");
        }
        assertTrue(missing.isEmpty(), String.join("\n", missing));
    }

    @Test
    void everyLessonSketchIsTheSolutionOfAStep() throws IOException {
        Set<String> named = new TreeSet<>();
        for (String step : steps().values()) {
            Matcher s = SOLUTION.matcher(step);
            while (s.find()) {
                named.add(s.group(1));
            }
        }
        Set<String> sketches = new TreeSet<>();
        for (Path dir : SketchHarness.findSketches(root().resolve("examples/Lesson"))) {
            sketches.add(dir.getFileName().toString());
        }
        assertEquals(sketches, named, "the sketches of examples/Lesson and the solutions the page names");
    }

    @Test
    void theFirstStepIsAWholeSketchThatCompiles() throws Exception {
        Matcher block = JAVA_BLOCK.matcher(steps().get(1));
        assertTrue(block.find(), "step 1 shows no code");
        SketchHarness.JavaSketch sketch = SketchHarness.preprocess("ClassroomStep1", block.group(1));
        Path classes = SketchHarness.compile(sketch, tmp, SketchHarness.sketchClasspath());
        assertTrue(Files.isRegularFile(classes.resolve("ClassroomStep1.class")));
    }
}
