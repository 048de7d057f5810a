package tactus.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.BufferedReader;
import java.io.File;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.Set;
import java.util.TreeSet;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import javax.tools.JavaCompiler;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import tactus.PhysicalModel;
import tactus.bench.paper.ContactGroupHook;
import tactus.bench.paper.PaperScenes;
import tactus.bench.paper.SnapshotReader;

/**
 * The side-by-side scenes (written once against the paper's API) use only that API, compile against the library
 * alone, build with the expected element counts and step without non-finite positions. No timing is asserted.
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class PaperScenesTest {
    static final Path SOURCE = Paths.get("tools", "tactus", "bench", "paper", "PaperScenes.java");

    /** @return the method names of the paper's PhysicalModel, from the hand-written list of its API */
    static Set<String> paperMethods() throws Exception {
        Set<String> names = new TreeSet<>();
        try (InputStream in = PaperScenesTest.class.getResourceAsStream("/tactus/paper-api-v1.1.txt")) {
            assertTrue(in != null, "test resource tactus/paper-api-v1.1.txt is missing");
            BufferedReader r = new BufferedReader(new InputStreamReader(in, StandardCharsets.UTF_8));
            boolean inModel = false;
            Pattern method = Pattern.compile("^(?:static )?\\S+ (\\w+)\\(");
            for (String line; (line = r.readLine()) != null;) {
                if (line.startsWith("[")) {
                    inModel = line.equals("[PhysicalModel]");
                } else if (inModel) {
                    Matcher m = method.matcher(line.trim());
                    if (m.find()) {
                        names.add(m.group(1));
                    }
                }
            }
        }
        return names;
    }

    @Test
    void theSceneSourceCallsOnlyMethodsOfThePapersPhysicalModel() throws Exception {
        String src = new String(Files.readAllBytes(SOURCE), StandardCharsets.UTF_8);
        Set<String> api = paperMethods();
        assertTrue(api.contains("addContact3D") && api.contains("computeStep"), "API list read: " + api.size());
        Matcher m = Pattern.compile("\\b(?:mdl|m)\\.(\\w+)\\(").matcher(src);
        Set<String> used = new TreeSet<>();
        while (m.find()) {
            used.add(m.group(1));
        }
        assertTrue(used.size() >= 15, "model calls found in the source: " + used);
        for (String name : used) {
            assertTrue(api.contains(name), "PaperScenes calls " + name + "(), which the paper's engine does not have");
        }
        String paper = SideBySide.paperSource(src);
        assertEquals(1, countDifferentLines(src, paper), "the paper engine's copy differs by one line");
        assertTrue(paper.contains("\nimport miPhysics.*;\n"));
    }

    private static int countDifferentLines(String a, String b) {
        String[] x = a.split("\n", -1);
        String[] y = b.split("\n", -1);
        assertEquals(x.length, y.length);
        int d = 0;
        for (int i = 0; i < x.length; i++) {
            d += x[i].equals(y[i]) ? 0 : 1;
        }
        return d;
    }

    @Test
    void theSceneSourceCompilesAgainstTheLibraryAlone() throws Exception {
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        assertTrue(javac != null, "no Java compiler in " + System.getProperty("java.home") + " (install a JDK)");
        String main = new File(PhysicalModel.class.getProtectionDomain().getCodeSource().getLocation().toURI()).getPath();
        Path out = Files.createTempDirectory("paperscenes");
        int code = javac.run(null, null, null, "-nowarn", "-proc:none", "-encoding", "UTF-8", "--release", "17", "-cp",
                main + File.pathSeparator + SideBySide.processingCore(), "-d", out.toString(), SOURCE.toString());
        assertEquals(0, code, "PaperScenes.java must compile against the library's classes and Processing core only");
        assertTrue(Files.isRegularFile(out.resolve("tactus/bench/paper/PaperScenes.class")));
    }

    private static void stepAndCheck(String what, PhysicalModel mdl, int mats, int links, int steps) {
        assertEquals(mats, mdl.getNumberOfMats(), what + ": masses (Ground3D included)");
        assertEquals(links, mdl.getNumberOfLinks(), what + ": interactions");
        double before = sumOfPositions(mdl);
        for (int k = 0; k < steps; k++) {
            mdl.computeStep();
        }
        assertTrue(PaperScenes.finite(mdl), what + ": every position finite after " + steps + " steps");
        assertNotEquals(before, sumOfPositions(mdl), what + ": the model moves");
    }

    private static double sumOfPositions(PhysicalModel mdl) {
        double s = 0;
        for (int i = 0; i < mdl.getNumberOfMats(); i++) {
            tactus.Vect3D p = mdl.getMatPosAt(i);
            s += p.x + p.y + p.z;
        }
        return s;
    }

    @Test
    void eachSceneBuildsWithTheExpectedCountsAndStepsWithoutNaN() {
        stepAndCheck("string-470", PaperScenes.string(470, 44100), 472, 471, 500);
        stepAndCheck("string-1000", PaperScenes.string(1000, 44100), 1002, 1001, 500);
        stepAndCheck("mesh-100", PaperScenes.mesh(100), 10_000, 2 * 100 * 99 - 4 * 99, 100);
        stepAndCheck("marbles-200, one Contact3D per pair", PaperScenes.marbles(200, null), 201,
                200 * 199 / 2 + 2 * 200, 200);
        stepAndCheck("marbles-200, contact group", PaperScenes.marbles(200, new ContactGroupHook()), 201, 2 * 200, 200);
    }

    @Test
    void bothReadersReadTheModel() {
        PhysicalModel mdl = PaperScenes.marbles(20, null);
        mdl.computeNSteps(10);
        PaperScenes.LockedReader locked = new PaperScenes.LockedReader(mdl);
        locked.run();
        SnapshotReader snapshot = new SnapshotReader(mdl);
        snapshot.run();
        assertTrue(locked.sink != 0 && Double.isFinite(locked.sink), "locked reader read positions: " + locked.sink);
        assertTrue(snapshot.sink != 0 && Double.isFinite(snapshot.sink), "snapshot reader read: " + snapshot.sink);
    }
}
