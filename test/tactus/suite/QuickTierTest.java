package tactus.suite;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * The fast tier ({@code gradle quickTest}, the list in gradle/quicktest.gradle) covers every test package, and every
 * class it names exists there: a package added or a class moved without the list fails here, not silently.
 */
class QuickTierTest {
    private static final Pattern ENTRY = Pattern.compile("'(tactus[a-z.]*)'\\s*:\\s*\\[([^\\]]*)\\]");
    private static final Pattern NAME = Pattern.compile("'([A-Za-z0-9]+)'");

    private static Map<String, List<String>> listed() throws IOException {
        String text = new String(Files.readAllBytes(Path.of("gradle", "quicktest.gradle")), StandardCharsets.UTF_8);
        Map<String, List<String>> m = new TreeMap<>();
        Matcher e = ENTRY.matcher(text);
        while (e.find()) {
            List<String> classes = new ArrayList<>();
            Matcher n = NAME.matcher(e.group(2));
            while (n.find()) {
                classes.add(n.group(1));
            }
            m.put(e.group(1), classes);
        }
        return m;
    }

    @Test
    void everyTestPackageIsListedAndEveryListedClassExists() throws IOException {
        Map<String, List<String>> listed = listed();
        assertTrue(listed.size() >= 20, "read the list: " + listed.keySet());
        List<String> problems = new ArrayList<>();
        try (Stream<Path> dirs = Files.walk(Path.of("test", "tactus"))) {
            for (Path d : (Iterable<Path>) dirs.filter(Files::isDirectory)::iterator) {
                boolean hasTests;
                try (Stream<Path> files = Files.list(d)) {
                    hasTests = files.anyMatch(f -> f.getFileName().toString().endsWith("Test.java"));
                }
                String pkg = Path.of("test").relativize(d).toString().replace('/', '.').replace('\\', '.');
                if (hasTests && !listed.containsKey(pkg)) {
                    problems.add("package " + pkg + " has tests but no entry");
                }
            }
        }
        for (Map.Entry<String, List<String>> e : listed.entrySet()) {
            Path dir = Path.of("test", e.getKey().replace('.', '/'));
            for (String c : e.getValue()) {
                if (!Files.isRegularFile(dir.resolve(c + ".java"))) {
                    problems.add(e.getKey() + "." + c + " is listed but is not in " + dir);
                }
            }
        }
        assertTrue(problems.isEmpty(), "gradle/quicktest.gradle: " + String.join("; ", problems));
    }
}
