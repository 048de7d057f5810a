package tactus.bench;

import ddf.minim.ugens.Summer;
import java.io.BufferedReader;
import java.io.File;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.PrintWriter;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import tactus.Mass;
import tactus.PhysicalModel;
import tactus.Vect3D;
import tactus.audio.PhyUGen;
import tactus.audio.SteppedModel;
import tactus.audio.VoiceBank;
import tactus.export.FaustExportOptions;
import tactus.export.FaustExporter;
import tactus.faust.FaustCost;
import tactus.faust.FaustToolchain;

/**
 * The Faust column of {@code gradle bench} (issues #27, #36): each model exported with {@code FaustExporter}, compiled with
 * {@code faust -double} and {@code g++ -O3} (and {@code -O3 -march=native}), and timed per sample against Tactus
 * stepping the same model, through {@code computeStep()} plus an allocation-free read, and through a {@code PhyUGen}
 * ticked by a Minim {@code Summer} as an output ticks it. One process per engine: each Faust program runs in its own
 * process per measurement ({@code -bench}: its own warm-up, then the timed samples), Tactus in one child JVM that
 * keeps its models between measurements; the engines alternate within each round (the order reversed every round),
 * ratios are taken per round and the medians over rounds are reported. Times are CPU times of the measuring thread
 * (Tactus) or process (Faust), so that the other load of a shared machine counts as little as possible; the
 * wall-clock figures are printed beside them.
 *
 * <p>Models: 1-D strings of 30, 100, 300 and 1,000 masses (Mass1D, SpringDamper1D), the 8 x 8 metal plate (Osc1D),
 * 3-D strings of 100 and 1,000 masses (Mass3D, SpringDamper3D), 8 and 16 voices of the 100-mass 1-D string (V Faust
 * instances in one program; V models with a PhyUGen each on one Summer), and 16 voices of the 30- and 100-mass strings
 * in one {@code VoiceBank} (one model, one PhyUGen). The compiled programs are kept in {@code build/faustbench}
 * and reused while the exported source is the same. Without {@code faust} or {@code g++} the Faust column says so
 * and Tactus is measured alone.
 */
public final class FaustSideBySide {
    /** Model ids, in report order. */
    static final String[] MODELS = {"string1d-30", "string1d-100", "string1d-300", "string1d-1000", "plate-8x8",
        "string3d-100", "string3d-1000", "voices8-string1d-100", "voices16-string1d-100", "bank16-string1d-30",
        "bank16-string1d-100"};
    private static final int RATE = 44100;
    private static final double SAMPLE_NS = 1e9 / RATE;
    private static final String TAG = "<!-- side by side with Faust (gradle bench) -->";
    private static final String[] FLAVOURS = {"-O3", "-O3 -march=native"};

    private FaustSideBySide() {
    }

    /** The system property that sets the PhyUGens' block size in the Tactus process ({@code --block=N}). */
    static final String BLOCK_PROPERTY = "tactus.bench.block";
    /**
     * The PhyUGens' block size unless {@code --block=N} says otherwise: the PhyUGen's default, 64 samples, one call to
     * the model per block ({@code PhyUGen.setBlockSize}).
     */
    static final int DEFAULT_BLOCK = PhyUGen.DEFAULT_BLOCK_SIZE;
    /** The cost of one element update that SIMD code can reach with the model in cache (issue #36), in ns. */
    static final double ELEMENT_LIMIT_NS = 0.3;

    /** Options of a run. */

    static final class Options {
        boolean quick;
        List<String> models = new ArrayList<>(Arrays.asList(MODELS));
        File work = new File("build/faustbench");
        int timeoutSeconds = 900;
        long faustMemoryKb = 6_000_000;
        /** 1-D string sizes (masses) for the largest string in real time; 3-D strings of {@link #largest3d}. */
        int[] largest = {10_000, 12_500, 15_000};
        int[] largest3d = {5_000, 6_000};
        /** Only compile the Faust programs (into {@link #work}), measure nothing. */
        boolean compileOnly;
    }

    /**
     * {@code java tactus.bench.FaustSideBySide [--quick] [--models=a,b] [--largest=5000,10000] [--block=N]
     * [--compile-only] [report.md]}, or {@code --child} (the Tactus process).
     */
    public static void main(String[] args) throws Exception {
        if (args.length > 0 && args[0].equals("--child")) {
            child();
            return;
        }
        Options o = new Options();
        String out = "docs/performance.md";
        for (String a : args) {
            if (a.equals("--quick")) {
                o.quick = true;
            } else if (a.startsWith("--models=")) {
                o.models = Arrays.asList(a.substring(9).split(","));
            } else if (a.startsWith("--largest=")) {
                o.largest = a.length() == 10 ? new int[0]
                        : Arrays.stream(a.substring(10).split(",")).mapToInt(Integer::parseInt).toArray();
                o.largest3d = new int[0];
            } else if (a.startsWith("--block=")) {
                System.setProperty(BLOCK_PROPERTY, a.substring(8));   // the PhyUGens' block size (default 64)
            } else if (a.equals("--compile-only")) {
                o.compileOnly = true;
            } else {
                out = a;
            }
        }
        run(new File(out), o);
    }

    // ================================================================================================ models

    /** @return the model of an id (for voices: one voice). */
    static PhysicalModel model(String id) {
        if (multiVoice(id)) {
            return model(voice(id));
        }
        if (id.equals("plate-8x8")) {
            return plate(8);
        }
        int n = Integer.parseInt(id.substring(id.indexOf('-') + 1));
        return FaustCost.string(n, id.startsWith("string3d"));
    }

    /** @return the listening mass of a model: mass 2n/3 + 1 of a string, p3_5 of the plate. */
    static String listened(String id) {
        if (multiVoice(id)) {
            return listened(voice(id));
        }
        if (id.equals("plate-8x8")) {
            return "p3_5";
        }
        int n = Integer.parseInt(id.substring(id.indexOf('-') + 1));
        return "m" + (2 * n / 3 + 1);
    }

    /**
     * @return true for an id of several voices: "voicesV-&lt;model&gt;" (V models) or "bankV-&lt;model&gt;" (one
     *     VoiceBank of V voices)
     */
    static boolean multiVoice(String id) {
        return id.startsWith("voices") || id.startsWith("bank");
    }

    /** @return the number of voices of a model id: V for "voicesV-&lt;model&gt;" or "bankV-&lt;model&gt;", else 1. */
    static int voices(String id) {
        return multiVoice(id) ? Integer.parseInt(id.substring(id.startsWith("bank") ? 4 : 6, id.indexOf('-'))) : 1;
    }

    /** @return the model one voice of a "voicesV-&lt;model&gt;" id plays. */
    static String voice(String id) {
        return id.substring(id.indexOf('-') + 1);
    }

    /**
     * @return the VoiceBank of a "bankV-string1d-N" id: V voices of {@link FaustCost#string}'s 1-D string in one
     *     model, each struck as that string is
     */
    static VoiceBank bank(String id) {
        int n = Integer.parseInt(voice(id).substring("string1d-".length()));
        PhysicalModel m = new PhysicalModel(RATE);
        VoiceBank bank = new VoiceBank(m, voices(id), (mm, prefix, v) -> FaustCost.addString(mm, prefix, n, false));
        m.init();
        for (int v = 0; v < bank.size(); v++) {
            m.triggerForceImpulse(bank.name(v, FaustCost.struckMass(n)), 0, 0, 1);
        }
        return bank;
    }

    /** The 8 x 8 plate of {@link FaustCost#plate}, struck at p2_2. */
    static PhysicalModel plate(int n) {
        PhysicalModel m = FaustCost.plate(n);
        m.triggerForceImpulse("p2_2", 0, 0, 1);
        return m;
    }

    /** @return the Faust source of a model: one output, the listening mass along z. */
    static String dsp(String id) {
        return FaustExporter.toDsp(model(id), new FaustExportOptions().name(id.replace('-', '_'))
                .listen(listened(id), SteppedModel.Z, 1));
    }

    // ================================================================================================ child

    /** One model as Tactus plays it, in both forms. */
    private static final class Subject {
        final PhysicalModel[] models;
        final Mass[] reads;
        final Summer root = new Summer();
        final float[] frame = new float[1];
        final Vect3D scratch = new Vect3D();

        Subject(String id) {
            int v = voices(id);
            int block = Integer.getInteger(BLOCK_PROPERTY, DEFAULT_BLOCK);
            reads = new Mass[v];
            if (id.startsWith("bank")) {   // one model of V voices, stepped; another, heard through one PhyUGen
                VoiceBank stepped = bank(id);
                models = new PhysicalModel[] {stepped.getModel()};
                for (int i = 0; i < v; i++) {
                    reads[i] = stepped.getModel().getMass(stepped.name(i, listened(id)));
                }
                VoiceBank heard = bank(id);
                PhyUGen u = new PhyUGen(heard.getModel());
                u.setBlockSize(block);
                heard.listenToMass(u, listened(id), SteppedModel.Z, 1, 0);
                patch(u);
            } else {
                models = new PhysicalModel[v];
                for (int i = 0; i < v; i++) {
                    models[i] = model(id);
                    reads[i] = models[i].getMass(listened(id));
                    PhyUGen u = new PhyUGen(model(id));
                    u.setBlockSize(block);
                    u.listenToMass(listened(id), SteppedModel.Z, 1, 0);
                    patch(u);
                }
            }
            root.setSampleRate(RATE);
            root.setChannelCount(1);
        }

        private void patch(PhyUGen u) {
            u.patch(root);
            u.setSampleRate(RATE);
            u.setChannelCount(1);
        }

        double step(int samples) {
            double sum = 0;
            for (int s = 0; s < samples; s++) {
                for (PhysicalModel m : models) {
                    m.computeStep();
                }
                for (Mass r : reads) {
                    sum += r.getPosition(scratch).z;
                }
            }
            return sum;
        }

        double tick(int samples) {
            double sum = 0;
            for (int s = 0; s < samples; s++) {
                frame[0] = 0;
                root.tick(frame);
                sum += frame[0];
            }
            return sum;
        }
    }

    /**
     * The Tactus process: reads lines "{@code <model> <seconds>}" and answers "{@code ok <step wall> <step cpu>
     * <ugen wall> <ugen cpu>}" in ns per sample (per sample of all voices), each form run for about the given time
     * after a warm-up of the model's first use.
     */
    private static void child() throws IOException {
        ThreadMXBean cpu = ManagementFactory.getThreadMXBean();
        Map<String, Subject> subjects = new LinkedHashMap<>();
        BufferedReader in = new BufferedReader(new InputStreamReader(System.in, StandardCharsets.UTF_8));
        PrintWriter out = new PrintWriter(System.out, true);
        double sink = 0;
        for (String line; (line = in.readLine()) != null; ) {
            String[] t = line.trim().split(" ");
            if (t.length < 2) {
                break;
            }
            Subject s = subjects.get(t[0]);
            double seconds = Double.parseDouble(t[1]);
            if (s == null) {
                s = new Subject(t[0]);
                subjects.put(t[0], s);
                for (long end = System.nanoTime() + 2_000_000_000L; System.nanoTime() < end; ) {
                    sink += s.step(512) + s.tick(512);
                }
            }
            double[] r = new double[4];
            for (int form = 0; form < 2; form++) {
                long n = 0;
                long w0 = System.nanoTime();
                long c0 = cpu.getCurrentThreadCpuTime();
                long end = w0 + (long) (seconds * 1e9);
                do {
                    sink += form == 0 ? s.step(512) : s.tick(512);
                    n += 512;
                } while (System.nanoTime() < end);
                r[2 * form] = (System.nanoTime() - w0) / (double) n;
                r[2 * form + 1] = (cpu.getCurrentThreadCpuTime() - c0) / (double) n;
            }
            out.printf(Locale.ROOT, "ok %.3f %.3f %.3f %.3f %s%n", r[0], r[1], r[2], r[3], Double.isNaN(sink) ? "nan" : "finite");
        }
    }

    /** The Tactus child JVM, same flags as the bench's children. */
    private static final class TactusProcess implements AutoCloseable {
        final Process p;
        final PrintWriter to;
        final BufferedReader from;

        TactusProcess() throws IOException {
            String java = System.getProperty("java.home") + File.separator + "bin" + File.separator + "java";
            ProcessBuilder pb = new ProcessBuilder(java, "-Xms1g", "-Xmx1g", "-XX:+UseParallelGC",
                    "-D" + BLOCK_PROPERTY + "=" + Integer.getInteger(BLOCK_PROPERTY, DEFAULT_BLOCK), "-cp",
                    System.getProperty("java.class.path"), FaustSideBySide.class.getName(), "--child");
            pb.redirectError(ProcessBuilder.Redirect.INHERIT);
            p = pb.start();
            to = new PrintWriter(p.getOutputStream(), true, StandardCharsets.UTF_8);
            from = new BufferedReader(new InputStreamReader(p.getInputStream(), StandardCharsets.UTF_8));
        }

        double[] measure(String id, double seconds) throws IOException {
            to.println(id + " " + seconds);
            String line = from.readLine();
            if (line == null || !line.startsWith("ok ")) {
                throw new IllegalStateException("the Tactus child answered " + line);
            }
            String[] t = line.split(" ");
            if (!t[5].equals("finite")) {
                throw new IllegalStateException(id + ": Tactus's output is not finite");
            }
            return new double[] {Double.parseDouble(t[1]), Double.parseDouble(t[2]), Double.parseDouble(t[3]),
                Double.parseDouble(t[4])};
        }

        @Override
        public void close() throws IOException {
            to.close();
            try {
                if (!p.waitFor(20, java.util.concurrent.TimeUnit.SECONDS)) {
                    p.destroyForcibly();
                }
            } catch (InterruptedException e) {
                p.destroyForcibly();
                Thread.currentThread().interrupt();
            }
        }
    }

    // ================================================================================================ parent

    /** What one model measured: per round, [wall, cpu] per column. */
    private static final class Row {
        final String id;
        String faustProblem;
        final List<double[]> faustO3 = new ArrayList<>();
        final List<double[]> faustNative = new ArrayList<>();
        final List<double[]> tactus = new ArrayList<>();

        Row(String id) {
            this.id = id;
        }
    }

    /** Runs every model and writes the section into the report. */
    static void run(File report, Options o) throws IOException, InterruptedException {
        long start = System.nanoTime();
        String loadStart = Bench.loadavg();
        String tools = toolsProblem();
        if (tools != null) {
            System.out.println("Faust side by side: " + tools + "; Tactus is measured alone (not compared)");
        }
        FaustToolchain.limitFaustMemory(o.faustMemoryKb);
        Path work = o.work.toPath().toAbsolutePath();
        Map<String, Path[]> programs = new LinkedHashMap<>();
        List<Row> rows = new ArrayList<>();
        for (String id : o.models) {
            Row row = new Row(id);
            rows.add(row);
            if (tools != null) {
                row.faustProblem = tools;
                continue;
            }
            try {
                programs.put(id, compile(id, work, o.timeoutSeconds));
            } catch (IllegalStateException | IOException e) {
                row.faustProblem = "does not compile: " + firstLine(e.getMessage());
                System.out.println(id + ": Faust program " + row.faustProblem);
            }
        }
        if (o.compileOnly) {
            return;
        }
        int rounds = o.quick ? 3 : 5;
        double seconds = o.quick ? 0.25 : 0.5;
        try (TactusProcess tactus = new TactusProcess()) {
            for (int r = 0; r < rounds; r++) {
                for (Row row : rows) {
                    Path[] exe = programs.get(row.id);
                    boolean faustFirst = r % 2 == 0;
                    if (!faustFirst) {
                        row.tactus.add(tactus.measure(row.id, seconds));
                    }
                    if (exe != null) {
                        double estimate = row.tactus.isEmpty() ? 1_000 * voices(row.id) : row.tactus.get(0)[3];
                        int samples = (int) Math.max(20_000, Math.min(50_000_000, seconds * 1e9 / estimate));
                        row.faustO3.add(FaustToolchain.benchmark(exe[0], samples, voices(row.id), 600));
                        row.faustNative.add(FaustToolchain.benchmark(exe[1], samples, voices(row.id), 600));
                    }
                    if (faustFirst) {
                        row.tactus.add(tactus.measure(row.id, seconds));
                    }
                    System.out.println(progress(row, r));
                }
            }
        }
        List<double[]> largest = largestString(o);
        String loadEnd = Bench.loadavg();
        String section = section(rows, largest, rounds, seconds, loadStart, loadEnd, (System.nanoTime() - start) / 1e9);
        String old = report.exists() ? new String(Files.readAllBytes(report.toPath()), StandardCharsets.UTF_8) : "";
        Files.write(report.toPath(), SideBySideReport.replaceSection(old, section, TAG).getBytes(StandardCharsets.UTF_8));
        System.out.println("Faust side by side written into " + report);
    }

    private static String progress(Row row, int round) {
        double[] t = row.tactus.get(row.tactus.size() - 1);
        String f = row.faustO3.isEmpty() ? "Faust: " + row.faustProblem
                : String.format(Locale.ROOT, "Faust -O3 %.0f ns, native %.0f ns (cpu)", last(row.faustO3)[1],
                        last(row.faustNative)[1]);
        return String.format(Locale.ROOT, "round %d %s: Tactus computeStep %.0f ns, PhyUGen %.0f ns (cpu); %s", round + 1,
                row.id, t[1], t[3], f);
    }

    private static double[] last(List<double[]> l) {
        return l.get(l.size() - 1);
    }

    /** @return why Faust cannot be measured here (a missing tool), or null. */
    private static String toolsProblem() {
        try {
            FaustToolchain.requireTools();
            return null;
        } catch (IllegalStateException e) {
            return "skipped, " + firstLine(e.getMessage());
        }
    }

    private static String firstLine(String s) {
        if (s == null) {
            return "";
        }
        int nl = s.indexOf('\n');
        return nl < 0 ? s : s.substring(0, nl);
    }

    /**
     * @return the two executables (-O3, -O3 -march=native) of a model, compiled once and kept; a failure is kept too
     *     (a file {@code <id>.failed}), so that a model faust cannot compile is not tried again at every run (not a
     *     timeout: delete build/faustbench to try a failed model again)
     */
    static Path[] compile(String id, Path work, int timeout) throws IOException {
        String name = multiVoice(id) ? voice(id) : id;
        String dsp = dsp(name);
        Path failed = work.resolve(name + ".failed");
        Path src = work.resolve(name + ".dsp");
        if (Files.exists(failed) && Files.exists(src)
                && new String(Files.readAllBytes(src), StandardCharsets.UTF_8).equals(dsp)) {
            throw new IllegalStateException(new String(Files.readAllBytes(failed), StandardCharsets.UTF_8));
        }
        try {
            long t0 = System.nanoTime();
            Path cpp = FaustToolchain.faustCpp(dsp, work, name, true, timeout, true);
            Path[] exe = new Path[FLAVOURS.length];
            for (int i = 0; i < FLAVOURS.length; i++) {
                exe[i] = FaustToolchain.gpp(cpp, work.resolve(name + (i == 0 ? "-O3" : "-native")), FLAVOURS[i], timeout,
                        true);
            }
            System.out.printf(Locale.ROOT, "%s: Faust programs ready (%.0f s)%n", name, (System.nanoTime() - t0) / 1e9);
            Files.deleteIfExists(failed);
            return exe;
        } catch (IllegalStateException e) {
            if (e.getMessage() == null || !e.getMessage().contains("did not finish within")) {
                // a compiler that fails fails again; one that ran out of time on a busy machine may finish next time
                Files.write(failed, firstLine(e.getMessage()).getBytes(StandardCharsets.UTF_8));
            }
            throw e;
        }
    }

    /**
     * The largest string a PhyUGen plays in real time on one core: 1-D and 3-D strings of the given sizes rendered
     * through Minim's tick in a Tactus child, CPU time per sample, the best of a few runs.
     *
     * @return per size: {masses, 1 for 3-D, wall ns, cpu ns}
     */
    private static List<double[]> largestString(Options o) throws IOException {
        List<double[]> out = new ArrayList<>();
        if (o.largest.length + o.largest3d.length == 0) {
            return out;
        }
        try (TactusProcess tactus = new TactusProcess()) {
            for (int threeD = 0; threeD < 2; threeD++) {
                for (int n : threeD == 0 ? o.largest : o.largest3d) {
                    double[] best = null;
                    for (int r = 0; r < (o.quick ? 2 : 3); r++) {
                        double[] t = tactus.measure((threeD == 0 ? "string1d-" : "string3d-") + n, o.quick ? 0.5 : 1.0);
                        if (best == null || t[3] < best[3]) {
                            best = t;
                        }
                    }
                    out.add(new double[] {n, threeD, best[2], best[3]});
                    System.out.printf(Locale.ROOT, "%s string of %d masses through PhyUGen: %.0f ns per sample (cpu)%n",
                            threeD == 0 ? "1-D" : "3-D", n, best[3]);
                }
            }
        }
        return out;
    }

    // ================================================================================================ report

    private static double median(List<Double> v) {
        double[] a = v.stream().mapToDouble(Double::doubleValue).sorted().toArray();
        return a.length == 0 ? Double.NaN : a.length % 2 == 1 ? a[a.length / 2] : (a[a.length / 2 - 1] + a[a.length / 2]) / 2;
    }

    private static List<Double> column(List<double[]> l, int k) {
        List<Double> v = new ArrayList<>();
        for (double[] d : l) {
            v.add(d[k]);
        }
        return v;
    }

    /** Per-round ratios a[ka] / b[kb]. */
    private static List<Double> ratios(List<double[]> a, int ka, List<double[]> b, int kb) {
        List<Double> v = new ArrayList<>();
        for (int i = 0; i < Math.min(a.size(), b.size()); i++) {
            v.add(a.get(i)[ka] / b.get(i)[kb]);
        }
        return v;
    }

    private static String spread(List<Double> v, String format) {
        if (v.isEmpty()) {
            return "–";
        }
        double lo = v.stream().mapToDouble(Double::doubleValue).min().getAsDouble();
        double hi = v.stream().mapToDouble(Double::doubleValue).max().getAsDouble();
        return String.format(Locale.ROOT, format + " (" + format + "–" + format + ")", median(v), lo, hi);
    }

    private static String label(String id) {
        switch (id) {
            case "plate-8x8":
                return "8×8 metal plate (64 Osc1D, 112 SpringDamper1D)";
            case "voices8-string1d-100":
            case "voices16-string1d-100":
                return voices(id) + " voices of the 100-mass 1-D string (per sample of all voices)";
            case "bank16-string1d-30":
            case "bank16-string1d-100":
                return voices(id) + " voices of the " + voice(id).substring("string1d-".length())
                        + "-mass 1-D string in one `VoiceBank`"
                        + " (one model, one PhyUGen; per sample of all voices)";
            default:
                int n = Integer.parseInt(id.substring(id.indexOf('-') + 1));
                return String.format(Locale.ROOT, "%s string, %,d masses", id.startsWith("string3d") ? "3-D" : "1-D", n);
        }
    }

    /**
     * @return the target ratio (Faust -O3 / PhyUGen) of issue #36 for a model: 1x at 30 masses, on the plate and per
     *     voice; 2x at 100 masses and 3x at 300 (1-D); 3x on 3-D strings
     */
    static double target(String id) {
        if (id.startsWith("string3d") || id.equals("string1d-300") || id.equals("string1d-1000")) {
            return 3;
        }
        if (id.equals("string1d-100")) {
            return 2;
        }
        return 1;
    }

    /** @return the element updates (masses plus interactions) of one step of a model, all voices together. */
    static int elements(String id) {
        PhysicalModel m = model(id);
        return voices(id) * (m.getNumberOfMats() + m.getNumberOfLinks());
    }

    /**
     * Says how far to trust the absolute figures: a machine whose 1-minute load stayed below its core count is
     * called quiet; otherwise it was shared, and only the per-round ratios are comparable.
     */
    private static String loadVerdict(String loadStart, String loadEnd) {
        double cores = Runtime.getRuntime().availableProcessors();
        if (firstNumber(loadStart) < cores && firstNumber(loadEnd) < cores) {
            return "a quiet machine (the 1-minute load below the core count throughout); the ratios are still taken "
                    + "per round, engines alternating";
        }
        return "**the machine was shared with other work**, so read the ratios (taken per round, engines alternating) "
                + "rather than the absolute figures";
    }

    /** @return the first number of a load-average line, or infinity when there is none. */
    private static double firstNumber(String loadLine) {
        try {
            return Double.parseDouble(loadLine.trim().split("\\s+")[0]);
        } catch (RuntimeException e) {
            return Double.POSITIVE_INFINITY;
        }
    }

    private static String section(List<Row> rows, List<double[]> largest, int rounds, double seconds, String loadStart,
                                  String loadEnd, double wallSeconds) {
        StringBuilder s = new StringBuilder();
        s.append(Bench.KEPT_BEGIN).append('\n').append(TAG).append('\n');
        s.append("## Side by side with Faust's compiled C++ (issues #27, #36)\n\n");
        s.append(String.format(Locale.ROOT, "Generated by `gradle bench` (`tactus.bench.FaustSideBySide`) on %s, in %.0f s, "
                + "%d rounds. Machine: %s, %d cores, JDK %s; Faust %s, %s. Load average (1, 5, 15 min) %s at start, %s at "
                + "end: %s.\n\n", java.time.ZonedDateTime.now(java.time.ZoneOffset.UTC)
                .format(java.time.format.DateTimeFormatter.ofPattern("yyyy-MM-dd HH:mm 'UTC'")), wallSeconds, rounds,
                cpuName(), Runtime.getRuntime().availableProcessors(), System.getProperty("java.vm.version"),
                version("faust", "--version"), version("g++", "--version"), loadStart, loadEnd,
                loadVerdict(loadStart, loadEnd)));
        s.append("ns per sample, CPU time of the measuring thread (Tactus) or process (Faust), median of the rounds "
                + "(min–max); a voices row is per sample of all its voices. Share = PhyUGen's time over the 22.7 µs of a "
                + "sample at 44.1 kHz. Ratio = Faust's time / PhyUGen's time, per round (above 1: Tactus faster). Per "
                + "element = PhyUGen's time over the element updates (masses plus interactions, all voices) of one "
                + "sample, against about " + ELEMENT_LIMIT_NS + " ns that SIMD code reaches with the model in cache. "
                + "The PhyUGens compute blocks of " + Integer.getInteger(BLOCK_PROPERTY, DEFAULT_BLOCK) + " samples "
                + "(`setBlockSize`; `--block=1` measures the per-sample path).\n\n");
        s.append("| model | Faust -O3 | Faust -O3 -march=native | Tactus `computeStep` + read | Tactus `PhyUGen` (Minim tick) "
                + "| PhyUGen share of 22.7 µs | PhyUGen per element | ratio -O3 / PhyUGen | ratio native / PhyUGen | target "
                + "| verdict |\n");
        s.append("|---|---|---|---|---|---|---|---|---|---|---|\n");
        for (Row r : rows) {
            String o3 = r.faustO3.isEmpty() ? r.faustProblem : spread(column(r.faustO3, 1), "%.0f");
            String nat = r.faustNative.isEmpty() ? "–" : spread(column(r.faustNative, 1), "%.0f");
            double ugen = median(column(r.tactus, 3));
            List<Double> ratio = ratios(r.faustO3, 1, r.tactus, 3);
            List<Double> ratioNative = ratios(r.faustNative, 1, r.tactus, 3);
            double target = target(r.id);
            String verdict = ratio.isEmpty() ? "not compared" : median(ratio) >= target ? "met" : "**not met**";
            s.append(String.format(Locale.ROOT, "| %s | %s | %s | %s | %s | %.1f%% | %.2f ns (%.0f× the limit) | %s | %s "
                    + "| ≥ %.1f× | %s |\n", label(r.id),
                    o3, nat, spread(column(r.tactus, 1), "%.0f"), spread(column(r.tactus, 3), "%.0f"),
                    100 * ugen / SAMPLE_NS, ugen / elements(r.id), ugen / elements(r.id) / ELEMENT_LIMIT_NS,
                    ratio.isEmpty() ? "–" : spread(ratio, "%.2f×"),
                    ratioNative.isEmpty() ? "–" : spread(ratioNative, "%.2f×"), target, verdict));
        }
        s.append("\nWall-clock time of the same runs (ns per sample, medians): ");
        List<String> wall = new ArrayList<>();
        for (Row r : rows) {
            wall.add(String.format(Locale.ROOT, "%s: Faust -O3 %s, native %s, computeStep %.0f, PhyUGen %.0f", r.id,
                    r.faustO3.isEmpty() ? "–" : String.format(Locale.ROOT, "%.0f", median(column(r.faustO3, 0))),
                    r.faustNative.isEmpty() ? "–" : String.format(Locale.ROOT, "%.0f", median(column(r.faustNative, 0))),
                    median(column(r.tactus, 0)), median(column(r.tactus, 2))));
        }
        s.append(String.join("; ", wall)).append(".\n\n");
        if (!largest.isEmpty()) {
            s.append("**The largest string a PhyUGen plays in real time on one core** (Minim's tick, one listening "
                    + "point, CPU time, best of the runs; the strings of the table above): ");
            List<String> l = new ArrayList<>();
            for (double[] d : largest) {
                l.add(String.format(Locale.ROOT, "%s, %,d masses (%,d elements): %.1f µs per sample, %.0f%% of a core, "
                        + "%.2f ns per element", d[1] == 1 ? "3-D" : "1-D", (int) d[0], 2 * (int) d[0] + 1, d[3] / 1000,
                        100 * d[3] / SAMPLE_NS, d[3] / (2 * d[0] + 1)));
            }
            s.append(String.join("; ", l)).append(". Target (issues #27, #36): at least 25,000 elements in real time.\n\n");
        }
        s.append(String.format(Locale.ROOT, "Method: the models are exported with `FaustExporter` (one output: the listening "
                + "mass along z; no input), translated with `faust -double` and compiled against "
                + "`tools/tactus/faust/offline.cpp` with `g++ -O3` and `g++ -O3 -march=native` (kept in build/faustbench). "
                + "A Faust measurement is one process: `-bench` renders in blocks of 256 samples, a tenth of the samples "
                + "untimed first, then about %.2f s timed; `-voices V` renders V instances in turn per block. Tactus runs "
                + "in one child JVM (`-Xms1g -Xmx1g -XX:+UseParallelGC`) that builds each model on first use, warms it for "
                + "2 s, then measures about %.2f s of `computeStep()` + `Mass.getPosition(Vect3D)` per sample (a "
                + "voices row: each voice its own model; a `VoiceBank` row: one model of all voices, every voice read) "
                + "and %.2f s of a `Summer` ticked per sample with the model's `PhyUGen`(s) patched into it, "
                + "as an `AudioOutput` or the `OfflineRenderer` ticks them. In each round every model is measured by both "
                + "engines, Faust first in even rounds, Tactus first in odd ones. Strings: `FaustCost.string` (between two "
                + "fixed points, struck once, listened at mass 2n/3 + 1); the plate as in `FaustAgreementTest`, struck at "
                + "p2_2. `faust` is limited to 6 GB and 900 s per model; a model it cannot compile is reported as such.\n",
                seconds, seconds, seconds));
        s.append(Bench.KEPT_END).append('\n');
        return s.toString();
    }

    private static String cpuName() {
        try {
            for (String l : Files.readAllLines(Path.of("/proc/cpuinfo"))) {
                if (l.startsWith("model name")) {
                    return l.substring(l.indexOf(':') + 1).trim();
                }
            }
        } catch (IOException e) {
            // not Linux: the JVM's view only
        }
        return System.getProperty("os.arch");
    }

    private static String version(String tool, String flag) {
        try {
            Process p = new ProcessBuilder(tool, flag).redirectErrorStream(true).start();
            String first = new BufferedReader(new InputStreamReader(p.getInputStream(), StandardCharsets.UTF_8)).readLine();
            p.waitFor();
            return first == null ? tool + " (no version)" : first.trim();
        } catch (IOException e) {
            return tool + " missing";
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return tool;
        }
    }
}
