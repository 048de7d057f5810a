package tactus.dist;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Properties;
import java.util.jar.JarInputStream;
import java.util.jar.Manifest;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import java.util.zip.ZipEntry;
import java.util.zip.ZipFile;
import java.util.zip.ZipInputStream;

import javax.xml.parsers.DocumentBuilderFactory;

import org.junit.jupiter.api.Test;
import org.w3c.dom.Element;
import org.w3c.dom.Node;

import tactus.PhysicalModel;

/**
 * One version everywhere: the version set in gradle.properties ({@code tactusVersion}) is the one in the
 * contribution's library.properties (prettyVersion, and the PDE's integer version derived from it), in the manifest
 * of the contribution's Tactus.jar, in the POM, in {@link PhysicalModel#VERSION}, and in the Maven coordinates that
 * the README, the docs and examples/gradle-app name. The Gradle test task builds the contribution and the POM first.
 */
class VersionTest {
    private static final Pattern SEMVER = Pattern.compile("(\\d+)\\.(\\d+)\\.(\\d+)(?:[-+].*)?");

    /** The version as gradle.properties sets it, read from the file itself. */
    static String theVersion() throws IOException {
        Path file = Path.of("gradle.properties");
        assertTrue(Files.isRegularFile(file), "no gradle.properties in " + Path.of("").toAbsolutePath());
        Properties p = new Properties();
        try (InputStream in = Files.newInputStream(file)) {
            p.load(in);
        }
        String v = p.getProperty("tactusVersion");
        assertNotNull(v, "gradle.properties sets no tactusVersion");
        assertTrue(SEMVER.matcher(v.trim()).matches(), "tactusVersion is not like 1.2.3: " + v);
        return v.trim();
    }

    private static Path distDir() {
        String dir = System.getProperty("tactus.dist.dir");
        if (dir == null) {
            fail("run through 'gradle test', which builds the contribution first and sets tactus.dist.dir");
        }
        return Path.of(dir);
    }

    private static byte[] entry(ZipFile zip, String name) throws IOException {
        ZipEntry e = zip.getEntry(name);
        assertNotNull(e, name + " is missing from " + zip.getName());
        try (InputStream in = zip.getInputStream(e)) {
            return in.readAllBytes();
        }
    }

    @Test
    void libraryPropertiesCarriesTheVersionAndItsPdeInteger() throws IOException {
        String v = theVersion();
        Properties p = new Properties();
        try (ZipFile zip = new ZipFile(distDir().resolve("Tactus.zip").toFile())) {
            byte[] bytes = entry(zip, "Tactus/library.properties");
            String text = new String(bytes, StandardCharsets.UTF_8);
            assertFalse(text.matches("(?s).*@\\w+@.*"), "a template token was left in library.properties:\n" + text);
            p.load(new ByteArrayInputStream(bytes));
        }
        assertEquals(v, p.getProperty("prettyVersion"), "library.properties prettyVersion");
        Matcher m = SEMVER.matcher(v);
        assertTrue(m.matches());
        int expected = Integer.parseInt(m.group(1)) * 10000 + Integer.parseInt(m.group(2)) * 100
                + Integer.parseInt(m.group(3));
        assertEquals(Integer.toString(expected), p.getProperty("version"),
                "library.properties version: the PDE's integer, major * 10000 + minor * 100 + patch");
    }

    @Test
    void theJarManifestAndItsResourceCarryTheVersion() throws IOException {
        String v = theVersion();
        byte[] jar;
        try (ZipFile zip = new ZipFile(distDir().resolve("Tactus.zip").toFile())) {
            jar = entry(zip, "Tactus/library/Tactus.jar");
        }
        try (JarInputStream in = new JarInputStream(new ByteArrayInputStream(jar))) {
            Manifest mf = in.getManifest();
            assertNotNull(mf, "Tactus.jar has no manifest");
            assertEquals(v, mf.getMainAttributes().getValue("Implementation-Version"), "Implementation-Version");
        }
        Properties resource = new Properties();
        try (ZipInputStream in = new ZipInputStream(new ByteArrayInputStream(jar))) {
            for (ZipEntry e = in.getNextEntry(); e != null; e = in.getNextEntry()) {
                if (e.getName().equals("tactus/internal/version.properties")) {
                    resource.load(in);
                }
            }
        }
        assertEquals(v, resource.getProperty("version"), "tactus/internal/version.properties in Tactus.jar");
    }

    @Test
    void thePomCarriesTheVersion() throws Exception {
        String path = System.getProperty("tactus.dist.pom");
        assertNotNull(path, "run through 'gradle test', which generates the POM first and sets tactus.dist.pom");
        Element project = DocumentBuilderFactory.newInstance().newDocumentBuilder().parse(Path.of(path).toFile())
                .getDocumentElement();
        String version = null;
        for (Node n = project.getFirstChild(); n != null; n = n.getNextSibling()) {
            if (n instanceof Element && ((Element) n).getTagName().equals("version")) {
                version = n.getTextContent().trim();
            }
        }
        assertEquals(theVersion(), version, "the POM's <version>");
    }

    @Test
    void physicalModelKnowsTheVersionAtRunTime() throws IOException {
        assertEquals(theVersion(), PhysicalModel.VERSION);
        assertEquals(theVersion(), PhysicalModel.version());
    }

    /** Maven coordinates of the library, with the group and version they name: "io.github.tactus:tactus:0.3.0". */
    private static final Pattern GRADLE_COORDINATES = Pattern.compile("([\\w.-]+):tactus:([\\w.${}+-]*[\\w}])");
    private static final Pattern MAVEN_COORDINATES = Pattern.compile(
            "<groupId>([^<]*)</groupId>\\s*<artifactId>tactus</artifactId>\\s*<version>([^<]*)</version>");
    private static final Pattern GRADLE_APP_DEFAULT = Pattern.compile(
            "def tactusVersion = .*: '([^']+)'");

    @Test
    void theDocsAndTheGradleAppNameTheseCoordinates() throws IOException {
        String v = theVersion();
        List<Path> files = new ArrayList<>();
        files.add(Path.of("README.md"));
        files.add(Path.of("examples/gradle-app/build.gradle"));
        try (Stream<Path> docs = Files.walk(Path.of("docs"))) {
            docs.filter(f -> f.toString().endsWith(".md")).sorted().forEach(files::add);
        }
        int found = 0;
        List<String> wrong = new ArrayList<>();
        for (Path f : files) {
            String text = Files.readString(f, StandardCharsets.UTF_8);
            for (Pattern pattern : List.of(GRADLE_COORDINATES, MAVEN_COORDINATES)) {
                Matcher m = pattern.matcher(text);
                while (m.find()) {
                    found++;
                    if (!m.group(1).equals("io.github.tactus")) {
                        wrong.add(f + ": group '" + m.group(1) + "' in " + m.group() + " (the group is io.github.tactus)");
                    }
                    String version = m.group(2);
                    if (!version.equals(v) && !version.startsWith("$")) {   // ${tactusVersion} in a build file
                        wrong.add(f + ": version " + version + " in " + m.group() + " (gradle.properties: " + v + ")");
                    }
                }
            }
            Matcher app = GRADLE_APP_DEFAULT.matcher(text);
            while (app.find()) {
                found++;
                if (!app.group(1).equals(v)) {
                    wrong.add(f + ": the default tactusVersion is " + app.group(1) + ", not " + v);
                }
            }
        }
        assertTrue(found >= 3, "expected the coordinates in the getting-started page and examples/gradle-app; found "
                + found + " in " + files.size() + " files");
        assertTrue(wrong.isEmpty(), String.join("\n", wrong));
    }
}
