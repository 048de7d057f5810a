package tactus.bench;

import java.io.BufferedReader;
import java.io.File;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Paths;
import java.text.SimpleDateFormat;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Date;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TimeZone;
import java.util.concurrent.TimeUnit;
import javax.tools.JavaCompiler;
import javax.tools.ToolProvider;
import tactus.bench.paper.PaperScenes;

/**
 * The side-by-side part of {@code gradle bench}: the scenes of {@link PaperScenes}, written once against the paper's
 * API, timed on the paper's engine and on Tactus in forked JVMs with the same flags, alternating the engines
 * (round 1 paper then Tactus, round 2 Tactus then paper, ...), and the paired ratio of each round. Writes its section
 * of {@code docs/performance.md} (see {@link SideBySideReport}) in place, leaving the rest of the page as it is.
 *
 * <p>The paper's engine is GPL and not vendored: give the path of a {@code miPhysics.jar} built from the authors'
 * repository (docs/performance.md says how). This class then copies {@code PaperScenes.java} with its engine import
 * line {@value #TACTUS_IMPORT} replaced by {@value #PAPER_IMPORT} (the only change) and compiles the copy against
 * that jar and Processing core. Without a jar, Tactus is measured alone and the report says "not compared".
 *
 * <p>Usage: {@code tactus.bench.SideBySide [out.md] --source=<PaperScenes.java> [--miphysics=<jar>] [--work=<dir>]
 * [--quick] [--rounds=N] [--scenes=id,id]}.
 */
public final class SideBySide {
    /** The engine import line of the shared source, as written (Tactus). */
    static final String TACTUS_IMPORT = "import tactus.*;";
    /** What the build puts in its place for the paper's engine. */
    static final String PAPER_IMPORT = "import miPhysics.*;";
    static final String[] FLAGS = {"-Xms2g", "-Xmx2g", "-XX:+UseParallelGC", "-Djava.awt.headless=true",
        "-Dfile.encoding=UTF-8"};
    static final int CHILD_TIMEOUT_S = 300;

    private SideBySide() {
    }

    /**
     * Runs the side-by-side benchmark.
     *
     * @param args see the class comment
     */
    public static void main(String[] args) throws Exception {
        String out = "docs/performance.md";
        Options o = new Options();
        for (String a : args) {
            if (!o.parse(a)) {
                out = a;
            }
        }
        run(new File(out), o);
    }

    /** The options of a run. */
    static final class Options {
        String source;
        String miPhysicsJar;
        String work = "build/paperbench";
        boolean quick;
        int rounds = -1;
        List<String> scenes = new ArrayList<>(Arrays.asList(PaperScenes.SCENES));

        /** @return false when the argument is not an option of this class */
        boolean parse(String a) {
            if (a.startsWith("--source=")) {
                source = a.substring(9);
            } else if (a.startsWith("--miphysics=")) {
                miPhysicsJar = a.substring(12).isEmpty() ? null : a.substring(12);
            } else if (a.startsWith("--work=")) {
                work = a.substring(7);
            } else if (a.equals("--quick")) {
                quick = true;
            } else if (a.startsWith("--rounds=")) {
                rounds = Integer.parseInt(a.substring(9));
            } else if (a.startsWith("--scenes=")) {
                scenes = new ArrayList<>(Arrays.asList(a.substring(9).split(",")));
                for (String s : scenes) {
                    if (!Arrays.asList(PaperScenes.SCENES).contains(s)) {
                        throw new IllegalArgumentException("unknown side-by-side scene " + s + "; scenes: "
                                + Arrays.toString(PaperScenes.SCENES));
                    }
                }
            } else {
                return false;
            }
            return true;
        }

        int rounds() {
            return rounds > 0 ? rounds : quick ? 3 : 5;
        }
    }

    // ================================================================================ the paper engine's build

    /**
     * The paper engine's copy of the shared source: the one line {@value #TACTUS_IMPORT} replaced by
     * {@value #PAPER_IMPORT}.
     *
     * @param source the text of PaperScenes.java
     * @return the copy
     * @throws IllegalArgumentException when the import line is not there exactly once
     */
    static String paperSource(String source) {
        String[] lines = source.split("\n", -1);
        int found = 0;
        for (int i = 0; i < lines.length; i++) {
            if (lines[i].trim().equals(TACTUS_IMPORT)) {
                lines[i] = PAPER_IMPORT;
                found++;
            }
        }
        if (found != 1) {
            throw new IllegalArgumentException("the shared scene source must have the line '" + TACTUS_IMPORT
                    + "' exactly once, found " + found);
        }
        return String.join("\n", lines);
    }

    /** @return the jar of Processing core on this JVM's class path (the paper's engine is compiled against it) */
    static String processingCore() {
        for (String e : System.getProperty("java.class.path").split(File.pathSeparator)) {
            if (e.endsWith(".jar") && new File(e).getName().startsWith("core-")) {
                return e;
            }
        }
        throw new IllegalStateException("Processing core (core-*.jar) is not on the class path; run through gradle bench");
    }

    /**
     * Copies the shared source with the paper engine's import and compiles it against the jar.
     *
     * @return the class path of the paper engine's children
     */
    static String buildPaper(Options o) throws IOException {
        File jar = new File(o.miPhysicsJar);
        if (!jar.isFile()) {
            throw new IllegalArgumentException("-PmiPhysicsJar: no such file " + jar.getAbsolutePath()
                    + " (docs/performance.md says how to build it)");
        }
        File src = new File(o.work, "src/tactus/bench/paper/PaperScenes.java");
        File classes = new File(o.work, "classes");
        src.getParentFile().mkdirs();
        classes.mkdirs();
        String text = new String(Files.readAllBytes(Paths.get(o.source)), StandardCharsets.UTF_8);
        Files.write(src.toPath(), paperSource(text).getBytes(StandardCharsets.UTF_8));
        String cp = jar.getAbsolutePath() + File.pathSeparator + processingCore();
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        if (javac == null) {
            throw new IllegalStateException("no Java compiler in this JVM: run gradle bench with a JDK, not a JRE");
        }
        int code = javac.run(null, null, null, "-nowarn", "-encoding", "UTF-8", "--release", "17", "-cp", cp, "-d",
                classes.getAbsolutePath(), src.getAbsolutePath());
        if (code != 0) {
            throw new IllegalStateException("the scene source did not compile against " + jar + " (javac exit " + code + ")");
        }
        System.out.println("SideBySide: compiled " + src + " against " + jar);
        return classes.getAbsolutePath() + File.pathSeparator + cp;
    }

    // ================================================================================ measuring

    /** One engine: a name, the class path of its children and the extra arguments they get. */
    static final class Engine {
        final String key;
        final String classPath;
        final String expectedClass;
        final List<String> extra;
        final Map<String, List<double[]>> rounds = new LinkedHashMap<>();
        final Map<String, List<double[]>> cpu = new LinkedHashMap<>();

        Engine(String key, String classPath, String expectedClass, String... extra) {
            this.key = key;
            this.classPath = classPath;
            this.expectedClass = expectedClass;
            this.extra = Arrays.asList(extra);
        }
    }

    static void run(File out, Options o) throws IOException, InterruptedException {
        if (o.source == null) {
            throw new IllegalArgumentException("--source=<path of tools/tactus/bench/paper/PaperScenes.java> is required");
        }
        long started = System.currentTimeMillis();
        String loadStart = Bench.loadavg();
        Engine tactus = new Engine("Tactus", System.getProperty("java.class.path"), "tactus.PhysicalModel",
                "--reader=snapshot", "--group");
        Engine paper = null;
        if (o.miPhysicsJar != null) {
            paper = new Engine("paper", buildPaper(o), "miPhysics.PhysicalModel", "--reader=lock");
        } else {
            System.out.println("SideBySide: no -PmiPhysicsJar given: Tactus only, the paper's engine is NOT COMPARED");
        }
        Map<String, String> elements = new LinkedHashMap<>();
        Map<String, String> problems = new LinkedHashMap<>();
        System.out.println("SideBySide: " + o.scenes + ", " + o.rounds() + " rounds" + (o.quick ? " (quick)" : "")
                + "; load at start: " + loadStart);
        for (String scene : o.scenes) {
            for (int r = 0; r < o.rounds(); r++) {
                List<Engine> order = new ArrayList<>();
                order.add(tactus);
                if (paper != null) {
                    order.add(r % 2 == 0 ? 0 : 1, paper);
                }
                for (Engine e : order) {
                    System.out.println(String.format(Locale.ROOT, "== %s, round %d/%d, %s", scene, r + 1, o.rounds(),
                            e.key));
                    fork(e, scene, o.quick, elements, problems);
                }
            }
        }
        String loadEnd = Bench.loadavg();
        long seconds = (System.currentTimeMillis() - started) / 1000;
        SideBySideReport report = new SideBySideReport(paper == null ? null : paper.rounds, tactus.rounds, elements,
                problems).withCpu(paper == null ? null : paper.cpu, tactus.cpu);
        String section = report.section(header(o, loadStart, loadEnd, seconds), method(o));
        System.out.println();
        System.out.println(report.table());
        System.out.println(report.verdictTable());
        System.out.println(report.readerTable());
        String old = out.isFile() ? new String(Files.readAllBytes(out.toPath()), StandardCharsets.UTF_8) : "";
        File parent = out.getAbsoluteFile().getParentFile();
        if (parent != null) {
            parent.mkdirs();
        }
        Files.write(out.toPath(), SideBySideReport.replaceSection(old, section).getBytes(StandardCharsets.UTF_8));
        System.out.println("SideBySide: wrote its section of " + out.getAbsolutePath() + " (" + seconds + " s)"
                + (paper == null ? "; paper's engine not compared (no -PmiPhysicsJar)" : ""));
    }

    /** Forks one child and files its results under the engine's rounds; a failure is recorded as a problem. */
    static void fork(Engine e, String scene, boolean quick, Map<String, String> elements, Map<String, String> problems)
            throws IOException, InterruptedException {
        List<String> cmd = new ArrayList<>();
        cmd.add(Paths.get(System.getProperty("java.home"), "bin", "java").toString());
        cmd.addAll(Arrays.asList(FLAGS));
        cmd.addAll(Arrays.asList("-cp", e.classPath, PaperScenes.class.getName(), scene));
        if (quick) {
            cmd.add("--quick");
        }
        cmd.addAll(e.extra);
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).start();
        Thread watchdog = new Thread(() -> {
            try {
                if (!p.waitFor(CHILD_TIMEOUT_S, TimeUnit.SECONDS)) {
                    p.destroyForcibly();
                }
            } catch (InterruptedException ie) {
                Thread.currentThread().interrupt();
            }
        }, "side-by-side-watchdog");
        watchdog.setDaemon(true);
        watchdog.start();
        List<Map<String, String>> results = new ArrayList<>();
        String engineClass = null;
        String last = "";
        try (BufferedReader in = new BufferedReader(new InputStreamReader(p.getInputStream(), StandardCharsets.UTF_8))) {
            String line;
            while ((line = in.readLine()) != null) {
                if (line.startsWith(PaperScenes.RESULT + "\t")) {
                    results.add(Bench.parse(line));
                } else if (line.startsWith(PaperScenes.INFO + "\t")) {
                    engineClass = Bench.parse(line).get("engine");
                    System.out.println("  " + line);
                } else {
                    System.out.println("  " + line);
                    last = line;
                }
            }
        }
        p.waitFor();
        String prefix = e.key.equals("paper") ? "paper:" : "";
        if (p.exitValue() != 0 || results.isEmpty() || !e.expectedClass.equals(engineClass)) {
            String why = p.exitValue() != 0 ? "child failed, exit " + p.exitValue() + ": " + last
                    : !e.expectedClass.equals(engineClass) ? "ran " + engineClass + ", expected " + e.expectedClass
                    : "no result";
            System.out.println("  FAILED: " + why);
            for (SideBySideReport.Row row : SideBySideReport.ROWS) {
                String key = e.key.equals("paper") ? row.paperKey : row.tactusKey;
                if (key.startsWith(scene + "/")) {
                    problems.put(prefix + key, "a child failed: " + why);
                }
            }
            return;
        }
        for (Map<String, String> m : results) {
            String key = scene + "/" + m.get("variant");
            e.rounds.computeIfAbsent(key, k -> new ArrayList<>()).add(Bench.splitArray(m.get("us")));
            e.cpu.computeIfAbsent(key, k -> new ArrayList<>()).add(Bench.splitArray(m.get("cpu")));
            long n = Long.parseLong(m.get("mats")) + Long.parseLong(m.get("links"));
            if (e.key.equals("Tactus")) {
                elements.put(key, String.format(Locale.ROOT, "%,d", n));
            }
            if (!"true".equals(m.get("finite"))) {
                problems.put(prefix + key, "non-finite positions");
            }
            System.out.println(String.format(Locale.ROOT, "  %s %s: %s µs per step, median of %s; %s reads", e.key,
                    key, fmt(SideBySideReport.median(Bench.splitArray(m.get("us")))), m.get("us"), m.get("reads")));
        }
    }

    private static String fmt(double x) {
        return String.format(Locale.ROOT, "%.2f", x);
    }

    // ================================================================================ report text

    static String cpuModel() {
        try {
            for (String l : Files.readAllLines(Paths.get("/proc/cpuinfo"), StandardCharsets.UTF_8)) {
                if (l.startsWith("model name")) {
                    return l.substring(l.indexOf(':') + 1).trim();
                }
            }
        } catch (IOException | RuntimeException e) {
            return "unknown";
        }
        return "unknown";
    }

    static String gitCommit() {
        try {
            Process p = new ProcessBuilder("git", "rev-parse", "--short", "HEAD").redirectErrorStream(true).start();
            String s = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8).trim();
            return p.waitFor() == 0 ? s : "unknown";
        } catch (IOException | InterruptedException e) {
            return "unknown";
        }
    }

    /**
     * @return true when the 1-minute load average in a {@link Bench#loadavg()} text is at least 1.5: the bench's own
     *         stepping thread accounts for about 1, so more means another program competed for the cores
     */
    static boolean busy(String load) {
        try {
            return Double.parseDouble(load.split(" ")[0]) >= 1.5;
        } catch (RuntimeException e) {
            return true;
        }
    }

    static String header(Options o, String loadStart, String loadEnd, long seconds) {
        SimpleDateFormat d = new SimpleDateFormat("yyyy-MM-dd HH:mm 'UTC'", Locale.ROOT);
        d.setTimeZone(TimeZone.getTimeZone("UTC"));
        StringBuilder sb = new StringBuilder();
        sb.append("Generated by `gradle bench` (`tactus.bench.SideBySide`, scenes in `tools/tactus/bench/paper/PaperScenes.java`) on ")
                .append(d.format(new Date())).append(", in ").append(seconds).append(" s")
                .append(o.quick ? ", quick mode" : "").append(". Tactus at commit ").append(gitCommit())
                .append("; the paper's engine: ")
                .append(o.miPhysicsJar == null ? "**not compared** (no `-PmiPhysicsJar` given)"
                        : "`" + new File(o.miPhysicsJar).getName() + "` (miPhysics, built from commit c29f407 as described below)")
                .append(".\n\n");
        if (busy(loadStart) || busy(loadEnd)) {
            sb.append("**Preliminary**: the machine was not quiet (1-minute load average ").append(loadStart.split(" ")[0])
                    .append(" at start, ").append(loadEnd.split(" ")[0]).append(" at end, on ")
                    .append(Runtime.getRuntime().availableProcessors())
                    .append(" cores): rerun on a quiet machine before quoting these figures.\n\n");
        }
        sb.append("Machine: ").append(cpuModel()).append(", ").append(Runtime.getRuntime().availableProcessors())
                .append(" cores; JDK ").append(System.getProperty("java.vm.vendor")).append(' ')
                .append(System.getProperty("java.runtime.version")).append("; child JVM flags `")
                .append(String.join(" ", Arrays.asList(FLAGS).subList(0, 3))).append("` for both engines; load average "
                + "(1, 5, 15 min) ").append(loadStart).append(" at start, ").append(loadEnd).append(" at end.\n\n");
        return sb.toString();
    }

    static String method(Options o) {
        return "Scenes (ALGO_UNITS, parameters per step): **string**, N Mass3D (M 1) between two Ground3D, N + 1 "
                + "SpringDamper3D (l0 0.08 at spacing 0.1, K 0.4, Z 0.001), friction 1e-5, plucked; **mesh**, 100×100 "
                + "nodes, the border Ground3D, a SpringDamper3D (l0 0.09, K 0.2, Z 0.001) to the right and lower "
                + "neighbours (none between two grounded nodes), gravity 1e-5, friction 1e-5, a Gaussian bump; "
                + "**marbles**, the authors' EnclosedMarbles without its haptic avatar: 200 Mass3D (M 7–10) at random "
                + "in [-1, 1]³ (fixed seed), gravity 5e-5, friction 1e-3, a Bubble3D per marble (R 3, K 0.1, Z 0.1) "
                + "to a Ground3D, a PlaneContact per marble (z = 0, K 0.01, Z 0.01), and one Contact3D per unordered "
                + "pair (threshold 0.2, K 0.02, Z 0.01; the sketch adds both orders) or one contact group. "
                + "**Elements** = `getNumberOfMats()` + `getNumberOfLinks()` (Ground3D included; the group row counts "
                + "the group as none).\n\n"
                + "Method: one source (`PaperScenes.java`) written against the paper's API; `SideBySide` compiles a copy "
                + "whose only change is its import line (`" + TACTUS_IMPORT + "` → `" + PAPER_IMPORT + "`) against the "
                + "paper's jar. Each scene runs in " + o.rounds() + " rounds; a round forks one JVM per engine (same "
                + "flags), the engine that goes first alternating from round to round. A child builds the scene, warms "
                + "it up (" + (o.quick ? "1.5" : "3") + " s per variant), then measures " + (o.quick ? 5 : 7)
                + " runs of about " + (o.quick ? "0.4" : "0.8") + " s per variant, its variants interleaved; a round's "
                + "figure is the median of its runs, the ratio paper / Tactus is taken per round (paired), and the "
                + "table gives the median and the min–max over the rounds. The marbles and the mesh are stepped by "
                + "one `computeStep()` per step, as the haptic thread of EnclosedMarbles does. **Reader**: a thread "
                + "reads what a renderer reads, 60 times per simulated second of the 1 kHz model (period = 1000/60 "
                + "steps × the wall time per step measured in the warm-up, so the reads per step are those of a "
                + "sketch drawing at 60 fps while the model runs in real time): on Tactus `getSnapshot()` and every "
                + "mass position and link (ends, elongation) of the snapshot; on the paper's engine, which has no "
                + "snapshot, what its `ModelRenderer` copies (every mass position, every link's end positions, "
                + "elongation and rest length) inside `synchronized (mdl.getLock())`, the stepping thread waiting meanwhile. The contact "
                + "group row compares Tactus's `addContactGroup` with the paper engine's one `Contact3D` per pair (it "
                + "has no group). CPU/wall below 100 % means that the stepping thread was descheduled (other load on the "
                + "machine) or, on the paper's engine with a reader, waiting for the lock. The verdicts use wall time when "
                + "the runs concerned were undisturbed (median CPU/wall at least 90 %), else the stepping thread's CPU "
                + "time (wall × CPU/wall), which other load hardly moves but which leaves out the paper engine's lock "
                + "waits (so, on the reader rows, it favours the paper's engine); each verdict says which. Every scene checks that all positions are finite at the end.\n";
    }
}
