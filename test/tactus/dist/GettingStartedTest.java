package tactus.dist;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import tactus.sketch.SketchHarness;

/**
 * The first sketch of docs/getting-started.md goes through the editor's own preprocessor and compiles against
 * the library, so the page cannot drift from the API.
 */
class GettingStartedTest {
    @TempDir
    Path tmp;

    @Test
    void theFirstSketchOfTheGettingStartedPageCompiles() throws Exception {
        String examples = System.getProperty("tactus.dist.examples");
        assertTrue(examples != null, "run through 'gradle test'");
        Path page = Path.of(examples).getParent().resolve("docs/getting-started.md");
        String text = Files.readString(page, StandardCharsets.UTF_8);
        Matcher m = Pattern.compile("(?s)```java\\n(.*?)```").matcher(text);
        assertTrue(m.find(), "no java block in " + page);
        String code = m.group(1);
        assertTrue(code.contains("new ModelRenderer(this)") && code.contains("new OrbitCamera(this)"),
                "the first block is the first sketch");
        SketchHarness.JavaSketch sketch = SketchHarness.preprocess("FirstSketch", code);
        Path classes = SketchHarness.compile(sketch, tmp, SketchHarness.sketchClasspath());
        assertTrue(Files.isRegularFile(classes.resolve("FirstSketch.class")));
    }
}
