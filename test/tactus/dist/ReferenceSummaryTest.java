package tactus.dist;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;

/**
 * Keeps the public reference whole: every public or protected type, constructor and method outside {@code tactus.internal} and
 * {@code tactus.engine} has a Javadoc whose first sentence is text (a Javadoc that opens with a block tag such as
 * {@code @return} or {@code @param} gives an empty summary in the reference). A method marked {@code @Override}
 * inherits its documentation and is exempt.
 */
class ReferenceSummaryTest {

    /** A public declaration line: a type, a constructor or a method (fields are not in the summary tables). */
    private static final Pattern PUBLIC_DECLARATION = Pattern.compile(
            "^\\s*(?:public|protected)\\s+(?:(?:static|final|abstract|synchronized|default|sealed)\\s+)*"
                    + "(?:(?:class|interface|enum|record)\\s+\\w+|[^;=()]*\\()");

    @Test
    void everyPublicMemberOutsideTheMachineryHasAFirstSentence() throws IOException {
        List<Path> files = referenceSources();
        assertTrue(files.size() > 100, "expected the library's sources under src/tactus, found " + files.size());
        List<String> problems = new ArrayList<>();
        for (Path f : files) {
            problems.addAll(problemsIn(f.toString(), Files.readAllLines(f, StandardCharsets.UTF_8)));
        }
        assertEquals(List.of(), problems, problems.size() + " public declarations have no summary in the reference:");
    }

    @Test
    void theCheckFindsATagFirstJavadocAMissingOneAndAcceptsAGoodOne() {
        List<String> tagFirst = List.of("class A {", "    /** @return the mass (kg). */", "    public double getMass() {",
                "        return 1;", "    }", "}");
        List<String> paramFirst = List.of("class A {", "    /**", "     * @param k stiffness (N/m)", "     */",
                "    public void setK(double k) {", "    }", "}");
        List<String> none = List.of("class A {", "    public void step() {", "    }", "}");
        List<String> protectedNone = List.of("class A {", "    protected final int view() {", "        return 0;", "    }", "}");
        List<String> good = List.of("/** A thing. */", "public class A {", "    /** {@return the mass (kg)} */",
                "    @Deprecated", "    public double getMass() {", "        return 1;", "    }",
                "    @Override", "    public String toString() {", "        return \"\";", "    }", "}");
        assertEquals(1, problemsIn("A.java", tagFirst).size());
        assertEquals(1, problemsIn("A.java", paramFirst).size());
        assertEquals(1, problemsIn("A.java", none).size());
        assertEquals(1, problemsIn("A.java", protectedNone).size());
        assertEquals(List.of(), problemsIn("A.java", good));
    }

    /** The sources whose public members appear in the published reference. */
    private static List<Path> referenceSources() throws IOException {
        Path root = Paths.get("src", "tactus");
        try (Stream<Path> walk = Files.walk(root)) {
            return walk.filter(p -> p.toString().endsWith(".java"))
                    .filter(p -> !p.getFileName().toString().equals("package-info.java"))
                    .filter(p -> !p.startsWith(root.resolve("internal")) && !p.startsWith(root.resolve("engine")))
                    .sorted().collect(Collectors.toList());
        }
    }

    /** The public declarations of one file that have no Javadoc, or one that opens with a block tag. */
    static List<String> problemsIn(String file, List<String> lines) {
        List<String> problems = new ArrayList<>();
        for (int i = 0; i < lines.size(); i++) {
            Matcher m = PUBLIC_DECLARATION.matcher(lines.get(i));
            if (!m.find()) {
                continue;
            }
            int j = i - 1;
            boolean overrides = false;
            while (j >= 0 && lines.get(j).trim().startsWith("@")) {
                overrides |= lines.get(j).trim().startsWith("@Override");
                j--;
            }
            if (overrides) {
                continue;
            }
            String where = file + ":" + (i + 1) + " " + lines.get(i).trim();
            if (j < 0 || !lines.get(j).trim().endsWith("*/")) {
                problems.add(where + " (no Javadoc)");
                continue;
            }
            int start = j;
            while (start >= 0 && !lines.get(start).contains("/**")) {
                start--;
            }
            if (start < 0) {
                problems.add(where + " (a block comment, not a Javadoc)");
                continue;
            }
            String first = firstContent(lines.subList(start, j + 1));
            if (first.isEmpty() || first.startsWith("@")) {
                problems.add(where + " (its Javadoc opens with " + (first.isEmpty() ? "nothing" : first.split("\\s")[0]) + ")");
            }
        }
        return problems;
    }

    /** The first text of a Javadoc, without its delimiters and leading asterisks. */
    private static String firstContent(List<String> comment) {
        for (String line : comment) {
            String t = line.trim();
            t = t.replaceFirst("^/\\*\\*", "").replaceFirst("\\*/$", "").trim();
            t = t.replaceFirst("^\\*+", "").trim();
            if (!t.isEmpty()) {
                return t;
            }
        }
        return "";
    }
}
