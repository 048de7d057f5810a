package tactus.bench;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Paths;
import java.text.SimpleDateFormat;
import java.util.ArrayList;
import java.util.Date;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TimeZone;

/** Writes docs/performance.md from the children's results. All numbers in it come from this run. */
final class Report {
    private static final double AUDIO = 44100;
    private static final double HAPTIC = 1000;
    private static final double SAMPLE_NS = 1e9 / AUDIO;
    private static final String[] CHAINS = {"chain-470", "chain-1000", "chain-10000"};
    private static final String[] MESHES = {"sheet-100", "sheet-100-diag", "sheet-300", "sheet-367", "plate-50"};
    private static final String[] MARBLES = {"marbles-200", "marbles-200-rest", "marbles-600", "marbles-600-rest",
        "marbles-5000", "marbles-5000-rest"};
    private static final String PM = "PhysicalModel";
    private static final String HAND = "hand loop, parameter arrays";
    private static final String HAND_C = "hand loop, constants";
    private static final String HANDLE = "Mass.getPosition(Vect3D)";
    private static final String EXPLICIT = "explicit Contact3D";
    private static final String GROUP = "contact group";

    private final Bench.Parent p;
    private final StringBuilder md = new StringBuilder();

    Report(Bench.Parent p) {
        this.p = p;
    }

    // ============================================================================================ data access

    private Bench.ChildRun run(String scene, String jdk) {
        for (Bench.ChildRun r : p.runs) {
            if (r.scene.equals(scene) && r.jdk.equals(jdk)) {
                return r;
            }
        }
        return null;
    }

    private Map<String, String> res(String scene, String jdk, String variant) {
        Bench.ChildRun r = run(scene, jdk);
        if (r == null) {
            return null;
        }
        for (Map<String, String> m : r.results) {
            if (variant == null || variant.equals(m.get("variant"))) {
                return m;
            }
        }
        return null;
    }

    private static double[] arr(Map<String, String> m, String key) {
        return m == null ? new double[0] : Bench.splitArray(m.get(key));
    }

    private static double med(Map<String, String> m, String key) {
        return m == null ? Double.NaN : Harness.median(arr(m, key));
    }

    private static long elements(Map<String, String> m) {
        return m == null ? 0 : Long.parseLong(m.get("elements"));
    }

    /** Paired ratio of two variants measured in the same rounds: median, min, max of a[r] / b[r]. */
    private static double[] paired(Map<String, String> a, Map<String, String> b, String key) {
        double[] x = arr(a, key);
        double[] y = arr(b, key);
        int n = Math.min(x.length, y.length);
        if (n == 0) {
            return new double[] {Double.NaN, Double.NaN, Double.NaN};
        }
        double[] r = new double[n];
        for (int i = 0; i < n; i++) {
            r[i] = x[i] / y[i];
        }
        return new double[] {Harness.median(r), Harness.min(r), Harness.max(r)};
    }

    /** Why a cell is empty: the child failed, was skipped, or the JDK is missing. */
    private String missing(String scene, String jdk) {
        Bench.ChildRun r = run(scene, jdk);
        if (r == null) {
            return "not run";
        }
        if (r.skipped != null) {
            return "skipped";
        }
        if ("not available".equals(r.error)) {
            return "JDK not available";
        }
        return "failed";
    }

    private boolean hasJdk(String jdk) {
        for (Bench.Jdk j : p.jdks) {
            if (j.key.equals(jdk)) {
                return j.java != null;
            }
        }
        return false;
    }

    // ============================================================================================ formatting

    private static String f(String fmt, Object... a) {
        return String.format(Locale.ROOT, fmt, a);
    }

    /** Median with min-max: "1.52 (1.49–1.60)". */
    private static String spread(double[] v, String fmt) {
        if (v.length == 0) {
            return "–";
        }
        return f(fmt, Harness.median(v)) + " (" + f(fmt, Harness.min(v)) + "–" + f(fmt, Harness.max(v)) + ")";
    }

    /** A count rounded to 3 significant figures, with thousands separators. */
    static String count(double x) {
        if (!Double.isFinite(x)) {
            return "–";
        }
        if (x < 1000) {
            return f("%.0f", x);
        }
        double mag = Math.pow(10, Math.floor(Math.log10(x)) - 2);
        return f("%,.0f", Math.round(x / mag) * mag);
    }

    /** Steps per second, human readable. */
    static String rate(double x) {
        if (!Double.isFinite(x)) {
            return "–";
        }
        if (x >= 1e6) {
            return f("%.2f M", x / 1e6);
        }
        if (x >= 1e4) {
            return f("%.0f k", x / 1e3);
        }
        if (x >= 1e3) {
            return f("%.2f k", x / 1e3);
        }
        return f("%.0f", x);
    }

    /**
     * Allocation of a variant: "0" when every kept run allocated nothing; a per-step figure when every run allocated
     * (that is a real per-step allocation); otherwise "0 per step" plus the one-off bytes of the runs that had some
     * (a JIT or class-loading event: it does not grow with the number of steps).
     */
    private static String bytes(Map<String, String> m) {
        if (m == null) {
            return "–";
        }
        double[] runs = arr(m, "bytesRun");
        double[] perStep = arr(m, "bytes");
        int nonzero = 0;
        for (double b : runs) {
            if (b > 0) {
                nonzero++;
            }
        }
        if (nonzero == 0) {
            return "0";
        }
        if (nonzero == runs.length) {
            return f("**%.3g per step**", Harness.min(perStep));
        }
        return f("0 per step (one-off %,.0f B in %d of %d runs)", Harness.max(runs), nonzero, runs.length);
    }

    /** @return true when every kept run of the variant allocated: a real per-step allocation. */
    private static boolean allocatesPerStep(Map<String, String> m) {
        return Harness.min(arr(m, "bytesRun")) > 0;
    }

    private static String pct(double x) {
        return Double.isFinite(x) ? f("%.0f%%", 100 * x) : "–";
    }

    private void line(String s) {
        md.append(s).append('\n');
    }

    private void blank() {
        md.append('\n');
    }

    // ============================================================================================ report

    String markdown() {
        header();
        targets();
        machine();
        method();
        mainTable();
        capacity();
        marbles();
        overhead();
        audio();
        kernels();
        sketchers();
        loadTable();
        reproduce();
        return md.toString();
    }

    private void header() {
        SimpleDateFormat d = new SimpleDateFormat("yyyy-MM-dd HH:mm 'UTC'", Locale.ROOT);
        d.setTimeZone(TimeZone.getTimeZone("UTC"));
        line("# Tactus performance");
        blank();
        line("Generated by `gradle bench` (`tactus.bench.Bench`, sources in `tools/tactus/bench/`) on "
                + d.format(new Date(p.started)) + f(", in %d s", (p.finished - p.started) / 1000)
                + (p.quick ? ", **quick mode** (shorter warm-up and runs: figures are rougher)" : "")
                + ". Every number below was measured in that run; nothing is copied from elsewhere except the "
                + "authors' 7.5 ns figure, which is marked. Timings on a shared 2-core machine are noisy: read the "
                + "min–max ranges and the load table at the end before comparing two figures.");
        blank();
        line("An **element update** is one inertial mass moved or one interaction computed in one step. Fixed points "
                + "(Ground3D) are stepped (their force buffers are cleared) and that time is included, but they are "
                + "not counted as elements. **ns per element** = wall time of a run / (steps x counted elements).");
        blank();
    }

    private void targets() {
        line("## Targets of issue #4");
        blank();
        line("Judged on JDK 17 (the JDK 25 figure is beside it). Medians of the measured runs.");
        blank();
        line("| target | measured, JDK 17 | JDK 25 | verdict |");
        line("|---|---|---|---|");
        // 1. chain
        line(targetRow("chain: ≤ 2.0 ns per element update", CHAINS, 2.0));
        // 2. meshes
        line(targetRow("meshes (sheets, plate): ≤ 3.0 ns per element update", MESHES, 3.0));
        // 3. 10,000 elements at 44.1 kHz
        {
            Map<String, String> a = res("audio-5000", "17", HANDLE);
            Map<String, String> b = res("audio-5000", "25", HANDLE);
            String m17 = a == null ? missing("audio-5000", "17") : realtimeCell(a, AUDIO);
            String m25 = b == null ? missing("audio-5000", "25") : realtimeCell(b, AUDIO);
            String v = a == null ? "not measured" : med(a, "sps") >= AUDIO ? "**met**" : "**not met**";
            line("| ≥ 10,000 elements at 44.1 kHz on one core, compute only (measured directly: a "
                    + f("%,d", elements(a)) + "-element string stepped one sample at a time, reading one position "
                    + "per sample) | " + m17 + " | " + m25 + " | " + v + " |");
        }
        // 4. 400,000 at 1 kHz
        {
            Map<String, String> a = res("sheet-367", "17", PM);
            Map<String, String> b = res("sheet-367", "25", PM);
            String m17 = a == null ? missing("sheet-367", "17") : realtimeCell(a, HAPTIC);
            String m25 = b == null ? missing("sheet-367", "25") : realtimeCell(b, HAPTIC);
            String v = a == null ? "not measured" : med(a, "sps") >= HAPTIC ? "**met**" : "**not met**";
            line("| ≥ 400,000 elements at 1 kHz on one core, compute only (measured directly: a 367x367 sheet, "
                    + f("%,d", elements(a)) + " elements, computeNSteps) | " + m17 + " | " + m25 + " | " + v + " |");
        }
        // 5. overhead
        {
            String[] cells = new String[2];
            double r17 = Double.NaN;
            String[] jd = {"17", "25"};
            for (int i = 0; i < 2; i++) {
                Map<String, String> e = res("overhead", jd[i], PM);
                Map<String, String> h = res("overhead", jd[i], HAND);
                if (e == null || h == null) {
                    cells[i] = missing("overhead", jd[i]);
                    continue;
                }
                double[] r = paired(e, h, "ns");
                if (i == 0) {
                    r17 = r[0];
                }
                cells[i] = f("%.2fx (%.2f–%.2f)", r[0], r[1], r[2]) + f("; %.2f vs %.2f ns", med(e, "ns"), med(h, "ns"));
                Map<String, String> hc = res("overhead", jd[i], HAND_C);
                if (hc != null) {
                    double[] rc = paired(e, hc, "ns");
                    cells[i] += f("; against the constants loop %.2fx (%.2f–%.2f)", rc[0], rc[1], rc[2]);
                }
            }
            String v = Double.isNaN(r17) ? "not measured" : r17 <= 1.10 ? "**met**" : "**not met**";
            line("| engine overhead ≤ 10% vs a hand-written loop (springs-only 1,000-mass chain, PhysicalModel time / "
                    + "hand loop time, paired per round) | " + cells[0] + " | " + cells[1] + " | " + v + " |");
        }
        // 6. zero allocation
        {
            String[] jd = {"17", "25"};
            String[] cells = new String[2];
            boolean met = true;
            int n17 = 0;
            for (int i = 0; i < 2; i++) {
                List<String> perStep = new ArrayList<>();
                List<String> oneOff = new ArrayList<>();
                int n = 0;
                for (Bench.ChildRun r : p.runs) {
                    if (!r.jdk.equals(jd[i])) {
                        continue;
                    }
                    for (Map<String, String> m : r.results) {
                        n++;
                        String name = r.scene + " / " + m.get("variant");
                        if (allocatesPerStep(m)) {
                            perStep.add(name + f(" (%.3g B/step)", Harness.min(arr(m, "bytes"))));
                        } else if (Harness.max(arr(m, "bytesRun")) > 0) {
                            oneOff.add(name + f(" (%,.0f B once)", Harness.max(arr(m, "bytesRun"))));
                        }
                    }
                }
                if (i == 0) {
                    n17 = n;
                    met = perStep.isEmpty();
                }
                if (n == 0) {
                    cells[i] = "–";
                    continue;
                }
                String c = perStep.isEmpty() ? "0 B per step in all " + n + " variants"
                        : "allocates every step: " + String.join("; ", perStep);
                if (!oneOff.isEmpty()) {
                    c += "; one-off allocation in a single run (not per step): " + String.join("; ", oneOff);
                }
                cells[i] = c;
            }
            line("| 0 bytes allocated per step (a variant allocates per step if every one of its runs allocated) | "
                    + cells[0] + " | " + cells[1] + " | " + (n17 == 0 ? "not measured" : met ? "**met**" : "**not met**")
                    + " |");
        }
        // 7. authors' engine
        {
            Map<String, String> a = res("chain-1000", "17", PM);
            String c = a == null ? "–" : f("chain-1000: %.2f ns, %.1fx fewer ns than 7.5", med(a, "ns"),
                    7.5 / med(a, "ns"));
            Map<String, String> b = res("chain-1000", "25", PM);
            String c25 = b == null ? "–" : f("%.2f ns", med(b, "ns"));
            line("| for comparison: the authors' engine, about 7.5 ns per element update (figure from the issue text; "
                    + "not measured here, other machine) | " + c + " | " + c25 + " | reference only |");
        }
        blank();
    }

    private String targetRow(String what, String[] scenes, double limit) {
        StringBuilder c17 = new StringBuilder();
        StringBuilder c25 = new StringBuilder();
        boolean all = true;
        boolean any = false;
        for (String s : scenes) {
            Map<String, String> a = res(s, "17", PM);
            Map<String, String> b = res(s, "25", PM);
            if (c17.length() > 0) {
                c17.append("; ");
                c25.append("; ");
            }
            if (a == null) {
                c17.append(s).append(": ").append(missing(s, "17"));
                all = false;
            } else {
                any = true;
                double v = med(a, "ns");
                c17.append(s).append(": ").append(f(v <= limit ? "%.2f" : "**%.2f**", v)).append(disturbed(a));
                all &= v <= limit;
            }
            c25.append(s).append(": ").append(b == null ? missing(s, "25") : f("%.2f", med(b, "ns")) + disturbed(b));
        }
        String verdict = !any ? "not measured" : all ? "**met**" : "**not met**";
        return "| " + what + " | " + c17 + " | " + c25 + " | " + verdict + " |";
    }

    private static String realtimeCell(Map<String, String> m, double rate) {
        double sps = med(m, "sps");
        return f("%s steps/s = %.0f%% of one core at %s", rate(sps), 100 * rate / sps,
                rate == AUDIO ? "44.1 kHz" : "1 kHz") + disturbed(m);
    }

    /**
     * A warning when the kept runs were disturbed (median CPU/wall below 90%), with the figure on a CPU-time basis
     * (wall-time figure x CPU share), which leaves out the time the thread was descheduled.
     */
    private static String disturbed(Map<String, String> m) {
        double share = med(m, "cpu");
        if (!(share < 0.9)) {
            return "";
        }
        return f(" (⚠ disturbed: CPU/wall %.0f%%; on CPU time %.2f ns)", 100 * share, med(m, "ns") * share);
    }

    private void machine() {
        line("## Machine");
        blank();
        String cpu = "unknown";
        int procs = 0;
        String flags = "";
        try {
            for (String l : Files.readAllLines(Paths.get("/proc/cpuinfo"), StandardCharsets.UTF_8)) {
                if (l.startsWith("model name") && cpu.equals("unknown")) {
                    cpu = l.substring(l.indexOf(':') + 1).trim();
                } else if (l.startsWith("processor")) {
                    procs++;
                } else if (l.startsWith("flags") && flags.isEmpty()) {
                    String fl = " " + l.substring(l.indexOf(':') + 1).trim() + " ";
                    List<String> have = new ArrayList<>();
                    for (String x : new String[] {"sse4_2", "avx", "avx2", "fma", "avx512f", "avx512vl"}) {
                        if (fl.contains(" " + x + " ")) {
                            have.add(x);
                        }
                    }
                    flags = String.join(", ", have);
                }
            }
        } catch (IOException | RuntimeException e) {
            cpu = "unknown (" + e.getMessage() + ")";
        }
        String mem = "";
        try {
            for (String l : Files.readAllLines(Paths.get("/proc/meminfo"), StandardCharsets.UTF_8)) {
                if (l.startsWith("MemTotal")) {
                    long kb = Long.parseLong(l.replaceAll("[^0-9]", ""));
                    mem = f("%.1f GiB", kb / 1024.0 / 1024.0);
                }
            }
        } catch (IOException | RuntimeException e) {
            mem = "unknown";
        }
        line("| | |");
        line("|---|---|");
        line("| CPU | " + cpu + " |");
        line("| caches (cpu0, from /sys) | " + caches() + " |");
        line("| cores | " + procs + " logical processors in /proc/cpuinfo; availableProcessors() = "
                + Runtime.getRuntime().availableProcessors() + " |");
        line("| vector extensions | " + flags + " |");
        line("| memory | " + mem + " |");
        line("| OS | " + System.getProperty("os.name") + " " + System.getProperty("os.version") + " |");
        for (Bench.Jdk j : p.jdks) {
            Map<String, String> info = null;
            for (Bench.ChildRun r : p.runs) {
                if (r.jdk.equals(j.key) && r.info.containsKey("runtime")) {
                    info = r.info;
                    break;
                }
            }
            String label = j.key.equals("17") ? "JDK 17 (the running java)" : "JDK 25";
            if (j.java == null) {
                line("| " + label + " | not available |");
            } else if (info == null) {
                line("| " + label + " | `" + j.java + "` (no child reported) |");
            } else {
                line("| " + label + " | " + info.get("vendor") + " " + info.get("runtime") + ", " + info.get("vm")
                        + "; `" + j.java + "`; UseAVX=" + info.get("UseAVX") + ", MaxVectorSize="
                        + info.get("MaxVectorSize") + ", UseSuperWord=" + info.get("UseSuperWord") + " |");
            }
        }
        line("| child JVM flags | `-Xms2g -Xmx2g -XX:+UseParallelGC` |");
        line("| load average (1, 5, 15 min) | at start: " + p.loadStart + "; at end: " + p.loadEnd + " |");
        blank();
    }

    /** @return the cache hierarchy of cpu0, for example "L1d 48K, L1i 64K, L2 2048K, L3 491520K". */
    private static String caches() {
        List<String> out = new ArrayList<>();
        try {
            for (int i = 0; i < 8; i++) {
                java.nio.file.Path d = Paths.get("/sys/devices/system/cpu/cpu0/cache/index" + i);
                if (!Files.isDirectory(d)) {
                    break;
                }
                String level = new String(Files.readAllBytes(d.resolve("level")), StandardCharsets.US_ASCII).trim();
                String type = new String(Files.readAllBytes(d.resolve("type")), StandardCharsets.US_ASCII).trim();
                String size = new String(Files.readAllBytes(d.resolve("size")), StandardCharsets.US_ASCII).trim();
                String t = type.equals("Data") ? "d" : type.equals("Instruction") ? "i" : "";
                out.add("L" + level + t + " " + size);
            }
        } catch (IOException | RuntimeException e) {
            return "unknown";
        }
        return out.isEmpty() ? "unknown" : String.join(", ", out);
    }

    private void method() {
        line("## Method");
        blank();
        Harness.Config c = p.quick ? Harness.Config.quick() : Harness.Config.full();
        line("- **One forked JVM per (scene, JDK)**, same classpath, `-Xms2g -Xmx2g -XX:+UseParallelGC`; the parent "
                + "process only forks, collects one machine-readable line per variant from the child's stdout, and "
                + "writes this file. The two JDKs of a scene run back to back, so they see similar load.");
        line("- **Build** through the public `PhysicalModel` API in ALGO_UNITS (the overhead scene also builds the "
                + "same chain on `tactus.engine.Engine` directly, and as a hand-written loop), `init()`, then one "
                + "`System.gc()` so that no collection of build garbage lands in a measured run.");
        line(f("- **Warm-up** of each variant: advancing in growing chunks until ≥ %.1f s and ≥ %,d steps "
                + "(at most %.1f s); the median rate of the last five chunks sizes the measured runs to about %.1f s each.",
                c.warmupSeconds, c.warmupMinSteps, c.warmupMaxSeconds, c.runSeconds));
        line(f("- **%d measured runs** per variant, each one `computeNSteps(n)` call with n = the whole run (audio "
                + "scenes: n calls of `computeStep()` plus one position read). When a scene has several variants "
                + "they are **interleaved** (round-robin, order rotating per round), and ratios between them are "
                + "taken per round (paired), which cancels most of the load drift of a shared machine.", c.runs));
        line(f("- **Disturbed rounds are repeated**: a round in which any run got less than %.0f%% CPU time over "
                + "wall time (the thread was descheduled by other load) is measured again, up to %d rounds; the "
                + "first %d undisturbed rounds are kept, or the %d least disturbed if there are not enough (the load "
                + "table at the end says how many rounds each child measured and kept). The criterion is the CPU "
                + "share, never the speed.", 100 * c.minCpuShare, c.maxRounds, c.runs, c.runs));
        line("- **Per run**: wall time (`System.nanoTime`), this thread's CPU time (CPU/wall below 100% means the "
                + "thread was descheduled: other load), and this thread's allocated bytes "
                + "(`com.sun.management.ThreadMXBean.getThreadAllocatedBytes`) around the call, minus the cost of "
                + "reading the counter (two back-to-back reads).");
        line("- **Allocation** is judged per variant: it allocates per step only if every kept run allocated (a real "
                + "per-step allocation shows in every run). A few hundred bytes in a single run are a one-off JVM "
                + "event, not stepping: for example, the chain allocates 440 B once, exactly when HotSpot "
                + "OSR-compiles the loop of `Engine.step(int)` with C2 at about step 51,200 (seen with "
                + "`-XX:+LogCompilation`, at the same step in every repetition).");
        line("- **Reported**: median and min–max of the runs. Largest real-time model = 1e9 / (rate x ns per "
                + "element), compute only (100% of one core) and with 50% headroom (half of it). This is a linear "
                + "extrapolation from the measured size: the cost per element changes with model size (cache) and, "
                + "at 44.1 kHz, small models pay a fixed per-step overhead (see the audio section for the real "
                + "per-sample figures).");
        line("- **Per-kernel profile** (after the measured runs, diagnostic only): the compiled plan's kernels are "
                + "run one by one in plan order and timed individually, alternating with blocks of whole normal "
                + "steps; the divergence guard's scan is timed separately and amortised over its 64-step interval. "
                + "Each figure is the median over blocks of 64 steps.");
        blank();
        line("Scenes (parameters per step, ALGO_UNITS):");
        blank();
        line("- **chain-N**: a 3D string of N Mass3D (M 1) between two Ground3D, N + 1 SpringDamper3D "
                + "(K 0.4, Z 0.001, l0 0.08 at spacing 0.1, so under tension), air friction 1e-5, plucked in y and z. "
                + "Elements: N + (N + 1).");
        line("- **sheet-W**: W x W nodes, border fixed (Ground3D), interior Mass3D (M 1); SpringDamper3D to the right "
                + "and down neighbours (K 0.2, Z 0.001, l0 0.09 at spacing 0.1); `-diag` adds the down-right "
                + "diagonal (K 0.1, Z 0.0005); links between two fixed nodes left out; friction 1e-5; a Gaussian "
                + "bump in z. Elements: (W − 2)² masses + links. sheet-367 has 400,405 elements: the 1 kHz target "
                + "size.");
        line("- **plate-50**: 50 x 50 Osc1D (M 1, K 0.01, Z 0.0001) with SpringDamper1D to the right and down "
                + "neighbours (K 0.2, Z 0.0005), like miPhysics' MetalPlate1D. Elements: 2,500 + 4,900.");
        line("- **marbles-N**: after miPhysics' EnclosedMarbles: N Mass3D (M 7–10), gravity 5e-5, friction 1e-3, "
                + "a Bubble3D per marble to a fixed centre (R 3, K 0.1, Z 0.1), a PlaneContact per marble on z = 0 "
                + "(l0 0.1, K 0.01, Z 0.01), and a contact (threshold 0.2, K 0.02, Z 0.01) for every unordered pair "
                + "i < j (one per pair, where EnclosedMarbles adds both orders), either as explicit Contact3D links or "
                + "as one `addContactGroup` over all marbles. The marbles start as a loose lattice pile (spacing "
                + "0.21, no contact engaged) in the bottom of the bubble. In place of the haptic avatar a **stirrer** "
                + "keeps them moving: a Mass2DPlane of mass 1e6 in the plane z = 0.3, on a zero-length Spring3D to a "
                + "fixed hub, launched into a circular orbit of radius 1.2 (period about 3 s at 1 kHz), with a "
                + "Contact3D to every marble (threshold 0.5, like the avatar's in EnclosedMarbles). marbles-N-rest "
                + "has no stirrer: the marbles settle and rest, the cheapest state for a contact group. Elements "
                + "(both variants, explicit count): N + N(N − 1)/2 + 2N, plus N + 2 with the stirrer (its mass, arm "
                + "and N contacts).");
        line("- **overhead**: a springs-only chain, 1,000 Mass3D + 1,001 Spring3D (K 0.4, l0 0.08), no damping, no "
                + "friction, no gravity: through PhysicalModel; on the Engine with stencil runs on and off; and as a "
                + "hand-written loop of the same equations on plain arrays (`HandChain`), once with per-element "
                + "parameter arrays (the primary reference) and once with constants.");
        line("- **audio-N**: the chain-N string at 44.1 kHz stepped as an audio callback would: one `computeStep()` "
                + "per sample, then the listening mass's position read with an allocation-free getter.");
        blank();
    }

    private void mainTable() {
        line("## Strings and meshes");
        blank();
        line("| scene | elements | JDK 17 ns/element, median (min–max) | JDK 17 steps/s | JDK 25 ns/element | "
                + "JDK 25 steps/s | bytes/step (17; 25) | CPU/wall (17; 25) | build |");
        line("|---|---|---|---|---|---|---|---|---|");
        List<String> scenes = new ArrayList<>();
        for (String s : CHAINS) {
            scenes.add(s);
        }
        for (String s : MESHES) {
            scenes.add(s);
        }
        for (String s : scenes) {
            Map<String, String> a = res(s, "17", PM);
            Map<String, String> b = res(s, "25", PM);
            Map<String, String> any = a != null ? a : b;
            if (any == null) {
                line("| " + s + " | – | " + missing(s, "17") + " | – | " + missing(s, "25") + " | – | – | – | – |");
                continue;
            }
            line("| " + s + " (" + any.get("title") + ") | " + f("%,d", elements(any)) + " | "
                    + (a == null ? missing(s, "17") : spread(arr(a, "ns"), "%.2f")) + " | "
                    + (a == null ? "–" : rate(med(a, "sps"))) + " | "
                    + (b == null ? missing(s, "25") : spread(arr(b, "ns"), "%.2f")) + " | "
                    + (b == null ? "–" : rate(med(b, "sps"))) + " | "
                    + bytes(a) + "; " + bytes(b) + " | "
                    + pct(med(a, "cpu")) + "; " + pct(med(b, "cpu")) + " | "
                    + f("%.1f s", Double.parseDouble(any.get("build"))) + " |");
        }
        blank();
    }

    private void capacity() {
        line("## Largest model in real time on one core (linear extrapolation)");
        blank();
        line("Elements = 1e9 / (rate x median ns per element). Each cell: compute only (100% of a core) / with 50% "
                + "headroom. Valid near the measured size; the 44.1 kHz column ignores the per-step overhead that "
                + "dominates small models (see the audio section).");
        blank();
        line("| scene (measured size) | ns/element JDK 17 | 1 kHz, JDK 17 | 44.1 kHz, JDK 17 | ns/element JDK 25 | "
                + "1 kHz, JDK 25 | 44.1 kHz, JDK 25 |");
        line("|---|---|---|---|---|---|---|");
        List<String> scenes = new ArrayList<>();
        for (String s : CHAINS) {
            scenes.add(s);
        }
        for (String s : MESHES) {
            scenes.add(s);
        }
        for (String s : scenes) {
            Map<String, String> a = res(s, "17", PM);
            Map<String, String> b = res(s, "25", PM);
            long el = elements(a != null ? a : b);
            StringBuilder row = new StringBuilder("| " + s + " (" + f("%,d", el) + ") |");
            List<Map<String, String>> both = new ArrayList<>();
            both.add(a);
            both.add(b);
            for (Map<String, String> m : both) {
                if (m == null) {
                    row.append(" – | – | – |");
                    continue;
                }
                double ns = med(m, "ns");
                row.append(f(" %.2f |", ns));
                for (double rate : new double[] {HAPTIC, AUDIO}) {
                    double cap = 1e9 / (rate * ns);
                    row.append(' ').append(count(cap)).append(" / ").append(count(cap / 2)).append(" |");
                }
            }
            line(row.toString());
        }
        blank();
    }

    private void marbles() {
        line("## Enclosed marbles");
        blank();
        boolean group = false;
        for (Bench.ChildRun r : p.runs) {
            for (Map<String, String> m : r.results) {
                group |= GROUP.equals(m.get("variant"));
            }
        }
        line("Contact scenes do not scale linearly in elements, so they are given per step: µs per step and the share "
                + "of one core they need at the 1 kHz haptic rate (EnclosedMarbles runs at 1 kHz; the miPhysics paper "
                + "needed 200 Hz for 600 marbles). 'ns/element' uses the explicit-link element count for both "
                + "variants (N + N(N−1)/2 + 2N), so it is an *effective* figure for the contact group. 'engaged' = "
                + "pair contacts closer than the threshold per marble at the end of the run. 'stirrer speed' is in "
                + "units per second at the end of the run (2.5 at launch): the stirrer kept ploughing through the "
                + "measured runs. Rows 'at rest' have no stirrer; the marbles have settled. The explicit links cost "
                + "about the same in both states (every pair is visited every step); the contact group's cost depends "
                + "on the motion, through its neighbour-list rebuilds (see the per-kernel profile).");
        blank();
        if (!group) {
            line("`PhysicalModel.addContactGroup` did not exist in the build that ran, so only explicit contacts were "
                    + "measured.");
            blank();
        }
        line("| marbles | variant | elements (explicit count) | JDK 17 µs/step, median (min–max) | JDK 17 ns/element "
                + "| core share at 1 kHz (17) | JDK 25 µs/step | core share at 1 kHz (25) | bytes/step (17; 25) | "
                + "engaged (17) | stirrer speed at end (17) | build |");
        line("|---|---|---|---|---|---|---|---|---|---|---|---|");
        for (String s : MARBLES) {
            Bench.ChildRun r17 = run(s, "17");
            Bench.ChildRun r25 = run(s, "25");
            List<String> variants = new ArrayList<>();
            for (Bench.ChildRun r : new Bench.ChildRun[] {r17, r25}) {
                if (r != null) {
                    for (Map<String, String> m : r.results) {
                        if (!variants.contains(m.get("variant"))) {
                            variants.add(m.get("variant"));
                        }
                    }
                }
            }
            String n = s.substring(s.indexOf('-') + 1).replace("-rest", ", at rest");
            if (variants.isEmpty()) {
                line("| " + n + " | – | – | " + missing(s, "17") + " | – | – | " + missing(s, "25")
                        + " | – | – | – | – | – |");
            }
            for (String v : variants) {
                Map<String, String> a = res(s, "17", v);
                Map<String, String> b = res(s, "25", v);
                Map<String, String> any = a != null ? a : b;
                line("| " + n + " | " + v + " | " + f("%,d", elements(any)) + " | "
                        + (a == null ? missing(s, "17") : spread(us(arr(a, "sps")), "%.1f")) + " | "
                        + (a == null ? "–" : f("%.2f", med(a, "ns"))) + " | "
                        + (a == null ? "–" : pct(HAPTIC / med(a, "sps"))) + " | "
                        + (b == null ? missing(s, "25") : spread(us(arr(b, "sps")), "%.1f")) + " | "
                        + (b == null ? "–" : pct(HAPTIC / med(b, "sps"))) + " | "
                        + bytes(a) + "; " + bytes(b) + " | "
                        + (a == null ? "–" : extra(a, "engaged")) + " | "
                        + (a == null || extra(a, "stirrer").equals("NaN") ? "–" : extra(a, "stirrer")) + " | "
                        + f("%.1f s", Double.parseDouble(any.get("build"))) + " |");
            }
        }
        blank();
        if (group) {
            line("Speed-up of the contact group over explicit links (explicit µs/step / group µs/step, paired per "
                    + "round, median (min–max)):");
            blank();
            for (String s : new String[] {"marbles-200", "marbles-200-rest", "marbles-600", "marbles-600-rest"}) {
                StringBuilder sb = new StringBuilder("- " + s + ": ");
                for (String jdk : new String[] {"17", "25"}) {
                    Map<String, String> e = res(s, jdk, EXPLICIT);
                    Map<String, String> g = res(s, jdk, GROUP);
                    if (e == null || g == null) {
                        sb.append("JDK ").append(jdk).append(" –; ");
                        continue;
                    }
                    double[] r = paired(g, e, "sps");
                    sb.append(f("JDK %s **%.1fx** (%.1f–%.1f); ", jdk, r[0], r[1], r[2]));
                }
                line(sb.toString());
            }
            Map<String, String> st = res("marbles-5000", "17", GROUP);
            Map<String, String> rs = res("marbles-5000-rest", "17", GROUP);
            if (st != null && rs != null) {
                line(f("- marbles-5000, contact group, JDK 17: %.0f µs/step stirred (%s) against %.0f µs/step at rest "
                        + "(%s).", 1e6 / med(st, "sps"), groupKernel(st), 1e6 / med(rs, "sps"), groupKernel(rs)));
            }
            line("- marbles-5000: contact group only. 5,000 explicit marbles would be 12.5 million Contact3D links: "
                    + "with names, handles and engine tables that is several GB (beyond the 2 GB child heap), "
                    + "minutes to build, and at the explicit per-element cost measured above tens of milliseconds "
                    + "per step, i.e. far from 1 kHz.");
        } else {
            line("marbles-5000 needs the contact group (5,000 explicit marbles would be 12.5 million Contact3D links: "
                    + "several GB, beyond the 2 GB child heap, and tens of ms per step); it was skipped.");
        }
        blank();
    }

    /** @return the contact-group kernel's profile entry: listed pairs, rebuilds per step and time per step. */
    private static String groupKernel(Map<String, String> m) {
        for (String[] k : profile(m)) {
            if (k[0].startsWith("ContactGroupKernel")) {
                return k[0].replace("ContactGroupKernel(", "").replace(")", "") + f(", kernel %.0f µs/step",
                        Double.parseDouble(k[2]) / 1000);
            }
        }
        return "no profile";
    }

    private static double[] us(double[] sps) {
        double[] v = new double[sps.length];
        for (int i = 0; i < v.length; i++) {
            v[i] = 1e6 / sps[i];
        }
        return v;
    }

    private static String extra(Map<String, String> m, String key) {
        for (String kv : m.getOrDefault("extra", "").split(";")) {
            int eq = kv.indexOf('=');
            if (eq > 0 && kv.substring(0, eq).equals(key)) {
                return kv.substring(eq + 1);
            }
        }
        return "–";
    }

    private void overhead() {
        line("## Engine overhead: springs-only chain vs a hand-written loop");
        blank();
        line("1,000 Mass3D + 1,001 Spring3D (2,001 elements), no damping, friction or gravity, so the engine runs "
                + "the Free3D mass kernel and the spring kernels. All five variants run interleaved in one JVM; "
                + "ratios are per round (paired) against the hand loop with parameter arrays (the primary reference: "
                + "it reads the same per-element data as the engine) and against the hand loop with constants (the "
                + "fastest way to write a uniform chain). Below 1.00 means faster than that loop.");
        blank();
        line("| variant | JDK 17 ns/element, median (min–max) | ratio to hand loop (17) | ratio to constants loop (17) "
                + "| JDK 25 ns/element | ratio to hand loop (25) | ratio to constants loop (25) | bytes/step (17; 25) |");
        line("|---|---|---|---|---|---|---|---|");
        for (String v : new String[] {PM, "Engine, stencil runs on", "Engine, stencil runs off", HAND, HAND_C}) {
            Map<String, String> a = res("overhead", "17", v);
            Map<String, String> b = res("overhead", "25", v);
            Map<String, String> ha = res("overhead", "17", HAND);
            Map<String, String> hb = res("overhead", "25", HAND);
            Map<String, String> ca = res("overhead", "17", HAND_C);
            Map<String, String> cb = res("overhead", "25", HAND_C);
            String ra = a == null || ha == null ? "–" : ratio(paired(a, ha, "ns"));
            String rb = b == null || hb == null ? "–" : ratio(paired(b, hb, "ns"));
            String rca = a == null || ca == null ? "–" : ratio(paired(a, ca, "ns"));
            String rcb = b == null || cb == null ? "–" : ratio(paired(b, cb, "ns"));
            line("| " + v + " | " + (a == null ? missing("overhead", "17") : spread(arr(a, "ns"), "%.2f")) + " | " + ra
                    + " | " + rca + " | " + (b == null ? missing("overhead", "25") : spread(arr(b, "ns"), "%.2f"))
                    + " | " + rb + " | " + rcb + " | " + bytes(a) + "; " + bytes(b) + " |");
        }
        blank();
        for (String jdk : new String[] {"17", "25"}) {
            Map<String, String> on = res("overhead", jdk, "Engine, stencil runs on");
            Map<String, String> off = res("overhead", jdk, "Engine, stencil runs off");
            if (on != null && off != null) {
                double[] r = paired(off, on, "ns");
                line(f("- JDK %s: stencil runs make the chain **%.2fx** faster than index arrays (off/on, paired: "
                        + "%.2f–%.2f).", jdk, r[0], r[1], r[2]));
            }
        }
        blank();
    }

    private static String ratio(double[] r) {
        return Double.isNaN(r[0]) ? "–" : f("%.2f (%.2f–%.2f)", r[0], r[1], r[2]);
    }

    private void audio() {
        line("## Audio rate, one sample at a time");
        blank();
        line("The string of chain-N at 44.1 kHz, stepped like an audio callback: per sample one `computeStep()` "
                + "(which takes the model's lock and checks for divergence) and one read of the listening mass "
                + "(mass N/3) with an allocation-free getter. One sample period is 22.7 µs; the core share is "
                + "ns per sample / 22,676 ns.");
        blank();
        line("| string | elements | getter | JDK 17 ns/sample, median (min–max) | ns/element (17) | core share at "
                + "44.1 kHz (17) | JDK 25 ns/sample | ns/element (25) | core share (25) | bytes/sample (17; 25) |");
        line("|---|---|---|---|---|---|---|---|---|---|");
        for (String s : new String[] {"audio-500", "audio-1000", "audio-5000"}) {
            Bench.ChildRun r = run(s, "17") != null ? run(s, "17") : run(s, "25");
            List<String> variants = new ArrayList<>();
            if (r != null) {
                for (Map<String, String> m : r.results) {
                    variants.add(m.get("variant"));
                }
            }
            if (variants.isEmpty()) {
                line("| " + s + " | – | – | " + missing(s, "17") + " | – | – | " + missing(s, "25") + " | – | – | – |");
            }
            for (String v : variants) {
                Map<String, String> a = res(s, "17", v);
                Map<String, String> b = res(s, "25", v);
                Map<String, String> any = a != null ? a : b;
                int n = Integer.parseInt(s.substring(6));
                line("| " + n + " masses | " + f("%,d", elements(any)) + " | `" + v + "` | "
                        + (a == null ? missing(s, "17") : spread(nsPerStep(a), "%.0f")) + " | "
                        + (a == null ? "–" : f("%.2f", med(a, "ns"))) + " | "
                        + (a == null ? "–" : f("%.1f%%", 100 * (1e9 / med(a, "sps")) / SAMPLE_NS)) + " | "
                        + (b == null ? missing(s, "25") : spread(nsPerStep(b), "%.0f")) + " | "
                        + (b == null ? "–" : f("%.2f", med(b, "ns"))) + " | "
                        + (b == null ? "–" : f("%.1f%%", 100 * (1e9 / med(b, "sps")) / SAMPLE_NS)) + " | "
                        + bytes(a) + "; " + bytes(b) + " |");
            }
        }
        blank();
        perSampleOverhead();
    }

    /** Per-sample overhead of computeStep() + getter: audio-N ns/sample minus chain-N ns/step (same model). */
    private void perSampleOverhead() {
        StringBuilder sb = new StringBuilder();
        for (String jdk : new String[] {"17", "25"}) {
            Map<String, String> a = res("audio-1000", jdk, HANDLE);
            Map<String, String> c = res("chain-1000", jdk, PM);
            if (a == null || c == null) {
                continue;
            }
            double perSample = 1e9 / med(a, "sps");
            double perStep = 1e9 / med(c, "sps");
            double[] sa = nsPerStep(a);
            double[] sc = nsPerStep(c);
            double spread = Math.max(Harness.max(sa) - Harness.min(sa), Harness.max(sc) - Harness.min(sc));
            double diff = perSample - perStep;
            if (Math.abs(diff) <= spread) {
                sb.append(f(" JDK %s: %.0f ns per sample against %.0f ns per step with computeNSteps; the difference "
                        + "(%+.0f ns) is within the spread of the runs (%.0f ns), so the per-sample cost of the call, "
                        + "the lock, the divergence check and the getter is too small to see here.", jdk, perSample,
                        perStep, diff, spread));
            } else {
                sb.append(f(" JDK %s: %.0f ns per sample against %.0f ns per step with computeNSteps, i.e. about "
                        + "%+.0f ns (%+.1f%%) for the call, the lock, the divergence check and the getter.", jdk,
                        perSample, perStep, diff, 100 * diff / perStep));
            }
        }
        if (sb.length() > 0) {
            line("Per-sample overhead, the same 1,000-mass string stepped one sample at a time (audio-1000) or in big "
                    + "chunks (chain-1000), measured in different JVMs, so only a rough figure:" + sb);
            blank();
        }
    }

    private static double[] nsPerStep(Map<String, String> m) {
        double[] sps = arr(m, "sps");
        double[] v = new double[sps.length];
        for (int i = 0; i < v.length; i++) {
            v[i] = 1e9 / sps[i];
        }
        return v;
    }

    private void kernels() {
        line("## Where the time goes: per-kernel profile");
        blank();
        line("Per scene and variant, the kernels of the compiled plan in the order they run (one kernel per kind of "
                + "module, one per stencil run), with the elements each one handles and its time per step. 'whole "
                + "step' is `StepPlan.step()` timed in blocks between the per-kernel blocks (the sum of the kernel "
                + "times is a little higher: one nanoTime per kernel); 'divergence guard' is the scan every 64 steps, "
                + "amortised per step (Engine.step runs it; it is part of the measured figures above).");
        blank();
        line("| scene / variant | kernel | elements | JDK 17 ns/step | share | ns/element | JDK 25 ns/step | ns/element |");
        line("|---|---|---|---|---|---|---|---|");
        List<String> scenes = new ArrayList<>();
        for (String s : CHAINS) {
            scenes.add(s);
        }
        for (String s : MESHES) {
            scenes.add(s);
        }
        for (String s : MARBLES) {
            scenes.add(s);
        }
        scenes.add("overhead");
        for (String s : scenes) {
            Bench.ChildRun r = run(s, "17");
            if (r == null || r.results.isEmpty()) {
                continue;
            }
            for (Map<String, String> m : r.results) {
                String v = m.get("variant");
                if (s.equals("overhead") && !(v.equals(PM) || v.equals("Engine, stencil runs off"))) {
                    continue;
                }
                List<String[]> k17 = profile(m);
                if (k17.isEmpty()) {
                    continue;
                }
                Map<String, String> m25 = res(s, "25", v);
                List<String[]> k25 = m25 == null ? new ArrayList<>() : profile(m25);
                double sum = 0;
                for (String[] k : k17) {
                    if (!k[0].equals("step") && !k[0].equals("guard")) {
                        sum += Double.parseDouble(k[2]);
                    }
                }
                for (int i = 0; i < k17.size(); i++) {
                    String[] k = k17.get(i);
                    String[] q = i < k25.size() && baseName(k25.get(i)[0]).equals(baseName(k[0])) ? k25.get(i) : null;
                    double ns = Double.parseDouble(k[2]);
                    long el = Long.parseLong(k[1]);
                    String name = k[0].equals("step") ? "**whole step**" : k[0].equals("guard") ? "divergence guard"
                            : k[0];
                    boolean real = !k[0].equals("step") && !k[0].equals("guard");
                    long elements = k[0].equals("step") ? elements(m) : el;
                    String elCell = k[0].equals("guard") ? "–" : elements >= 0 ? f("%,d", elements) : "?";
                    line("| " + (i == 0 ? s + " / " + v : "") + " | " + name + " | " + elCell + " | "
                            + f("%,.0f", ns) + " | " + (real ? pct(ns / sum) : "") + " | "
                            + (elements > 0 && !k[0].equals("guard") ? f("%.2f", ns / elements) : "–") + " | "
                            + (q == null ? "–" : f("%,.0f", Double.parseDouble(q[2]))) + " | "
                            + (q == null || elements <= 0 || k[0].equals("guard") ? "–"
                                    : f("%.2f", Double.parseDouble(q[2]) / elements)) + " |");
                }
            }
        }
        blank();
    }

    /** A kernel's name without the run-dependent details (listed pairs, rebuild rate) that follow it. */
    private static String baseName(String name) {
        int cut = name.length();
        for (char c : new char[] {'(', ','}) {
            int i = name.indexOf(c);
            if (i >= 0 && !name.startsWith("StencilKernel")) {
                cut = Math.min(cut, i);
            }
        }
        return name.substring(0, cut);
    }

    private static List<String[]> profile(Map<String, String> m) {
        List<String[]> out = new ArrayList<>();
        String s = m.getOrDefault("profile", "");
        if (s.isEmpty()) {
            return out;
        }
        for (String e : s.split("\\|")) {
            String[] k = e.split("~");
            if (k.length == 3) {
                out.add(k);
            }
        }
        return out;
    }

    private void sketchers() {
        line("## In plain words, for sketchers");
        blank();
        Map<String, String> a1000 = res("audio-1000", "17", HANDLE);
        Map<String, String> a500 = res("audio-500", "17", HANDLE);
        Map<String, String> m200 = res("marbles-200", "17", EXPLICIT);
        Map<String, String> g200 = res("marbles-200", "17", GROUP);
        Map<String, String> c1000 = res("chain-1000", "17", PM);
        StringBuilder sb = new StringBuilder();
        if (a1000 != null) {
            double share = (1e9 / med(a1000, "sps")) / SAMPLE_NS;
            sb.append(f("A 1,000-mass string (2,001 elements) played at audio rate, 44,100 steps per second with one "
                    + "listening point, uses about **%.0f%% of one core** on this machine (JDK 17).", 100 * share));
            if (a500 != null) {
                sb.append(f(" A 500-mass string uses about %.0f%%.", 100 * (1e9 / med(a500, "sps")) / SAMPLE_NS));
            }
        }
        if (c1000 != null) {
            double cap = 1e9 / (AUDIO * med(c1000, "ns"));
            sb.append(f(" As a rule of thumb, at audio rate one core computes about %s elements (masses plus "
                    + "springs) of a string if it does nothing else; keep to about half, %s, to leave room for "
                    + "drawing, the audio library and the rest of the sketch.", count(cap), count(cap / 2)));
        }
        if (m200 != null) {
            sb.append(f(" At the 1 kHz haptic rate, 200 marbles that all collide with each other take %.0f%% of a "
                    + "core with one Contact3D per pair", 100 * HAPTIC / med(m200, "sps")));
            if (g200 != null) {
                sb.append(f(" and %.0f%% with a contact group", 100 * HAPTIC / med(g200, "sps")));
            }
            sb.append('.');
        }
        sb.append(" These figures are for the physics alone: drawing thousands of masses in Processing usually costs "
                + "more than simulating them, and a machine busy with other programs gives you less.");
        line(sb.toString());
        blank();
    }

    private void loadTable() {
        line("## Runs and machine load");
        blank();
        line("Each child JVM, in the order run: its wall time, the load average (1, 5, 15 min; running/total "
                + "threads) when it started and ended, and the median CPU/wall share of its runs (100% = never "
                + "descheduled). High load or a low share makes that row's figures less trustworthy.");
        blank();
        line("| scene | JDK | child wall time | load at start | load at end | CPU/wall (kept runs) | rounds kept / "
                + "measured | status |");
        line("|---|---|---|---|---|---|---|---|");
        for (Bench.ChildRun r : p.runs) {
            double cpu = Double.NaN;
            if (!r.results.isEmpty()) {
                List<Double> all = new ArrayList<>();
                for (Map<String, String> m : r.results) {
                    for (double d : arr(m, "cpu")) {
                        all.add(d);
                    }
                }
                double[] v = new double[all.size()];
                for (int i = 0; i < v.length; i++) {
                    v[i] = all.get(i);
                }
                cpu = Harness.median(v);
            }
            String status = r.ok ? (r.skipped != null ? "skipped: " + r.skipped : "ok") : r.error;
            String rounds = r.results.isEmpty() ? "–"
                    : arr(r.results.get(0), "ns").length + " / " + r.results.get(0).get("rounds");
            line("| " + r.scene + " | " + r.jdk + " | " + f("%.0f s", r.seconds) + " | "
                    + r.info.getOrDefault("loadStart", "–") + " | " + r.info.getOrDefault("loadEnd", "–") + " | "
                    + pct(cpu) + " | " + rounds + " | " + status.replace('|', '/') + " |");
        }
        blank();
    }

    private void reproduce() {
        line("## Reproducing");
        blank();
        line("`gradle bench` runs everything (the standard scenes, about 10 minutes, then the side-by-side scenes "
                + "against the paper's engine, then the side by side with Faust; see those sections) and rewrites this "
                + "file, keeping its kept sections. `-Pscenes=faust` runs the Faust comparison alone (about 4 minutes once "
                + "the programs are compiled; compiling the 3-D string of 1,000 masses takes faust and g++ several "
                + "minutes once, kept in build/faustbench), `-Pscenes=faust/string1d-100` one model. "
                + "`-Pscenes=standard` runs the standard scenes only, `-Pquick` shortens the runs, "
                + "`-PbenchArgs=\"--only=chain-1000,overhead --jdk=17\"` passes options through. By hand: "
                + "`java -cp build/classes/java/tools:build/classes/java/main:<processing core jar> tactus.bench.Bench "
                + "docs/performance.md [--quick] [--scenes=standard] [--only=chain-1000,overhead] [--jdk=17|25|both] "
                + "[--jdk25=<java>]`. `test/tactus/bench/BenchSmokeTest` checks the harness (a few hundred steps, no "
                + "timing) as part of `gradle test`.");
        blank();
        if (!hasJdk("25")) {
            line("JDK 25 was not available at `" + Bench.JDK25 + "`: its columns are empty.");
            blank();
        }
    }
}
