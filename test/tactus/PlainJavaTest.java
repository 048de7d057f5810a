package tactus;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.io.StringWriter;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.lang.reflect.Parameter;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import javax.tools.Diagnostic;
import javax.tools.DiagnosticCollector;
import javax.tools.JavaCompiler;
import javax.tools.JavaFileObject;
import javax.tools.StandardJavaFileManager;
import javax.tools.ToolProvider;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A plain Java program, compiled with javac and run with only Tactus's classes and its bundled dependencies
 * (jackson-core, jSerialComm) on the class path: no Processing core, no Minim. It builds a model with every family
 * of model call (masses, links, parameters, gravity, subsets, reads, the XML file), steps it and reads it; a second
 * program calls every public method of {@code PhysicalModel} and shows which of them javac cannot compile there.
 */
class PlainJavaTest {
    @TempDir
    Path dir;

    /** The program of docs/plain-java.md, in spirit: every model-call family, then a step and a read. */
    static final String PROGRAM = String.join("\n",
            "import tactus.*;",
            "import tactus.io.ModelXml;",
            "import java.io.File;",
            "public class PlainApp {",
            "  public static String run(String folder) {",
            "    PhysicalModel m = new PhysicalModel(1000, 50);",
            "    m.setGravity(9.81);",
            "    m.setGravityDirection(0, 1, 0);",
            "    m.setFriction(0.001);",
            "    m.addGround3D(\"g\", new Vect3D(0, 0, 0));",
            "    m.addMass3D(\"a\", 1.0, new Vect3D(0, 1, 0), new Vect3D(0, 1, 0));",
            "    m.addMass3D(\"b\", 1.0, new Vect3D(0, 2, 0), new Vect3D(0, 2, 0));",
            "    m.addSpringDamper3D(\"s1\", 1.0, 0.01, 0.001, \"g\", \"a\");",
            "    m.addSpringDamper3D(\"s2\", 1.0, 0.01, 0.001, \"a\", \"b\");",
            "    m.createMatSubset(\"moving\");",
            "    m.addMatToSubset(\"a\", \"moving\");",
            "    m.addMatToSubset(\"b\", \"moving\");",
            "    m.createLinkSubset(\"springs\");",
            "    m.addLinkToSubset(\"s1\", \"springs\");",
            "    m.changeStiffnessParamOfSubset(0.02, \"springs\");",
            "    m.setMatMass(\"b\", 2.0);",
            "    m.setLinkDamping(\"s2\", 0.002);",
            "    m.init();",
            "    m.computeNSteps(200);",
            "    Vect3D p = m.getMatPosition(\"b\");",
            "    Vect3D v = m.getMatVelocity(\"b\");",
            "    Vect3D f = m.getMatForce(\"a\");",
            "    File xml = new File(folder, \"plain.xml\");",
            "    ModelXml.save(m, xml);",
            "    PhysicalModel copy = new PhysicalModel(1000, 50);",
            "    ModelXml.load(xml, copy);",
            "    return m.getStepCount() + \" \" + m.getNumberOfMats() + \" \" + m.getNumberOfLinks() + \" \"",
            "        + p.y + \" \" + v.isFinite() + \" \" + f.isFinite() + \" \" + m.getLinkStiffness(\"s1\") + \" \"",
            "        + m.getParamValueOfSubset(\"springs\", \"stiffness\") + \" \" + m.getGravityDirection().y + \" \"",
            "        + copy.getNumberOfMats() + \" \" + m.getStabilityReport().isStable();",
            "  }",
            "}");

    @Test
    void aProgramWithoutProcessingCoreBuildsStepsAndReadsAModel() throws Exception {
        assertEquals(List.of(), compileDiagnostics("PVectorCall", "public class PVectorCall { public static void call()"
                + " { new tactus.Vect3D(1, 2, 3).toPVector(); } }", System.getProperty("java.class.path")),
                "a PVector call compiles with core");
        List<String> errors = compileDiagnostics("PlainApp", PROGRAM);
        assertEquals(List.of(), errors, "the plain-Java program must compile without Processing core");
        try (URLClassLoader loader = plainLoader()) {
            assertThrows(ClassNotFoundException.class, () -> loader.loadClass("processing.core.PVector"),
                    "the program's class path must not hold Processing core");
            assertThrows(ClassNotFoundException.class, () -> loader.loadClass("ddf.minim.UGen"),
                    "the program's class path must not hold Minim");
            Class<?> app = loader.loadClass("PlainApp");
            String[] out = ((String) app.getMethod("run", String.class).invoke(null, dir.toString())).split(" ");
            assertEquals("200", out[0], "steps");
            assertEquals("3", out[1], "masses");
            assertEquals("2", out[2], "links");
            double y = Double.parseDouble(out[3]);
            assertTrue(Double.isFinite(y) && y != 2.0, "the mass moved: y = " + y);
            assertEquals("true", out[4]);
            assertEquals("true", out[5]);
            assertEquals(0.02, Double.parseDouble(out[6]), 1e-12, "the subset call set the stiffness");
            assertEquals(0.02, Double.parseDouble(out[7]), 1e-12, "the subset read");
            assertEquals(1.0, Double.parseDouble(out[8]), 1e-12, "gravity direction (0, 1, 0)");
            assertEquals("3", out[9], "the model read back from its XML file");
            assertEquals("true", out[10], "stable");

            // A sketch's PVector call (compiled with core) run without core says what to use instead.
            Class<?> sketch = loader.loadClass("PVectorCall");
            java.lang.reflect.InvocationTargetException e = assertThrows(
                    java.lang.reflect.InvocationTargetException.class, () -> sketch.getMethod("call").invoke(null));
            String msg = e.getCause().getMessage();
            assertTrue(e.getCause() instanceof IllegalStateException, String.valueOf(e.getCause()));
            assertTrue(msg.contains("Processing core") && msg.contains("getMatPosition(name)"), msg);
        }
    }

    /** A PhyUGen made without Minim on the class path: the message names Minim and how to add it. */
    @Test
    void aPhyUGenWithoutMinimNamesMinim() throws Exception {
        assertEquals(List.of(), compileDiagnostics("MinimCall", "public class MinimCall { public static void call() {"
                + " tactus.audio.AudioLibrary.newPhyUGen(new tactus.PhysicalModel(44100, 50)); } }",
                System.getProperty("java.class.path")), "the call compiles with Minim");
        try (URLClassLoader loader = plainLoader()) {
            Class<?> call = loader.loadClass("MinimCall");
            java.lang.reflect.InvocationTargetException e = assertThrows(
                    java.lang.reflect.InvocationTargetException.class, () -> call.getMethod("call").invoke(null));
            assertTrue(e.getCause() instanceof IllegalStateException, String.valueOf(e.getCause()));
            String msg = e.getCause().getMessage();
            assertTrue(msg.contains("new PhyUGen(model) needs Minim") && msg.contains("ddf.minim.UGen was not found")
                    && msg.contains("net.compartmental.code:minim:2.2.2"), msg);
        }
        // With Minim (the test's own class path) the same call makes the UGen.
        assertTrue(tactus.audio.AudioLibrary.isMinimPresent());
        assertEquals("tactus.audio.PhyUGen", tactus.audio.AudioLibrary.newPhyUGen(new PhysicalModel(44100, 50))
                .getClass().getName());
    }

    /**
     * Every public method of PhysicalModel without a Processing type in its signature is called once in a generated
     * program (never run); javac without core refuses exactly the calls listed in docs/plain-java.md.
     */
    @Test
    void everyModelCallCompilesWithoutCoreExceptTheDocumentedOverload() throws Exception {
        StringBuilder src = new StringBuilder("public class EveryCall {\n  static void all(tactus.PhysicalModel m)"
                + " throws Exception {\n");
        List<String> lines = new ArrayList<>();
        for (Method method : PhysicalModel.class.getMethods()) {
            if (method.getDeclaringClass() != PhysicalModel.class || Modifier.isStatic(method.getModifiers())
                    || mentionsProcessing(method)) {
                continue;
            }
            StringBuilder call = new StringBuilder("    m.").append(method.getName()).append('(');
            Parameter[] ps = method.getParameters();
            for (int i = 0; i < ps.length; i++) {
                call.append(i > 0 ? ", " : "").append(argument(ps[i].getType()));
            }
            call.append(");");
            src.append(call).append('\n');
            lines.add(method.getName() + Arrays.toString(method.getParameterTypes()));
        }
        src.append("  }\n}\n");
        assertTrue(lines.size() > 150, "methods found: " + lines.size());
        Set<String> refused = new TreeSet<>();
        for (String error : compileDiagnostics("EveryCall", src.toString())) {
            int line = Integer.parseInt(error.substring(0, error.indexOf(':')));
            refused.add(lines.get(line - 3));
        }
        assertEquals(Set.of("setGravityDirection[class tactus.Vect3D]"), refused,
                "the calls javac refuses without Processing core (docs/plain-java.md lists them)");
    }

    private static boolean mentionsProcessing(Method m) {
        return m.toGenericString().contains("processing.");
    }

    private static String argument(Class<?> t) {
        if (t == boolean.class) {
            return "false";
        }
        if (t.isPrimitive()) {
            return "(" + t.getName() + ") 0";
        }
        return "(" + t.getCanonicalName() + ") null";
    }

    /** @return "line: message" for each error javac reports on the source, compiled against the plain class path. */
    private List<String> compileDiagnostics(String name, String source) throws Exception {
        return compileDiagnostics(name, source, plainClassPath());
    }

    private List<String> compileDiagnostics(String name, String source, String classPath) throws Exception {
        Path file = dir.resolve(name + ".java");
        Files.write(file, source.getBytes(StandardCharsets.UTF_8));
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        DiagnosticCollector<JavaFileObject> diags = new DiagnosticCollector<>();
        try (StandardJavaFileManager fm = javac.getStandardFileManager(diags, null, StandardCharsets.UTF_8)) {
            List<String> options = List.of("-d", dir.toString(), "-classpath", classPath, "-proc:none",
                    "--release", "17");
            javac.getTask(new StringWriter(), fm, diags, options, null,
                    fm.getJavaFileObjects(file.toFile())).call();
        }
        List<String> errors = new ArrayList<>();
        for (Diagnostic<? extends JavaFileObject> d : diags.getDiagnostics()) {
            if (d.getKind() == Diagnostic.Kind.ERROR) {
                errors.add(d.getLineNumber() + ": " + d.getMessage(null));
            }
        }
        return errors;
    }

    /** Tactus's main classes, jackson-core and jSerialComm: what the jar and its bundled dependencies hold. */
    private static List<File> plainEntries() throws Exception {
        List<File> entries = new ArrayList<>();
        for (Class<?> c : new Class<?>[] {PhysicalModel.class, com.fasterxml.jackson.core.JsonFactory.class,
                com.fazecast.jSerialComm.SerialPort.class}) {
            entries.add(new File(c.getProtectionDomain().getCodeSource().getLocation().toURI()));
        }
        return entries;
    }

    private static String plainClassPath() throws Exception {
        StringBuilder sb = new StringBuilder();
        for (File f : plainEntries()) {
            sb.append(sb.length() > 0 ? File.pathSeparator : "").append(f.getPath());
        }
        return sb.toString();
    }

    private URLClassLoader plainLoader() throws Exception {
        List<URL> urls = new ArrayList<>();
        urls.add(dir.toUri().toURL());
        for (File f : plainEntries()) {
            urls.add(f.toURI().toURL());
        }
        return new URLClassLoader(urls.toArray(new URL[0]), ClassLoader.getPlatformClassLoader());
    }
}
