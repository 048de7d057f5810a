package tactus.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringWriter;
import java.lang.reflect.Method;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import javax.tools.DiagnosticCollector;
import javax.tools.JavaCompiler;
import javax.tools.JavaFileObject;
import javax.tools.StandardJavaFileManager;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import tactus.haptics.TimingVerdict;

/**
 * The verdict of examples/gradle-app, compiled here against the library: FAILED names every reason; a loop that ran
 * late on a busy machine is OK but says it was late and what to do (the run of 488 ticks where 500 were required
 * used to end "gradle-app: FAILED" with no reason).
 */
class GradleAppVerdictTest {
    @TempDir
    Path dir;

    private Method verdict() throws Exception {
        String examples = System.getProperty("tactus.dist.examples", "examples");
        Path app = Path.of(examples, "gradle-app", "src", "main", "java", "tactusapp", "App.java");
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        DiagnosticCollector<JavaFileObject> diags = new DiagnosticCollector<>();
        boolean ok;
        try (StandardJavaFileManager fm = javac.getStandardFileManager(diags, null, StandardCharsets.UTF_8)) {
            ok = javac.getTask(new StringWriter(), fm, diags, List.of("-d", dir.toString(), "-classpath",
                    System.getProperty("java.class.path"), "-proc:none"), null,
                    fm.getJavaFileObjects(app.toFile())).call();
        }
        assertTrue(ok, "examples/gradle-app compiles against the library: " + diags.getDiagnostics());
        URLClassLoader loader = new URLClassLoader(new URL[] {dir.toUri().toURL()}, getClass().getClassLoader());
        Method m = loader.loadClass("tactusapp.App").getDeclaredMethod("verdict", List.class, TimingVerdict.class);
        m.setAccessible(true);
        return m;
    }

    @Test
    void aLateButWorkingRunIsOkAndSaysItWasLate() throws Exception {
        Method verdict = verdict();
        String line = (String) verdict.invoke(null, new ArrayList<String>(),
                TimingVerdict.haptic(488, 30, 45, 0, "normal priority (real-time refused: chrt failed)"));
        assertTrue(line.startsWith("gradle-app: OK: the string's pitch matches theory and the hand felt the chain, but "
                + "the real-time run was LATE: the haptic loop missed 6.1 % of its ticks (30 of 488; bound 1 %); its "
                + "worst tick was 45.0 ms late (bound 20 ms)"), line);
        assertTrue(line.contains("real-time priority"), line);
        String quiet = (String) verdict.invoke(null, new ArrayList<String>(),
                TimingVerdict.haptic(1000, 0, 0.3, 0, "real-time (SCHED_FIFO 50)"));
        assertEquals("gradle-app: OK: the string's pitch matches theory and the hand felt the chain; the real-time run "
                + "was on time (1000 ticks, 0.0 % missed, worst tick 0.3 ms late, 0 watchdog trips; scheduling: "
                + "real-time (SCHED_FIFO 50))", quiet);
    }

    @Test
    void aFailureSaysWhy() throws Exception {
        Method verdict = verdict();
        List<String> failures = new ArrayList<>(List.of("the hand felt no force from the chain",
                "the string's pitch 99.00 Hz is +20.0 cents from theory 97.87 Hz (bound 5 cents)"));
        String line = (String) verdict.invoke(null, failures, null);
        assertEquals("gradle-app: FAILED: the hand felt no force from the chain; the string's pitch 99.00 Hz is +20.0"
                + " cents from theory 97.87 Hz (bound 5 cents)", line);
    }
}
