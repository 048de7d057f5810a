package tactus.bench;

import java.io.BufferedReader;
import java.io.File;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.PrintStream;
import java.lang.management.ManagementFactory;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.function.Supplier;

/**
 * {@code gradle bench}: the performance benchmark of issue #4. Writes a Markdown report (docs/performance.md).
 *
 * <p>Usage: {@code java -cp <test classes, main classes, Processing core> tactus.bench.Bench [out.md] [options]}
 * <ul>
 *   <li>{@code out.md}: the report to write (default {@code docs/performance.md});</li>
 *   <li>{@code --quick}: shorter warm-up and runs (about a quarter of the time; for trying the harness);</li>
 *   <li>{@code --only=id,id}: run only these scenes (ids: see {@link Scenes#ids()});</li>
 *   <li>{@code --jdk=17|25|both}: which JDKs to run (default both; 17 means the running java);</li>
 *   <li>{@code --jdk25=/path/to/bin/java}: the second JDK (default
 *       {@value #JDK25});</li>
 *   <li>{@code --scenes=standard,paper,paper/<id>,faust,faust/<id>,<id>}: which parts run (see {@link Selection}; default all);</li>
 *   <li>{@code --paper-source=<PaperScenes.java>}, {@code --paper-miphysics=<jar>}, {@code --paper-work=<dir>},
 *       {@code --paper-rounds=N}: the side-by-side part against the paper's engine ({@link SideBySide}).</li>
 * </ul>
 *
 * <p>The parent process does no timing. It forks one child JVM per (scene, JDK) with the same classpath and
 * {@code -Xms2g -Xmx2g -XX:+UseParallelGC}; the child builds the scene, warms up, measures (see {@link Harness})
 * and prints one machine-readable {@code @@RESULT} line per variant, which the parent collects; every other line of
 * the child is progress and is relayed to stdout. A child that fails or hangs (timeout {@value #CHILD_TIMEOUT_S} s)
 * is reported as failed; the others still run.
 */
public final class Bench {
    static final String JDK25 = "/usr/lib/jvm/temurin-25-jdk-amd64/bin/java";
    static final int CHILD_TIMEOUT_S = 300;
    static final String RESULT = "@@RESULT";
    static final String INFO = "@@INFO";
    static final String SKIP = "@@SKIP";

    private Bench() {
    }

    public static void main(String[] args) throws Exception {
        if (args.length > 0 && args[0].equals("--child")) {
            child(Arrays.copyOfRange(args, 1, args.length));
            return;
        }
        String out = "docs/performance.md";
        boolean quick = false;
        List<String> only = null;
        String jdks = "both";
        String jdk25 = JDK25;
        SideBySide.Options side = new SideBySide.Options();
        Selection selection = new Selection(null);
        for (String a : args) {
            if (a.equals("--quick")) {
                quick = true;
                side.quick = true;
            } else if (a.startsWith("--only=")) {
                only = Arrays.asList(a.substring(7).split(","));
            } else if (a.startsWith("--jdk=")) {
                jdks = a.substring(6);
            } else if (a.startsWith("--jdk25=")) {
                jdk25 = a.substring(8);
            } else if (a.startsWith("--scenes=")) {
                selection = new Selection(a.substring(9));
            } else if (a.startsWith("--paper-")) {
                side.parse("--" + a.substring(8));
            } else if (a.startsWith("--")) {
                throw new IllegalArgumentException("unknown option " + a);
            } else {
                out = a;
            }
        }
        if (selection.standard) {
            new Parent(new File(out), quick, selection.only != null ? selection.only : only, jdks, jdk25).run();
        }
        if (selection.paper != null) {
            side.scenes = selection.paper;
            SideBySide.run(new File(out), side);
        }
        if (selection.faust != null) {
            FaustSideBySide.Options f = new FaustSideBySide.Options();
            f.quick = quick;
            f.models = selection.faust;
            FaustSideBySide.run(new File(out), f);
        }
    }

    /**
     * What {@code --scenes=} selects (Gradle: {@code -Pscenes=}): a comma-separated list of {@code standard} (every
     * scene of this class), {@code paper} (every side-by-side scene), {@code paper/<id>} (one side-by-side scene, see
     * {@link tactus.bench.paper.PaperScenes#SCENES}), {@code faust} (every model of the side by side with Faust),
     * {@code faust/<id>} (one, see {@link FaustSideBySide#MODELS}) and standard scene ids. Absent: everything.
     */
    static final class Selection {
        boolean standard;
        List<String> only;
        List<String> paper;
        /** The models of the side by side with Faust ({@link FaustSideBySide#MODELS}), or null. */
        List<String> faust;

        Selection(String spec) {
            if (spec == null || spec.isEmpty()) {
                standard = true;
                paper = new ArrayList<>(Arrays.asList(tactus.bench.paper.PaperScenes.SCENES));
                faust = new ArrayList<>(Arrays.asList(FaustSideBySide.MODELS));
                return;
            }
            for (String t : spec.split(",")) {
                if (t.equals("standard")) {
                    standard = true;
                } else if (t.equals("faust")) {
                    faust = new ArrayList<>(Arrays.asList(FaustSideBySide.MODELS));
                } else if (t.startsWith("faust/")) {
                    String id = t.substring(6);
                    if (!Arrays.asList(FaustSideBySide.MODELS).contains(id)) {
                        throw new IllegalArgumentException("unknown Faust side-by-side model " + id + "; models: "
                                + Arrays.toString(FaustSideBySide.MODELS));
                    }
                    if (faust == null) {
                        faust = new ArrayList<>();
                    }
                    faust.add(id);
                } else if (t.equals("paper")) {
                    paper = new ArrayList<>(Arrays.asList(tactus.bench.paper.PaperScenes.SCENES));
                } else if (t.startsWith("paper/")) {
                    String id = t.substring(6);
                    if (!Arrays.asList(tactus.bench.paper.PaperScenes.SCENES).contains(id)) {
                        throw new IllegalArgumentException("unknown side-by-side scene " + id + "; scenes: "
                                + Arrays.toString(tactus.bench.paper.PaperScenes.SCENES));
                    }
                    if (paper == null) {
                        paper = new ArrayList<>();
                    }
                    paper.add(id);
                } else {
                    standard = true;
                    if (only == null) {
                        only = new ArrayList<>();
                    }
                    only.add(t);
                }
            }
        }
    }

    // ================================================================================================ parent

    /** One forked child: its scene, JDK, what it printed and how it ended. */
    static final class ChildRun {
        String scene;
        String jdk;
        boolean ok;
        String error = "";
        double seconds;
        Map<String, String> info = new LinkedHashMap<>();
        List<Map<String, String>> results = new ArrayList<>();
        String skipped;
    }

    /** A JDK to run children on: a key ("17" = the running java, "25"), and its java launcher (null if absent). */
    static final class Jdk {
        final String key;
        final String java;

        Jdk(String key, String java) {
            this.key = key;
            this.java = java;
        }
    }

    static final class Parent {
        final File out;
        final boolean quick;
        final List<String> only;
        final List<Jdk> jdks = new ArrayList<>();
        final List<ChildRun> runs = new ArrayList<>();
        String loadStart;
        String loadEnd;
        long started;
        long finished;

        Parent(File out, boolean quick, List<String> only, String which, String jdk25) {
            this.out = out;
            this.quick = quick;
            this.only = only;
            String self = Paths.get(System.getProperty("java.home"), "bin", "java").toString();
            if (!which.equals("25")) {
                jdks.add(new Jdk("17", self));
            }
            if (!which.equals("17")) {
                jdks.add(new Jdk("25", new File(jdk25).canExecute() ? jdk25 : null));
            }
        }

        void run() throws IOException {
            started = System.currentTimeMillis();
            loadStart = loadavg();
            List<String> ids = new ArrayList<>();
            for (String id : Scenes.ids()) {
                if (only == null || only.contains(id)) {
                    ids.add(id);
                }
            }
            if (only != null) {
                for (String id : only) {
                    if (!Scenes.ids().contains(id)) {
                        throw new IllegalArgumentException("unknown scene " + id + "; scenes: " + Scenes.ids());
                    }
                }
            }
            System.out.println("Bench: " + ids.size() + " scenes x " + jdks.size() + " JDKs" + (quick ? " (quick)" : "")
                    + "; load at start: " + loadStart + "; report: " + out.getAbsolutePath());
            int k = 0;
            for (String id : ids) {
                k++;
                for (Jdk jdk : jdks) {
                    ChildRun cr;
                    if (jdk.java == null) {
                        cr = new ChildRun();
                        cr.scene = id;
                        cr.jdk = jdk.key;
                        cr.error = "not available";
                    } else {
                        System.out.println(String.format(Locale.ROOT, "== scene %d/%d: %s, JDK %s", k, ids.size(), id,
                                jdk.key));
                        cr = fork(id, jdk);
                    }
                    runs.add(cr);
                }
            }
            loadEnd = loadavg();
            finished = System.currentTimeMillis();
            System.out.println("Bench: load at end: " + loadEnd + "; total " + (finished - started) / 1000 + " s");
            String md = new Report(this).markdown();
            if (only == null || only.contains("parallel")) {
                System.out.println("== parallel stepping (forked JVM)");
                md = md + ParallelBench.section();
            }
            md = md + keptSections(out);
            File parent = out.getAbsoluteFile().getParentFile();
            if (parent != null) {
                parent.mkdirs();
            }
            Files.write(out.toPath(), md.getBytes(StandardCharsets.UTF_8));
            System.out.println("Bench: wrote " + out.getAbsolutePath());
        }

        ChildRun fork(String scene, Jdk jdk) throws IOException {
            ChildRun cr = new ChildRun();
            cr.scene = scene;
            cr.jdk = jdk.key;
            List<String> cmd = new ArrayList<>(Arrays.asList(jdk.java, "-Xms2g", "-Xmx2g", "-XX:+UseParallelGC",
                    "-Djava.awt.headless=true", "-Dfile.encoding=UTF-8",
                    "-cp", System.getProperty("java.class.path"), Bench.class.getName(), "--child", scene, jdk.key));
            if (quick) {
                cmd.add("--quick");
            }
            ProcessBuilder pb = new ProcessBuilder(cmd);
            pb.redirectErrorStream(true);
            long t0 = System.nanoTime();
            Process p = pb.start();
            Thread watchdog = new Thread(() -> {
                try {
                    if (!p.waitFor(CHILD_TIMEOUT_S, java.util.concurrent.TimeUnit.SECONDS)) {
                        p.destroyForcibly();
                    }
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }, "bench-watchdog");
            watchdog.setDaemon(true);
            watchdog.start();
            List<String> tail = new ArrayList<>();
            try (BufferedReader r = new BufferedReader(new InputStreamReader(p.getInputStream(), StandardCharsets.UTF_8))) {
                String line;
                while ((line = r.readLine()) != null) {
                    if (line.startsWith(RESULT + "\t")) {
                        cr.results.add(parse(line));
                    } else if (line.startsWith(INFO + "\t")) {
                        cr.info.putAll(parse(line));
                    } else if (line.startsWith(SKIP + "\t")) {
                        cr.skipped = parse(line).get("reason");
                        System.out.println("  skipped: " + cr.skipped);
                    } else {
                        System.out.println("  " + line);
                        tail.add(line);
                        if (tail.size() > 8) {
                            tail.remove(0);
                        }
                    }
                }
            }
            int code;
            try {
                code = p.waitFor();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                p.destroyForcibly();
                code = -1;
            }
            cr.seconds = (System.nanoTime() - t0) * 1e-9;
            cr.ok = code == 0 && (!cr.results.isEmpty() || cr.skipped != null);
            if (!cr.ok) {
                cr.error = (code != 0 ? "exit code " + code + (cr.seconds >= CHILD_TIMEOUT_S ? " (timed out)" : "")
                        : "no result") + (tail.isEmpty() ? "" : ": " + tail.get(tail.size() - 1));
                System.out.println("  FAILED: " + cr.error);
            }
            return cr;
        }
    }

    /** Parses {@code TAG\tkey=value\tkey=value...}. */
    static Map<String, String> parse(String line) {
        Map<String, String> m = new LinkedHashMap<>();
        String[] parts = line.split("\t");
        for (int i = 1; i < parts.length; i++) {
            int eq = parts[i].indexOf('=');
            if (eq > 0) {
                m.put(parts[i].substring(0, eq), parts[i].substring(eq + 1));
            }
        }
        return m;
    }

    /** Formats {@code TAG\tkey=value...}; tabs and line breaks in values become spaces. */
    static String format(String tag, Map<String, String> m) {
        StringBuilder sb = new StringBuilder(tag);
        for (Map.Entry<String, String> e : m.entrySet()) {
            sb.append('\t').append(e.getKey()).append('=').append(e.getValue().replace('\t', ' ').replace('\n', ' ')
                    .replace('\r', ' '));
        }
        return sb.toString();
    }

    static String joinArray(double[] v) {
        StringBuilder sb = new StringBuilder();
        for (int i = 0; i < v.length; i++) {
            if (i > 0) {
                sb.append(',');
            }
            sb.append(String.format(Locale.ROOT, "%.6g", v[i]));
        }
        return sb.toString();
    }

    static double[] splitArray(String s) {
        if (s == null || s.isEmpty()) {
            return new double[0];
        }
        String[] p = s.split(",");
        double[] v = new double[p.length];
        for (int i = 0; i < p.length; i++) {
            v[i] = Double.parseDouble(p[i]);
        }
        return v;
    }

    /** Marks the start of a hand-written section of the report that a new run keeps (measured by other tools). */
    static final String KEPT_BEGIN = "<!-- kept by gradle bench: begin -->";
    /** Marks the end of a kept section. */
    static final String KEPT_END = "<!-- kept by gradle bench: end -->";

    /**
     * @return the kept sections of the existing report (each from {@link #KEPT_BEGIN} to {@link #KEPT_END}, markers
     *     included), to append to the new one; empty when there is none or the file cannot be read
     */
    static String keptSections(File report) {
        String old;
        try {
            old = new String(Files.readAllBytes(report.toPath()), StandardCharsets.UTF_8);
        } catch (IOException | RuntimeException e) {
            return "";
        }
        StringBuilder kept = new StringBuilder();
        int from = 0;
        while (true) {
            int b = old.indexOf(KEPT_BEGIN, from);
            int e = b < 0 ? -1 : old.indexOf(KEPT_END, b);
            if (e < 0) {
                return kept.toString();
            }
            kept.append('\n').append(old, b, e + KEPT_END.length()).append('\n');
            from = e + KEPT_END.length();
        }
    }

    /** @return the first three fields of /proc/loadavg (1, 5, 15 minutes), or "unknown". */
    static String loadavg() {
        try {
            String s = new String(Files.readAllBytes(Paths.get("/proc/loadavg")), StandardCharsets.US_ASCII).trim();
            String[] f = s.split("\\s+");
            return f.length >= 4 ? f[0] + " " + f[1] + " " + f[2] + " (running/total " + f[3] + ")" : s;
        } catch (IOException | RuntimeException e) {
            return "unknown";
        }
    }

    // ================================================================================================ child

    /** Child: {@code --child <scene> <jdk key> [--quick]}. */
    static void child(String[] args) {
        String id = args[0];
        String jdkKey = args.length > 1 ? args[1] : "?";
        boolean quick = Arrays.asList(args).contains("--quick");
        PrintStream out = System.out;
        Map<String, String> info = new LinkedHashMap<>();
        info.put("javaVersion", System.getProperty("java.version"));
        info.put("runtime", System.getProperty("java.runtime.version"));
        info.put("vm", System.getProperty("java.vm.name") + " " + System.getProperty("java.vm.version"));
        info.put("vendor", System.getProperty("java.vendor"));
        info.put("vmArgs", String.join(" ", ManagementFactory.getRuntimeMXBean().getInputArguments()));
        for (String opt : new String[] {"UseAVX", "MaxVectorSize", "UseSuperWord"}) {
            info.put(opt, vmOption(opt));
        }
        info.put("loadStart", loadavg());
        out.println(format(INFO, info));
        Scenes.Scene scene = Scenes.byId(id);
        if (scene == null) {
            throw new IllegalArgumentException("unknown scene " + id);
        }
        String tag = "[" + id + " | JDK " + jdkKey + "]";
        if (scene.variants.isEmpty()) {
            Map<String, String> m = new LinkedHashMap<>();
            m.put("reason", id.startsWith("marbles") ? "explicit contacts are not benchmarked above 600 marbles and "
                    + "PhysicalModel.addContactGroup does not exist in this build" : "no variant");
            out.println(format(SKIP, m));
            return;
        }
        List<Workload> ws = new ArrayList<>();
        double[] build = new double[scene.variants.size()];
        for (int i = 0; i < build.length; i++) {
            Supplier<Workload> s = scene.variants.get(i);
            long t0 = System.nanoTime();
            Workload w = s.get();
            build[i] = (System.nanoTime() - t0) * 1e-9;
            ws.add(w);
            out.println(String.format(Locale.ROOT, "%s built %s: %,d elements in %.2f s", tag, w.variant(),
                    w.elements(), build[i]));
        }
        System.gc();
        Harness.Config c = quick ? Harness.Config.quick() : Harness.Config.full();
        List<Harness.Outcome> res = Harness.measure(ws, build, c, out, tag);
        String loadEnd = loadavg();
        for (Harness.Outcome o : res) {
            out.println(format(RESULT, resultMap(scene, o, loadEnd)));
        }
        Map<String, String> end = new LinkedHashMap<>();
        end.put("loadEnd", loadEnd);
        out.println(format(INFO, end));
        out.flush();
    }

    static Map<String, String> resultMap(Scenes.Scene scene, Harness.Outcome o, String loadEnd) {
        Map<String, String> m = new LinkedHashMap<>();
        m.put("scene", scene.id);
        m.put("family", scene.family);
        m.put("title", scene.title);
        m.put("variant", o.variant);
        m.put("elements", Long.toString(o.elements));
        m.put("build", String.format(Locale.ROOT, "%.3f", o.buildSeconds));
        m.put("warmupSeconds", String.format(Locale.ROOT, "%.3f", o.warmupSeconds));
        m.put("warmupSteps", Long.toString(o.warmupSteps));
        m.put("stepsPerRun", Integer.toString(o.stepsPerRun));
        m.put("ns", joinArray(o.nsPerElement));
        m.put("sps", joinArray(o.stepsPerSecond));
        m.put("bytes", joinArray(o.bytesPerStep));
        m.put("bytesTotal", Long.toString(o.bytesTotal));
        StringBuilder br = new StringBuilder();
        for (int i = 0; i < o.bytesRun.length; i++) {
            br.append(i > 0 ? "," : "").append(o.bytesRun[i]);
        }
        m.put("bytesRun", br.toString());
        m.put("cpu", joinArray(o.cpuShare));
        m.put("rounds", Integer.toString(o.roundsMeasured));
        m.put("cpuAll", joinArray(o.cpuAll));
        m.put("probe", String.format(Locale.ROOT, "%.6g", o.probe));
        m.put("profile", o.profile);
        m.put("extra", o.extra);
        m.put("loadEnd", loadEnd);
        return m;
    }

    private static String vmOption(String name) {
        try {
            com.sun.management.HotSpotDiagnosticMXBean b =
                    ManagementFactory.getPlatformMXBean(com.sun.management.HotSpotDiagnosticMXBean.class);
            return b.getVMOption(name).getValue();
        } catch (RuntimeException e) {
            return "n/a";
        }
    }
}
