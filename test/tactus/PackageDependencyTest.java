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
 * package may make (the JDK always may). The machinery behind the facade ({@code tactus.internal.*}) is layered: each
 * of its rooms imports only the rooms below it, the engine and the API's value types. The engine runs on a bare JVM; the audio side knows of the haptic side
 * only the {@code AvatarLink} interface it adapts ({@code ExchangeAvatarLink}); nothing imports the audio side.
 */
class PackageDependencyTest {

    /**
     * The API's value types (and Processing's {@code PVector}, which some of the paper's calls take and fill): what
     * the machinery may take and return besides its own types (it never names {@code PhysicalModel}, a handle or a
     * controller, which call it).
     */
    private static final List<String> VALUE_TYPES = List.of("tactus.Vect3D", "tactus.paramSystem", "tactus.matModuleType",
            "tactus.linkModuleType", "tactus.StabilityPolicy", "tactus.StabilityReport", "tactus.UnstableModelException",
            "tactus.DivergenceException", "tactus.DivergenceListener", "tactus.ModelSnapshot", "processing.core.PVector");

    /**
     * The rooms of the machinery (docs/architecture.md, "Inside tactus"), from the top down: each may import only the
     * rooms below it (and the engine, and the API's value types); none names a handle (they deal in module ids).
     */
    private static final List<String> INTERNAL_ORDER = List.of("tactus.internal.calls", "tactus.internal.realtime",
            "tactus.internal", "tactus.internal.read", "tactus.internal.edit", "tactus.internal.snapshot",
            "tactus.internal.stability", "tactus.internal.model");

    /** Per package (its sub-packages included), the import prefixes it may use besides the JDK and itself. */
    private static final Map<String, List<String>> MAY_IMPORT = Map.of(
            "tactus.engine", List.of(),
            "tactus.io", List.of("tactus."),
            "tactus.export", List.of("tactus."),
            "tactus.render", List.of("tactus.", "processing.core.", "processing.event."),
            "tactus.haptics", List.of("tactus.", "com.fazecast.jSerialComm.", "com.fasterxml.jackson.core.",
                    "processing.core.", "processing.event."),
            "tactus.audio", List.of("tactus.", "tactus.haptics.AvatarLink", "ddf.minim."),
            "tactus", List.of("tactus.engine.", "tactus.render.", "tactus.io.", "tactus.internal.", "processing.core."));

    /** Packages nobody else may import, even where a prefix above would let them. */
    private static final Map<String, List<String>> NEVER = Map.of(
            "tactus.engine", List.of("tactus.audio", "tactus.haptics", "tactus.render", "tactus.io", "tactus.*"),
            "tactus.io", List.of("tactus.audio", "tactus.haptics", "tactus.render", "tactus.engine", "tactus.internal"),
            "tactus.export", List.of("tactus.audio", "tactus.haptics", "tactus.render", "tactus.io", "tactus.engine",
                    "tactus.internal"),
            "tactus.render", List.of("tactus.audio", "tactus.haptics", "tactus.io", "tactus.engine", "tactus.internal"),
            "tactus.haptics", List.of("tactus.audio", "tactus.render", "tactus.io", "tactus.internal"),
            "tactus.audio", List.of("tactus.render", "tactus.io", "tactus.engine", "tactus.internal"),
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
                    if (imp.startsWith("java.") || imp.startsWith("javax.") || room.equals(roomOfImport(imp))) {
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
    void everyInternalRoomIsMarkedNotApi() throws IOException {
        for (String room : INTERNAL_ORDER) {
            Path info = Paths.get("src", room.replace('.', '/'), "package-info.java");
            String text = new String(Files.readAllBytes(info), StandardCharsets.UTF_8);
            assertTrue(text.contains("Not API"), info + " must say that its package is not API");
        }
    }

    /**
     * Processing's "Sketch, Import Library" inserts one import per package of the library, or the packages that
     * library.properties lists as {@code imports}: those must be every package of src/ but the machinery's.
     */
    @Test
    void importLibraryLeavesTheMachineryOut() throws IOException {
        java.util.Set<String> packages = new java.util.TreeSet<>();
        try (Stream<Path> all = Files.walk(Paths.get("src"))) {
            for (Path p : (Iterable<Path>) all.filter(f -> f.toString().endsWith(".java"))::iterator) {
                Matcher pm = PACKAGE.matcher(new String(Files.readAllBytes(p), StandardCharsets.UTF_8));
                if (pm.find() && !pm.group(1).startsWith("tactus.internal")) {
                    packages.add(pm.group(1));
                }
            }
        }
        String imports = null;
        for (String line : Files.readAllLines(Paths.get("library.properties"), StandardCharsets.UTF_8)) {
            if (line.startsWith("imports=")) {
                imports = line.substring("imports=".length());
            }
        }
        assertTrue(imports != null, "library.properties must list the packages Import Library inserts (imports=)");
        assertTrue(packages.equals(new java.util.TreeSet<>(List.of(imports.split(",")))),
                "library.properties imports= must be " + String.join(",", packages) + ", got " + imports);
    }

    @Test
    void theRuleCatchesAForbiddenImport() {
        assertTrue(!allowed("tactus.engine", "tactus.PhysicalModel"), "the engine may not import the facade");
        assertTrue(!allowed("tactus.haptics", "tactus.audio.PhyUGen"), "haptics may not import audio");
        assertTrue(!allowed("tactus.audio", "tactus.haptics.HapticLoop"), "audio may import only AvatarLink");
        assertTrue(allowed("tactus.audio", "tactus.haptics.AvatarLink"), "audio adapts AvatarLink");
        assertTrue(!allowed("tactus", "tactus.audio.PhyUGen"), "the facade may not import audio");
        assertTrue(!allowed("tactus.render", "tactus.internal.ModelCore"), "only the facade reaches the machinery");
        assertTrue(!allowed("tactus.internal.model", "tactus.internal.realtime.Ownership"), "rooms point down only");
        assertTrue(!allowed("tactus.internal.realtime", "tactus.internal.calls.BuildCalls"), "rooms point down only");
        assertTrue(allowed("tactus.internal.realtime", "tactus.internal.ModelCore"), "the rule runs the rooms");
        assertTrue(!allowed("tactus.internal.edit", "tactus.PhysicalModel"), "the machinery never calls the facade");
        assertTrue(allowed("tactus.internal.edit", "tactus.Vect3D"), "the machinery speaks the value types");
        assertTrue(!allowed("tactus.internal.calls", "tactus.Mass"), "the calls return module ids, never handles");
        assertTrue(!allowed("tactus.internal.calls", "tactus.ParamController"), "controllers are the facade's own");
    }

    private static String roomOf(String pkg) {
        for (String room : INTERNAL_ORDER) {
            if (pkg.equals(room)) {
                return room;
            }
        }
        for (String room : new String[] {"tactus.engine", "tactus.io", "tactus.export", "tactus.render", "tactus.haptics",
            "tactus.audio"}) {
            if (pkg.equals(room) || pkg.startsWith(room + ".")) {
                return room;
            }
        }
        return "tactus";
    }

    /** @return the room of an imported type (its package, or the room holding it), or null outside Tactus. */
    private static String roomOfImport(String imp) {
        String pkg = imp.endsWith(".*") ? imp.substring(0, imp.length() - 2) : imp.substring(0, imp.lastIndexOf('.'));
        while (pkg.contains(".") && Character.isUpperCase(pkg.charAt(pkg.lastIndexOf('.') + 1))) {
            pkg = pkg.substring(0, pkg.lastIndexOf('.')); // a nested type: Outer.Inner
        }
        return pkg.equals("tactus") || pkg.startsWith("tactus.") ? roomOf(pkg) : null;
    }

    private static boolean allowed(String room, String imp) {
        if (INTERNAL_ORDER.contains(room)) {
            if (imp.startsWith("tactus.engine.")) {
                return true;
            }
            if (imp.startsWith("tactus.internal.")) {
                return INTERNAL_ORDER.indexOf(roomOfImport(imp)) >= INTERNAL_ORDER.indexOf(room);
            }
            return VALUE_TYPES.contains(imp);
        }
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
