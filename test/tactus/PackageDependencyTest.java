package tactus;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;

/**
 * Keeps the rooms of docs/architecture.md apart: every import of every library source file must be one its
 * package may make (the JDK always may). The engine runs on a bare JVM; the audio side knows of the haptic side
 * only the {@code AvatarLink} interface it adapts ({@code ExchangeAvatarLink}); nothing imports the audio side.
 */
class PackageDependencyTest {

    /** Per package (its sub-packages included), the import prefixes it may use besides the JDK and itself. */
    private static final Map<String, List<String>> MAY_IMPORT = Map.of(
            "tactus.engine", List.of(),
            "tactus.io", List.of("tactus."),
            "tactus.export", List.of("tactus."),
            "tactus.render", List.of("tactus.", "processing.core.", "processing.event."),
            "tactus.haptics", List.of("tactus.", "com.fazecast.jSerialComm.", "com.fasterxml.jackson.core.",
                    "processing.core.", "processing.event."),
            "tactus.audio", List.of("tactus.", "tactus.haptics.AvatarLink", "ddf.minim."),
            "tactus", List.of("tactus.engine.", "tactus.render.", "tactus.io.", "processing.core."));

    /** Packages nobody else may import, even where a prefix above would let them. */
    private static final Map<String, List<String>> NEVER = Map.of(
            "tactus.engine", List.of("tactus.audio", "tactus.haptics", "tactus.render", "tactus.io", "tactus.*"),
            "tactus.io", List.of("tactus.audio", "tactus.haptics", "tactus.render", "tactus.engine"),
            "tactus.export", List.of("tactus.audio", "tactus.haptics", "tactus.render", "tactus.io", "tactus.engine"),
            "tactus.render", List.of("tactus.audio", "tactus.haptics", "tactus.io", "tactus.engine"),
            "tactus.haptics", List.of("tactus.audio", "tactus.render", "tactus.io"),
            "tactus.audio", List.of("tactus.render", "tactus.io", "tactus.engine"),
            "tactus", List.of("tactus.audio", "tactus.haptics", "tactus.export"));

    private static final Pattern PACKAGE = Pattern.compile("(?m)^package\\s+([\\w.]+);");
    private static final Pattern IMPORT = Pattern.compile("(?m)^import\\s+(?:static\\s+)?([\\w.*]+);");

    @Test
    void everyImportIsOneItsRoomMayMake() throws IOException {
        List<String> violations = new ArrayList<>();
        int files = 0;
        try (Stream<Path> all = Files.walk(Paths.get("src"))) {
            for (Path p : (Iterable<Path>) all.filter(f -> f.toString().endsWith(".java"))::iterator) {
                String text = new String(Files.readAllBytes(p), StandardCharsets.UTF_8);
                Matcher pm = PACKAGE.matcher(text);
                if (!pm.find()) {
                    continue;
                }
                files++;
                String room = roomOf(pm.group(1));
                Matcher im = IMPORT.matcher(text);
                while (im.find()) {
                    String imp = im.group(1);
                    if (imp.startsWith("java.") || imp.startsWith("javax.") || imp.startsWith(room + ".")) {
                        continue;
                    }
                    if (!allowed(room, imp)) {
                        violations.add(p + ": " + room + " imports " + imp);
                    }
                }
            }
        }
        assertTrue(files > 100, "library sources found: " + files);
        assertTrue(violations.isEmpty(), "imports that cross the rooms of docs/architecture.md:\n"
                + String.join("\n", violations));
    }

    @Test
    void theRuleCatchesAForbiddenImport() {
        assertTrue(!allowed("tactus.engine", "tactus.PhysicalModel"), "the engine may not import the facade");
        assertTrue(!allowed("tactus.haptics", "tactus.audio.PhyUGen"), "haptics may not import audio");
        assertTrue(!allowed("tactus.audio", "tactus.haptics.HapticLoop"), "audio may import only AvatarLink");
        assertTrue(allowed("tactus.audio", "tactus.haptics.AvatarLink"), "audio adapts AvatarLink");
        assertTrue(!allowed("tactus", "tactus.audio.PhyUGen"), "the facade may not import audio");
    }

    private static String roomOf(String pkg) {
        for (String room : new String[] {"tactus.engine", "tactus.io", "tactus.export", "tactus.render", "tactus.haptics",
            "tactus.audio"}) {
            if (pkg.equals(room) || pkg.startsWith(room + ".")) {
                return room;
            }
        }
        return "tactus";
    }

    private static boolean allowed(String room, String imp) {
        if (room.equals("tactus.audio") && imp.startsWith("tactus.haptics.")) {
            return imp.equals("tactus.haptics.AvatarLink");
        }
        for (String never : NEVER.get(room)) {
            if (never.endsWith("*") ? imp.startsWith("tactus.") : (imp.equals(never) || imp.startsWith(never + "."))) {
                return false;
            }
        }
        for (String prefix : MAY_IMPORT.get(room)) {
            if (imp.startsWith(prefix) || imp.equals(prefix)) {
                return true;
            }
        }
        return false;
    }
}
