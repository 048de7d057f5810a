package tactus.sketch;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;

/**
 * Issue #11 asks for sketches of our own that use every call of the paper's engine. This test reads the list of
 * that API ({@code test/tactus/paper-api-v1.1.txt}, checked against the library by
 * {@code tactus.PaperApiCompletenessTest}) and fails for every method, constructor, field or enum constant that no
 * example sketch under {@code examples/} uses, except the few in {@link #NOT_FOR_SKETCHES}. Since
 * {@link ExamplesTest} runs every example and then presses every key it reacts to, each listed call is then run
 * headless in {@code gradle test} (a call behind the file chooser, {@code loadModelFromFile}, only opens it).
 *
 * <p>The check is textual, by name: a method counts as used when some sketch has {@code name(}, a constructor
 * when it has {@code new Class(}, a constant when it has {@code Type.CONSTANT} or {@code case CONSTANT:}, a field
 * when it has {@code .name}. Overloads of one name count as one.
 */
class ExamplesUsePaperApiTest {

    /** Members that a sketch has no reason to call, with the reason. */
    static final Map<String, String> NOT_FOR_SKETCHES = new LinkedHashMap<>();

    static {
        NOT_FOR_SKETCHES.put("new AbstractController",
                "the base class of the controllers; sketches make ParamController and MidiController");
        NOT_FOR_SKETCHES.put("new ParamController", "made by PhysicalModel.addParamController");
        NOT_FOR_SKETCHES.put("ParamController.updateParams", "called by the model at every step");
    }

    @Test
    void everyCallOfThePaperEngineIsUsedByAnExample() throws IOException {
        String sketches = allSketches();
        List<String> unused = new ArrayList<>();
        int members = 0;
        for (String[] m : apiList()) {
            members++;
            String cls = m[0];
            String member = m[1].replaceFirst("^static ", "");
            String key;
            Pattern use;
            if (member.startsWith("constant ")) {
                String name = member.substring("constant ".length()).trim();
                key = cls + "." + name;
                use = Pattern.compile("\\b" + cls + "\\." + name + "\\b|\\bcase\\s+" + name + "\\s*:");
            } else if (member.startsWith("field ")) {
                String name = member.split("\\s+")[2];
                key = cls + "." + name;
                use = Pattern.compile("\\." + name + "\\b");
            } else if (member.startsWith("new(")) {
                key = "new " + cls;
                use = Pattern.compile("\\bnew\\s+" + cls + "\\s*\\(");
            } else {
                Matcher name = Pattern.compile("^\\S+\\s+(\\w+)\\(").matcher(member);
                assertTrue(name.find(), "cannot read " + member);
                key = cls + "." + name.group(1);
                use = Pattern.compile("\\b" + name.group(1) + "\\s*\\(");
            }
            if (!use.matcher(sketches).find() && !NOT_FOR_SKETCHES.containsKey(key) && !unused.contains(key)) {
                unused.add(key);
            }
        }
        assertTrue(members > 200, "the list holds only " + members + " members");
        assertTrue(unused.isEmpty(), unused.size() + " call(s) of the paper's engine are used by no example under "
                + ExamplesTest.examplesRoot() + ":\n  " + String.join("\n  ", unused));
    }

    /** The exemptions must name members that exist in the list and that really are unused. */
    @Test
    void theExemptionsAreListedAndUnused() throws IOException {
        String sketches = allSketches();
        for (String key : NOT_FOR_SKETCHES.keySet()) {
            boolean listed = false;
            for (String[] m : apiList()) {
                String member = m[1].replaceFirst("^static ", "");
                String k = member.startsWith("new(") ? "new " + m[0]
                        : m[0] + "." + member.replaceFirst("^\\S+\\s+(\\w+)\\(.*$", "$1");
                listed |= k.equals(key);
            }
            assertTrue(listed, key + " is not in the API list");
            String name = key.startsWith("new ") ? "new\\s+" + key.substring(4) : key.substring(key.indexOf('.') + 1);
            assertFalse(Pattern.compile("\\b" + name + "\\s*\\(").matcher(sketches).find(),
                    key + " is used by an example now: remove it from NOT_FOR_SKETCHES");
        }
    }

    static String allSketches() throws IOException {
        try (Stream<Path> s = Files.walk(ExamplesTest.examplesRoot())) {
            StringBuilder all = new StringBuilder();
            for (Path p : s.filter(p -> p.toString().endsWith(".pde")).sorted().collect(Collectors.toList())) {
                all.append(new String(Files.readAllBytes(p), StandardCharsets.UTF_8)).append('\n');
            }
            assertFalse(all.length() == 0, "no sketch under " + ExamplesTest.examplesRoot());
            return all.toString();
        }
    }

    /** @return {class, member} pairs of the API list */
    static List<String[]> apiList() throws IOException {
        String text;
        try (InputStream in = ExamplesUsePaperApiTest.class.getResourceAsStream("/tactus/paper-api-v1.1.txt")) {
            assertTrue(in != null, "the resource tactus/paper-api-v1.1.txt is missing");
            text = new String(in.readAllBytes(), StandardCharsets.UTF_8);
        }
        List<String[]> out = new ArrayList<>();
        String cls = null;
        for (String raw : text.split("\n")) {
            String line = raw.trim();
            if (line.isEmpty() || line.startsWith("#")) {
                continue;
            }
            if (line.startsWith("[")) {
                cls = line.substring(1, line.length() - 1);
            } else {
                out.add(new String[] {cls, line});
            }
        }
        return out;
    }
}
