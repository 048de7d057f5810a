package tactus.sketch;

import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.File;
import java.io.IOException;
import java.io.InputStream;
import java.io.StringWriter;
import java.io.UncheckedIOException;
import java.io.Writer;
import java.lang.invoke.MethodHandle;
import java.lang.invoke.MethodHandles;
import java.lang.invoke.MethodType;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import javax.imageio.ImageIO;
import javax.tools.Diagnostic;
import javax.tools.DiagnosticCollector;
import javax.tools.JavaCompiler;
import javax.tools.JavaFileObject;
import javax.tools.StandardJavaFileManager;
import javax.tools.ToolProvider;

/**
 * Runs Processing sketches the way the Processing editor does, for tests: the {@code .pde} tabs are joined and
 * turned into Java by the editor's own preprocessor ({@code org.processing:preprocessor}), compiled with
 * {@link JavaCompiler} against the built library, Processing core and Minim, then run in a child JVM under Xvfb
 * ({@code xvfb-run -a}) for a given number of frames by {@link SketchRunner}, which saves the last frame as PNG.
 *
 * <p>Every step fails with an {@link AssertionError} whose message says what went wrong and shows the evidence:
 * the preprocessor's issues, the compiler's diagnostics with the generated line, or the sketch's exit code and
 * standard error. A missing preprocessor, {@code xvfb-run} or {@code xauth} is a failure, not a reason to skip.
 *
 * <p>The classpath a sketch is compiled and run against is read from the system property
 * {@value #CLASSPATH_PROPERTY} (set by {@code gradle test}); the folder for the generated files from
 * {@value #OUTPUT_PROPERTY} (default: a temporary folder).
 */
public final class SketchHarness {

    /** System property: the classpath of a sketch (library classes and jars, Processing core, Minim). */
    public static final String CLASSPATH_PROPERTY = "tactus.sketch.classpath";
    /** System property: the folder where each sketch's generated Java, classes, frame and logs go. */
    public static final String OUTPUT_PROPERTY = "tactus.sketch.output";
    /** What {@link SketchRunner} prints on standard output when the last frame has been saved. */
    static final String DONE_MARKER = "tactus-sketch-runner: frames=";
    /** What {@link SketchRunner} prints on standard output just before it ends the JVM with that status. */
    static final String STATUS_MARKER = "tactus-sketch-runner: status=";

    private static final String PREPROCESSOR = "processing.mode.java.preproc.PdePreprocessor";
    private static final Pattern PROBLEM = Pattern.compile("(?m)^.*(Exception|Error\\b).*$|^\\s+at \\S+\\(.*\\)$");

    private SketchHarness() {
    }

    // ============================================================================================ discovery

    /**
     * Finds every sketch below a folder: a sketch is a folder {@code Name} that holds {@code Name.pde}, at any
     * depth (for example {@code examples/Basics/HelloFigure4/HelloFigure4.pde}).
     *
     * @param root the folder to search
     * @return the sketch folders, sorted by path
     */
    public static List<Path> findSketches(Path root) {
        if (!Files.isDirectory(root)) {
            throw new AssertionError("no sketch folder " + root.toAbsolutePath());
        }
        try (Stream<Path> s = Files.walk(root)) {
            return s.filter(Files::isDirectory)
                    .filter(d -> d.getFileName() != null
                            && Files.isRegularFile(d.resolve(d.getFileName() + ".pde")))
                    .sorted()
                    .collect(Collectors.toList());
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    // ========================================================================================= preprocessing

    /** The Java code the preprocessor made from a sketch. */
    public static final class JavaSketch {
        /** The name of the sketch and of its public class. */
        public final String className;
        /** The generated Java source of the whole sketch. */
        public final String source;

        JavaSketch(String className, String source) {
            this.className = className;
            this.source = source;
        }
    }

    /**
     * Joins a sketch's tabs as the editor does (the main tab first, then the others in name order) and runs them
     * through Processing's preprocessor.
     *
     * @param sketchDir the sketch folder
     * @return the generated Java
     * @throws AssertionError if the preprocessor is not on the classpath or reports problems
     */
    public static JavaSketch preprocess(Path sketchDir) {
        String name = sketchDir.getFileName().toString();
        StringBuilder code = new StringBuilder();
        try (Stream<Path> s = Files.list(sketchDir)) {
            List<Path> tabs = s.filter(p -> p.getFileName().toString().endsWith(".pde")).sorted(
                    Comparator.comparing((Path p) -> !p.getFileName().toString().equals(name + ".pde"))
                            .thenComparing(p -> p.getFileName().toString()))
                    .collect(Collectors.toList());
            for (Path tab : tabs) {
                code.append(new String(Files.readAllBytes(tab), StandardCharsets.UTF_8)).append('\n');
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return preprocess(name, code.toString());
    }

    /**
     * Runs Processing code through the editor's preprocessor.
     *
     * @param className the sketch name, which becomes the class name
     * @param pdeCode   the code of all tabs
     * @return the generated Java
     * @throws AssertionError if the preprocessor is not on the classpath or reports problems
     */
    public static JavaSketch preprocess(String className, String pdeCode) {
        requirePreprocessor();
        return Preprocessor.run(className, pdeCode);
    }

    /**
     * Fails unless Processing's preprocessor can be loaded.
     *
     * @throws AssertionError naming the missing artifact
     */
    public static void requirePreprocessor() {
        try {
            Class.forName(PREPROCESSOR, false, SketchHarness.class.getClassLoader());
        } catch (ClassNotFoundException | LinkageError e) {
            throw new AssertionError("Processing's preprocessor (" + PREPROCESSOR + ", Maven artifact "
                    + "org.processing:preprocessor:4.5.7) is not on the test classpath; the sketch tests need it", e);
        }
    }

    /**
     * The calls into the preprocessor, in their own class so that nothing of it is loaded before
     * {@link #requirePreprocessor()} has checked that it is there.
     */
    private static final class Preprocessor {
        static JavaSketch run(String className, String pdeCode) {
            // The tab size would otherwise be read from the editor's preferences.txt (editor.tabs.size, 2 by default).
            processing.mode.java.preproc.PdePreprocessor pre =
                    processing.mode.java.preproc.PdePreprocessor.builderFor(className).setTabSize(2).build();
            StringWriter out = new StringWriter();
            processing.mode.java.preproc.PreprocessorResult result;
            try {
                // write(...) declares 'throws processing.utils.SketchException', a class of org.processing:utils,
                // which is not on Maven Central and not on our classpath. A method handle calls it without javac
                // or reflection ever needing that class; it is never thrown by the preprocessor itself.
                MethodHandle write = MethodHandles.publicLookup().findVirtual(pre.getClass(), "write",
                        MethodType.methodType(processing.mode.java.preproc.PreprocessorResult.class, Writer.class,
                                String.class));
                result = (processing.mode.java.preproc.PreprocessorResult) write.invoke(pre, out, pdeCode);
            } catch (RuntimeException | Error e) {
                throw e;
            } catch (Throwable t) {
                throw new AssertionError("the preprocessor failed on " + className + ": " + t, t);
            }
            List<processing.mode.java.preproc.PdePreprocessIssue> issues = result.getPreprocessIssues();
            if (!issues.isEmpty()) {
                String[] lines = pdeCode.split("\n", -1);
                StringBuilder m = new StringBuilder("the Processing preprocessor rejects " + className + ":");
                for (processing.mode.java.preproc.PdePreprocessIssue i : issues) {
                    int line = i.getLine();
                    m.append("\n  line ").append(line).append(": ").append(i.getMsg());
                    if (line >= 1 && line <= lines.length) {
                        m.append("\n    | ").append(lines[line - 1]);
                    }
                }
                throw new AssertionError(m.toString());
            }
            return new JavaSketch(result.getClassName() == null ? className : result.getClassName(),
                    out.toString());
        }
    }

    // =========================================================================================== compiling

    /**
     * The classpath sketches are compiled and run against, from {@value #CLASSPATH_PROPERTY}.
     *
     * @return the classpath
     * @throws AssertionError if the property is not set
     */
    public static String sketchClasspath() {
        String cp = System.getProperty(CLASSPATH_PROPERTY);
        if (cp == null || cp.isEmpty()) {
            throw new AssertionError("system property " + CLASSPATH_PROPERTY + " is not set; it lists the library "
                    + "classes, Processing core and Minim that sketches compile against (gradle test sets it)");
        }
        return cp;
    }

    /**
     * Compiles a preprocessed sketch.
     *
     * @param sketch    the generated Java
     * @param workDir   the folder for the source ({@code java/}) and the classes ({@code classes/})
     * @param classpath what the sketch compiles against
     * @return the folder of the compiled classes
     * @throws AssertionError with the compiler's diagnostics if it does not compile
     */
    public static Path compile(JavaSketch sketch, Path workDir, String classpath) {
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        if (javac == null) {
            throw new AssertionError("no Java compiler in " + System.getProperty("java.home")
                    + " (a JDK is needed, not a JRE)");
        }
        try {
            Path srcDir = Files.createDirectories(workDir.resolve("java"));
            Path classes = Files.createDirectories(workDir.resolve("classes"));
            Path src = srcDir.resolve(sketch.className + ".java");
            Files.write(src, sketch.source.getBytes(StandardCharsets.UTF_8));
            DiagnosticCollector<JavaFileObject> diagnostics = new DiagnosticCollector<>();
            try (StandardJavaFileManager files = javac.getStandardFileManager(diagnostics, Locale.ROOT,
                    StandardCharsets.UTF_8)) {
                List<String> options = List.of("-d", classes.toString(), "-classpath", classpath,
                        "-encoding", "UTF-8", "--release", "17", "-nowarn", "-proc:none");
                boolean ok = javac.getTask(null, files, diagnostics, options, null,
                        files.getJavaFileObjects(src.toFile())).call();
                if (!ok) {
                    String[] lines = sketch.source.split("\n", -1);
                    StringBuilder m = new StringBuilder(sketch.className + " does not compile (generated source "
                            + src + "):");
                    for (Diagnostic<? extends JavaFileObject> d : diagnostics.getDiagnostics()) {
                        if (d.getKind() != Diagnostic.Kind.ERROR) {
                            continue;
                        }
                        m.append("\n  line ").append(d.getLineNumber()).append(": ")
                                .append(d.getMessage(Locale.ROOT));
                        long l = d.getLineNumber();
                        if (l >= 1 && l <= lines.length) {
                            m.append("\n    | ").append(lines[(int) l - 1]);
                        }
                    }
                    throw new AssertionError(m.toString());
                }
            }
            return classes;
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    // ============================================================================================= running

    /** What one run of a sketch produced. */
    public static final class Run {
        /** The sketch's class name. */
        public final String sketch;
        /**
         * The exit status of the sketch's JVM, as {@link SketchRunner} reported it; if it reported none, the exit
         * code of {@code xvfb-run} (which passes on the JVM's, or gives its own errors, such as 5 when it cannot
         * remove its temporary folder).
         */
        public final int exitCode;
        /** The exit code of the {@code xvfb-run} process itself. */
        public final int processExitCode;
        /** The number of frames the runner reported, or -1 if it reported none. */
        public final int frames;
        /** The saved frame, or {@code null} if none was saved. */
        public final BufferedImage image;
        /** The standard output of the sketch. */
        public final String stdout;
        /** The standard error of the sketch. */
        public final String stderr;
        /** Wall-clock time of the run, in seconds. */
        public final double seconds;

        Run(String sketch, int exitCode, int processExitCode, int frames, BufferedImage image, String stdout,
                String stderr, double seconds) {
            this.sketch = sketch;
            this.exitCode = exitCode;
            this.processExitCode = processExitCode;
            this.frames = frames;
            this.image = image;
            this.stdout = stdout;
            this.stderr = stderr;
            this.seconds = seconds;
        }

        /** @return the standard error and output, for failure messages */
        public String logs() {
            return "--- status " + exitCode + " (xvfb-run exit code " + processExitCode + "), stderr of " + sketch
                    + " ---\n" + stderr + "\n--- stdout of " + sketch + " ---\n"
                    + (stdout.length() > 4000 ? stdout.substring(stdout.length() - 4000) : stdout);
        }
    }

    /**
     * Fails unless {@code xvfb-run} and {@code xauth} (which it needs) are on the {@code PATH}.
     *
     * @return the path of {@code xvfb-run}
     * @throws AssertionError naming the missing program and its Debian package
     */
    public static Path requireXvfb() {
        return requireXvfb(System.getenv("PATH"));
    }

    /**
     * Fails unless {@code xvfb-run} and {@code xauth} are in one of the folders of a search path.
     *
     * @param searchPath folders separated by {@link File#pathSeparator}, like {@code PATH}
     * @return the path of {@code xvfb-run}
     * @throws AssertionError naming the missing program and its Debian package
     */
    static Path requireXvfb(String searchPath) {
        Path xvfbRun = onPath("xvfb-run", searchPath);
        if (xvfbRun == null) {
            throw new AssertionError("xvfb-run is not on the PATH; the sketch tests run sketches under Xvfb and do "
                    + "not skip without it (Debian: apt-get install xvfb xauth; .ci/run installs them)");
        }
        if (onPath("xauth", searchPath) == null) {
            throw new AssertionError("xauth is not on the PATH; xvfb-run needs it (Debian: apt-get install xauth)");
        }
        return xvfbRun;
    }

    private static Path onPath(String program, String path) {
        if (path == null) {
            return null;
        }
        for (String dir : path.split(File.pathSeparator)) {
            Path p = Paths.get(dir.isEmpty() ? "." : dir, program);
            if (Files.isRegularFile(p) && Files.isExecutable(p)) {
                return p;
            }
        }
        return null;
    }

    /**
     * Runs a compiled sketch in a child JVM under Xvfb until it has drawn {@code frames} frames, saves the last
     * one as {@code png}, and returns what happened. The child is killed, with everything it started, after
     * {@code timeoutSeconds}.
     *
     * @param className      the sketch class
     * @param classes        the folder of the compiled sketch
     * @param classpath      the library classpath
     * @param frames         frames to draw (at least 1)
     * @param png            where to save the last frame
     * @param timeoutSeconds the longest the run may take
     * @return the run's results
     * @throws AssertionError if Xvfb is missing or the run times out (with the sketch's logs)
     */
    public static Run run(String className, Path classes, String classpath, int frames, Path png,
            double timeoutSeconds) {
        return run(className, classes, classpath, frames, png, timeoutSeconds, null, Map.of());
    }

    /**
     * Runs a compiled sketch as {@link #run(String, Path, String, int, Path, double)} does, with a sketch folder
     * and system properties for the child JVM. The sketch folder is what the sketch's {@code sketchPath()} and
     * {@code dataPath()} use, as the editor passes it with {@code --sketch-path}. The runner also saves the frame
     * at half the frame count, beside {@code png} as {@code <name>-mid.png} ({@link #midFramePath}).
     *
     * @param className      the sketch class
     * @param classes        the folder of the compiled sketch
     * @param classpath      the library classpath
     * @param frames         frames to draw (at least 2)
     * @param png            where to save the last frame
     * @param timeoutSeconds the longest the run may take
     * @param sketchPath     the sketch folder, or null for the JVM's working folder
     * @param properties     system properties for the child JVM ({@code -Dkey=value})
     * @return the run's results
     * @throws AssertionError if Xvfb is missing or the run times out (with the sketch's logs)
     */
    public static Run run(String className, Path classes, String classpath, int frames, Path png,
            double timeoutSeconds, Path sketchPath, Map<String, String> properties) {
        Path xvfbRun = requireXvfb();
        String runnerLocation = location(SketchRunner.class);
        String java = Paths.get(System.getProperty("java.home"), "bin", "java").toString();
        // xvfb-run waits for Xvfb's SIGUSR1, which a shell cannot catch when it starts with SIGUSR1 ignored, as
        // children of this JVM do once a native library (jSerialComm) has set it to ignored: reset it first.
        List<String> cmd = new ArrayList<>(List.of("env", "--default-signal=USR1", xvfbRun.toString(), "-a", "-s",
                "-screen 0 1280x1024x24",
                java, "-Xmx512m", "-Dfile.encoding=UTF-8"));
        properties.forEach((k, v) -> cmd.add("-D" + k + "=" + v));
        cmd.addAll(List.of("-cp", classes + File.pathSeparator + runnerLocation + File.pathSeparator + classpath,
                SketchRunner.class.getName(), className, Integer.toString(frames), png.toString()));
        if (sketchPath != null) {
            cmd.add(sketchPath.toAbsolutePath().toString());
        }
        try {
            Files.createDirectories(png.toAbsolutePath().getParent());
            Files.deleteIfExists(png);
            Files.deleteIfExists(midFramePath(png));
            Run r = runOnce(className, cmd, png, timeoutSeconds);
            // xvfb-run -a can race with another xvfb-run started at the same moment for the same display number.
            if (r.exitCode != 0 && r.stderr.contains("Xvfb failed to start")) {
                r = runOnce(className, cmd, png, timeoutSeconds);
            }
            return r;
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    private static Run runOnce(String className, List<String> cmd, Path png, double timeoutSeconds)
            throws IOException {
        long start = System.nanoTime();
        ProcessBuilder pb = new ProcessBuilder(cmd);
        // xvfb-run keeps its X authority file in a folder of its own under TMPDIR: put it beside the frame, away
        // from whatever else cleans /tmp.
        pb.environment().put("TMPDIR", png.toAbsolutePath().getParent().toString());
        Process p = pb.start();
        p.getOutputStream().close();
        Drain out = new Drain(p.getInputStream());
        Drain err = new Drain(p.getErrorStream());
        boolean finished;
        try {
            finished = p.waitFor((long) (timeoutSeconds * 1000), TimeUnit.MILLISECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            finished = false;
        }
        if (!finished) {
            kill(p);
        }
        String stdout = out.text();
        String stderr = err.text();
        double seconds = (System.nanoTime() - start) * 1e-9;
        if (!finished) {
            throw new AssertionError(String.format(Locale.ROOT, "%s did not finish within %.0f s and was killed",
                    className, timeoutSeconds) + "\n" + new Run(className, -1, -1, -1, null, stdout, stderr, seconds)
                    .logs());
        }
        int frames = marker(stdout, DONE_MARKER, -1);
        int status = marker(stdout, STATUS_MARKER, p.exitValue());
        BufferedImage image = Files.isRegularFile(png) ? ImageIO.read(png.toFile()) : null;
        return new Run(className, status, p.exitValue(), frames, image, stdout, stderr, seconds);
    }

    private static int marker(String stdout, String marker, int otherwise) {
        Matcher m = Pattern.compile(Pattern.quote(marker) + "(\\d+)").matcher(stdout);
        return m.find() ? Integer.parseInt(m.group(1)) : otherwise;
    }

    /** Kills a process and everything it started (xvfb-run starts Xvfb and the JVM). */
    private static void kill(Process p) {
        List<ProcessHandle> all = p.descendants().collect(Collectors.toList());
        all.forEach(ProcessHandle::destroyForcibly);
        p.destroyForcibly();
        try {
            p.waitFor(5, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    private static String location(Class<?> c) {
        try {
            return Paths.get(c.getProtectionDomain().getCodeSource().getLocation().toURI()).toString();
        } catch (Exception e) {
            throw new AssertionError("cannot locate the classes of " + c.getName(), e);
        }
    }

    /** Reads a stream to the end on its own thread, so that a chatty child never blocks on a full pipe. */
    private static final class Drain {
        private final ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        private final Thread thread;

        Drain(InputStream in) {
            thread = new Thread(() -> {
                byte[] b = new byte[8192];
                try (InputStream s = in) {
                    for (int n; (n = s.read(b)) >= 0; ) {
                        synchronized (bytes) {
                            bytes.write(b, 0, n);
                        }
                    }
                } catch (IOException ignored) {
                    // the process was killed: keep what was read
                }
            }, "sketch-output");
            thread.setDaemon(true);
            thread.start();
        }

        String text() {
            try {
                thread.join(2000);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
            synchronized (bytes) {
                return bytes.toString(StandardCharsets.UTF_8);
            }
        }
    }

    // ============================================================================================ checking

    /**
     * The standard deviation of the luminance (0 to 255) over all pixels: 0 for a blank, single-colour image.
     *
     * @param img the image
     * @return the standard deviation
     */
    public static double luminanceSpread(BufferedImage img) {
        double sum = 0;
        double sum2 = 0;
        long n = (long) img.getWidth() * img.getHeight();
        for (int y = 0; y < img.getHeight(); y++) {
            for (int x = 0; x < img.getWidth(); x++) {
                int rgb = img.getRGB(x, y);
                double l = 0.2126 * ((rgb >> 16) & 0xFF) + 0.7152 * ((rgb >> 8) & 0xFF) + 0.0722 * (rgb & 0xFF);
                sum += l;
                sum2 += l * l;
            }
        }
        double mean = sum / n;
        return Math.sqrt(Math.max(0, sum2 / n - mean * mean));
    }

    /**
     * Checks a run: exit code 0, nothing that looks like an exception on standard error, the frame count reached,
     * and a saved frame that is not blank.
     *
     * @param r      the run
     * @param frames the frames asked for
     * @throws AssertionError saying which check failed, with the sketch's logs
     */
    public static void check(Run r, int frames) {
        if (r.exitCode != 0) {
            throw new AssertionError(r.sketch + " exited with code " + r.exitCode + "\n" + r.logs());
        }
        Matcher problem = PROBLEM.matcher(r.stderr);
        if (problem.find()) {
            throw new AssertionError(r.sketch + " reported a problem on standard error: " + problem.group().trim()
                    + "\n" + r.logs());
        }
        if (r.frames != frames) {
            throw new AssertionError(r.sketch + " reported " + r.frames + " frames instead of " + frames + "\n"
                    + r.logs());
        }
        if (r.image == null) {
            throw new AssertionError(r.sketch + " saved no frame\n" + r.logs());
        }
        double spread = luminanceSpread(r.image);
        if (spread < 1.0) {
            throw new AssertionError(String.format(Locale.ROOT,
                    "%s drew a blank frame (luminance spread %.3f of 255)", r.sketch, spread) + "\n" + r.logs());
        }
    }

    /**
     * Where {@link SketchRunner} saves the frame drawn at half the frame count: beside the last frame, with
     * {@code -mid} before the extension.
     *
     * @param png the last frame's file
     * @return the mid frame's file
     */
    public static Path midFramePath(Path png) {
        String name = png.getFileName().toString();
        int dot = name.lastIndexOf('.');
        String mid = dot < 0 ? name + "-mid" : name.substring(0, dot) + "-mid" + name.substring(dot);
        return png.resolveSibling(mid);
    }

    /**
     * The folder for a sketch's generated files: {@value #OUTPUT_PROPERTY}/{@code name}, or a new temporary
     * folder.
     *
     * @param name the sketch name
     * @return the folder (created)
     */
    public static Path workDir(String name) {
        try {
            String base = System.getProperty(OUTPUT_PROPERTY);
            if (base == null || base.isEmpty()) {
                return Files.createTempDirectory("sketch-" + name);
            }
            return Files.createDirectories(Paths.get(base, name));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
