package tactus.dist;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.stream.Stream;
import java.util.zip.ZipEntry;
import java.util.zip.ZipFile;
import java.util.zip.ZipInputStream;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * Unzips the Processing contribution that {@code gradle dist} built ({@code build/dist/Tactus.zip}; the Gradle
 * test task builds it first) and checks it against the PDE's rules (see the Processing library reference notes):
 * one top folder named like its jar, {@code library/<Name>.jar}, no Processing core and no Minim inside any jar,
 * a {@code library.properties} that the PDE's line-by-line reader understands, categories from the PDE's list,
 * a {@code .pdex} that is the same zip, the sources, the reference and the example groups, and no non-sketch
 * folder among the examples. The rules are written out here again, independently of the build script.
 */
class DistributionTest {
    /** The categories the PDE knows (ContributionListing); anything else shows as "Unknown". */
    private static final Set<String> CATEGORIES = Set.of("3D", "Animation", "Data", "Geometry", "GUI", "Hardware",
            "I/O", "Math", "Renderer", "Simulation", "Sound", "Typography", "Utilities", "Video & Vision", "Other");
    private static final String NAME = "[A-Za-z][A-Za-z0-9_]*";

    private static Path distDir;
    private static Path examplesDir;
    /** Entry name (without the top folder) to content, for every file of the zip. */
    private static final Map<String, byte[]> FILES = new TreeMap<>();
    private static final Set<String> TOP = new TreeSet<>();
    private static String top;

    @BeforeAll
    static void unzip() throws IOException {
        String dir = System.getProperty("tactus.dist.dir");
        String examples = System.getProperty("tactus.dist.examples");
        if (dir == null || examples == null) {
            fail("run through 'gradle test', which builds the contribution first and sets tactus.dist.dir");
        }
        distDir = Path.of(dir);
        examplesDir = Path.of(examples);
        Path zip = distDir.resolve("Tactus.zip");
        assertTrue(Files.isRegularFile(zip), "no contribution at " + zip + " (gradle dist)");
        try (ZipFile z = new ZipFile(zip.toFile())) {
            for (ZipEntry e : java.util.Collections.list(z.entries())) {
                String name = e.getName();
                assertFalse(name.startsWith("/") || name.contains("\\") || name.contains("../"),
                        "unsafe entry name " + name);
                int slash = name.indexOf('/');
                TOP.add(slash < 0 ? name : name.substring(0, slash));
                if (!e.isDirectory()) {
                    assertTrue(slash > 0, "a file outside the top folder: " + name);
                    try (InputStream in = z.getInputStream(e)) {
                        FILES.put(name.substring(slash + 1), in.readAllBytes());
                    }
                }
            }
        }
        assertEquals(1, TOP.size(), "the zip must hold exactly one top folder, found " + TOP);
        top = TOP.iterator().next();
    }

    private static byte[] file(String path) {
        byte[] b = FILES.get(path);
        assertNotNull(b, path + " is missing from the contribution; it has " + FILES.keySet().stream()
                .filter(k -> !k.startsWith("src/") && !k.startsWith("reference/") && !k.startsWith("docs/"))
                .toList());
        return b;
    }

    private static List<String> jarsInLibrary() {
        List<String> jars = new ArrayList<>();
        for (String k : FILES.keySet()) {
            if (k.startsWith("library/") && (k.endsWith(".jar") || k.endsWith(".zip"))) {
                jars.add(k);
            }
        }
        return jars;
    }

    private static List<String> entriesOf(byte[] jar) throws IOException {
        List<String> names = new ArrayList<>();
        try (ZipInputStream in = new ZipInputStream(new ByteArrayInputStream(jar))) {
            for (ZipEntry e = in.getNextEntry(); e != null; e = in.getNextEntry()) {
                names.add(e.getName());
            }
        }
        return names;
    }

    /** Reads library.properties the way the PDE's Util.readSettings does, failing on what it would misread. */
    private static Map<String, String> pdeProperties(byte[] bytes) {
        String text;
        try {
            text = StandardCharsets.UTF_8.newDecoder().onMalformedInput(CodingErrorAction.REPORT)
                    .onUnmappableCharacter(CodingErrorAction.REPORT).decode(ByteBuffer.wrap(bytes)).toString();
        } catch (CharacterCodingException e) {
            throw new AssertionError("library.properties is not UTF-8 text", e);
        }
        Map<String, String> values = new LinkedHashMap<>();
        String[] lines = text.split("\r?\n", -1);
        for (int i = 0; i < lines.length; i++) {
            String line = lines[i];
            String where = "library.properties line " + (i + 1) + " '" + line + "'";
            if (line.isBlank()) {
                continue;
            }
            assertFalse(line.contains("#"), where + ": '#' starts a comment anywhere on a PDE line");
            assertFalse(line.endsWith("\\"), where + ": a trailing backslash does not continue a line in the PDE");
            assertFalse(line.matches(".*\\\\[:=u!nt ].*"), where + ": the PDE decodes no escapes");
            int eq = line.indexOf('=');
            assertTrue(eq > 0, where + ": not a key=value line");
            String key = line.substring(0, eq).trim();
            assertFalse(values.containsKey(key), where + ": key '" + key + "' appears twice");
            values.put(key, line.substring(eq + 1).trim());
        }
        return values;
    }

    @Test
    void theTopFolderIsAValidLibraryNameWithItsJar() throws IOException {
        assertTrue(top.matches(NAME), "the PDE ignores a library named '" + top + "'");
        assertEquals("Tactus", top);
        List<String> entries = entriesOf(file("library/" + top + ".jar"));
        assertTrue(entries.contains("tactus/PhysicalModel.class"), "library/" + top + ".jar lacks the library");
        assertTrue(entries.contains("tactus/render/ModelDrawer.class"), "library/" + top + ".jar lacks tactus.render");
        for (String e : entries) {
            assertFalse(e.startsWith("tactus/demo/") || e.startsWith("tactus/bench/") || e.startsWith("tactus/report/")
                    || e.startsWith("tactus/dist/") || e.endsWith("Test.class"),
                    "tools or test classes in the library jar: " + e);
        }
        file("library.properties");
    }

    @Test
    void noJarCarriesProcessingCoreOrMinim() throws IOException {
        List<String> jars = jarsInLibrary();
        assertTrue(jars.size() >= 2, "expected Tactus.jar and the bundled jSerialComm, found " + jars);
        assertTrue(jars.stream().anyMatch(j -> j.matches("library/jSerialComm-[0-9.]+\\.jar")),
                "jSerialComm (the serial port library the haptics need) is not bundled: " + jars);
        for (String jar : jars) {
            String base = jar.substring(jar.lastIndexOf('/') + 1).toLowerCase();
            assertFalse(base.startsWith("core") || base.contains("minim") || base.contains("jogl")
                    || base.contains("gluegen") || base.contains("kotlin") || base.contains("jsminim")
                    || base.contains("tritonus") || base.contains("mp3spi"),
                    jar + " belongs to Processing or Minim, which users install themselves");
            for (String e : entriesOf(FILES.get(jar))) {
                assertFalse(e.startsWith("processing/core/"), jar + " contains Processing core (" + e
                        + "): the PDE would disable the library");
                assertFalse(e.startsWith("ddf/minim/"), jar + " contains Minim (" + e + ")");
            }
        }
    }

    @Test
    void libraryPropertiesIsPlainTextWithTheRequiredFields() {
        byte[] bytes = file("library.properties");
        Map<String, String> p = pdeProperties(bytes);
        for (String key : List.of("name", "version", "prettyVersion", "authors", "categories", "sentence",
                "minRevision", "maxRevision")) {
            assertTrue(p.containsKey(key) && !p.get(key).isEmpty(), "library.properties: '" + key + "' is missing");
        }
        for (String key : List.of("version", "minRevision", "maxRevision")) {
            assertTrue(p.get(key).matches("[0-9]+"), "library.properties: '" + key + "' must be an integer, got "
                    + p.get(key));
        }
        assertTrue(Integer.parseInt(p.get("version")) >= 1, "version counts releases from 1");
        assertTrue(p.get("prettyVersion").matches("[0-9]+\\.[0-9]+\\.[0-9]+.*"), "prettyVersion " + p.get("prettyVersion"));
        // 4.x only: revision 1285 is Processing 4.0, the first with Java 17
        assertTrue(Integer.parseInt(p.get("minRevision")) >= 1285, "minRevision below Processing 4.0 (1285)");
        if (p.containsKey("url")) {
            assertTrue(p.get("url").matches("https?://\\S+"), "url must be a web address, got " + p.get("url"));
        }
        String sentence = p.get("sentence");
        assertTrue(sentence.endsWith(".") && Character.isUpperCase(sentence.charAt(0)),
                "the sentence starts with a capital and ends with a period: " + sentence);
        for (String key : p.keySet()) {
            assertFalse(key.equals("id") || key.equals("lastUpdated") || key.equals("category"),
                    "library.properties: '" + key + "' is set by the registry or unknown to the PDE");
        }
    }

    @Test
    void everyCategoryIsOneThePdeAccepts() {
        Map<String, String> p = pdeProperties(file("library.properties"));
        String[] cats = p.get("categories").split(",");
        assertTrue(cats.length >= 1);
        for (String c : cats) {
            assertTrue(CATEGORIES.contains(c.trim()), "category '" + c.trim() + "' is not one of " + CATEGORIES);
        }
    }

    @Test
    void thePdexAndTheListingAreCopiesOfTheZipAndOfItsProperties() throws IOException {
        Path zip = distDir.resolve("Tactus.zip");
        Path pdex = distDir.resolve("Tactus.pdex");
        Path txt = distDir.resolve("Tactus.txt");
        assertTrue(Files.isRegularFile(pdex), "no " + pdex);
        assertArrayEquals(Files.readAllBytes(zip), Files.readAllBytes(pdex), "the .pdex must be the same zip");
        assertTrue(Files.isRegularFile(txt), "no " + txt);
        assertArrayEquals(file("library.properties"), Files.readAllBytes(txt),
                "the registry's listing Tactus.txt must be the contribution's library.properties");
    }

    @Test
    void sourcesAndReferenceAreIncluded() {
        file("src/tactus/PhysicalModel.java");
        file("src/tactus/render/ModelDrawer.java");
        file("reference/index.html");
        for (String k : FILES.keySet()) {
            assertFalse(k.endsWith(".class") && !k.startsWith("library/"), "a compiled class outside library/: " + k);
        }
    }

    @Test
    void everyExampleGroupOfTheRepositoryShipsAndEverySketchIsWellFormed() throws IOException {
        // Every .pde sits in a folder of its own name, which is a name the PDE accepts, at any depth.
        Set<String> sketches = new TreeSet<>();
        for (String k : FILES.keySet()) {
            if (!k.startsWith("examples/")) {
                continue;
            }
            assertFalse(k.startsWith("examples/gradle-app/") || k.endsWith("build.gradle"),
                    "the Gradle application is not a Processing sketch and stays out of the contribution: " + k);
            if (k.endsWith(".pde")) {
                String[] parts = k.split("/");
                // examples/<Group>/<Sketch>/<Sketch>.pde, at any depth (the PDE also lists examples/<Sketch>/)
                assertTrue(parts.length >= 3, "a sketch must sit in a folder of its own under examples/: " + k);
                String folder = parts[parts.length - 2];
                String sketchDir = k.substring(0, k.lastIndexOf('/'));
                if (parts[parts.length - 1].equals(folder + ".pde")) {
                    assertTrue(folder.matches(NAME), "sketch name " + folder + " is not valid in the PDE");
                    sketches.add(sketchDir);
                }
            }
        }
        for (String k : FILES.keySet()) {
            if (k.startsWith("examples/") && k.endsWith(".pde")) {
                String dir = k.substring(0, k.lastIndexOf('/'));
                assertTrue(sketches.contains(dir), "no main tab <Folder>.pde next to " + k);
            }
        }
        assertFalse(sketches.isEmpty(), "the contribution has no examples");

        // Every sketch of the repository's examples/ (outside gradle-app) is in the zip, byte for byte.
        List<Path> expected;
        try (Stream<Path> walk = Files.walk(examplesDir)) {
            expected = walk.filter(Files::isRegularFile)
                    .filter(f -> !examplesDir.relativize(f).startsWith("gradle-app"))
                    .filter(f -> !f.getFileName().toString().startsWith("."))
                    .toList();
        }
        for (Path f : expected) {
            String rel = "examples/" + examplesDir.relativize(f).toString().replace('\\', '/');
            assertArrayEquals(Files.readAllBytes(f), file(rel), rel + " differs from the repository's copy");
        }
    }
}
