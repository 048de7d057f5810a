package tactus.bench;

import java.io.File;
import java.io.IOException;
import java.lang.invoke.MethodHandle;
import java.lang.invoke.MethodHandles;
import java.lang.invoke.MethodType;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.net.URL;
import java.net.URLClassLoader;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;

/**
 * Compares two builds of the library in one JVM: the audio benchmark's plucked string (N Mass2DPlane masses
 * between two Ground3D, N + 1 SpringDamper3D, K 0.2, Z 0.0001, l0 0.05 at spacing 0.1, at 44.1 kHz), rendered
 * sample by sample through {@code tactus.audio.PhyUGen.tick} with one listening point, as in
 * {@code test/tactus/audio/AudioBench}. Each build is loaded by its own class loader (the shared dependencies,
 * Minim and Processing core, by a common parent), so both run in the same process, on the same machine load,
 * with their own JIT-compiled code. Rounds alternate between the builds (the order swaps every round) and the
 * ratio after/before is taken per round, so that load drift on a shared machine cancels out. Times are this
 * thread's CPU time (time spent descheduled does not count).
 *
 * <p>Usage: {@code gradle beforeAfter -Pbefore=<commit>
 * [-Pscene=audio|audio1d|string-1000|mesh-100|marbles-200|line-N|lattice-N] [-Prounds=15] [-Psizes="1000 5000"]}, or {@code java -cp <tools classpath> tactus.bench.BeforeAfter
 * --before=<classes dir or jar> | --before-commit=<rev> [--after=<classes dir or jar>] [--deps=<jar:jar...>]
 * [--scene=...] [--rounds=15] [--forks=N] [N ...]}. {@code --forks=N} repeats the comparison in N fresh JVMs
 * (alternating which build is constructed first) and prints the median of their ratios: one JVM's ratio carries an
 * offset of its own (see {@link #forkAndSummarise}). {@code --before-commit} compiles {@code src/} of that commit
 * ({@code git archive}) into {@code build/beforeafter/}; {@code --after} and {@code --deps} default to the library's
 * classes and the jars of this JVM's class path. The other scenes ({@code --scene}) are those of
 * {@link tactus.bench.paper.PaperScenes} (and the moving contact groups of {@link GroupScenes}, {@code line-N} and
 * {@code lattice-N}), loaded once per build, stepped by {@code computeStep()}.
 */
public final class BeforeAfter {
    private static final int RATE = 44100;
    private static final ThreadMXBean CPU = ManagementFactory.getThreadMXBean();
    /** Build the "after" model first (forks alternate it, so that an effect of build order cancels out). */
    private static boolean AFTER_FIRST;

    private BeforeAfter() {
    }

    /** One build's string, ready to render: a bound {@code tick(float[])} handle. */
    private static class Build {
        final MethodHandle tick;
        final float[] frame = new float[1];

        /** For subclasses that render something else. */
        Build() {
            tick = null;
        }

        Build(ClassLoader loader, int n) throws ReflectiveOperationException {
            this(loader, n, false);
        }

        /**
         * @param oneD true for the 1-D string of {@code FaustCost} and the Faust side by side (n Mass1D between two
         *     Ground1D, n + 1 SpringDamper1D, K 0.2, Z 0.0005, struck once), listened to at mass 2n/3 + 1 along z
         */
        Build(ClassLoader loader, int n, boolean oneD) throws ReflectiveOperationException {
            Class<?> pm = Class.forName("tactus.PhysicalModel", true, loader);
            Class<?> v3 = Class.forName("tactus.Vect3D", true, loader);
            Object model = pm.getConstructor(int.class).newInstance(RATE);
            java.lang.reflect.Constructor<?> vec = v3.getConstructor(double.class, double.class, double.class);
            if (oneD) {
                pm.getMethod("addGround1D", String.class, v3).invoke(model, "g0", vec.newInstance(0.0, 0.0, 0.0));
                pm.getMethod("addGround1D", String.class, v3).invoke(model, "g1", vec.newInstance(n + 1.0, 0.0, 0.0));
                java.lang.reflect.Method mass = pm.getMethod("addMass1D", String.class, double.class, v3, v3);
                for (int i = 1; i <= n; i++) {
                    mass.invoke(model, "m" + i, 1.0, vec.newInstance((double) i, 0.0, 0.0), vec.newInstance(0.0, 0.0, 0.0));
                }
                java.lang.reflect.Method link = pm.getMethod("addSpringDamper1D", String.class, double.class,
                        double.class, double.class, String.class, String.class);
                for (int i = 0; i <= n; i++) {
                    link.invoke(model, "s" + i, 0.0, 0.2, 0.0005, i == 0 ? "g0" : "m" + i, i == n ? "g1" : "m" + (i + 1));
                }
                pm.getMethod("init").invoke(model);
                pm.getMethod("triggerForceImpulse", String.class, double.class, double.class, double.class)
                        .invoke(model, tactus.faust.FaustCost.struckMass(n), 0.0, 0.0, 1.0);
                tick = ugenTick(loader, pm, model, "m" + (2 * n / 3 + 1), 2);
                return;
            }
            pm.getMethod("addGround3D", String.class, v3).invoke(model, "g0", vec.newInstance(0.0, 0.0, 0.0));
            int apex = Math.max(1, n / 4);
            java.lang.reflect.Method mass = pm.getMethod("addMass2DPlane", String.class, double.class, v3, v3);
            for (int i = 1; i <= n; i++) {
                double y = i <= apex ? 0.001 * i / apex : 0.001 * (n + 1 - i) / (n + 1 - apex);
                mass.invoke(model, "m" + i, 1.0, vec.newInstance(i * 0.1, y, 0.0), vec.newInstance(0.0, 0.0, 0.0));
            }
            pm.getMethod("addGround3D", String.class, v3).invoke(model, "g" + (n + 1),
                    vec.newInstance((n + 1) * 0.1, 0.0, 0.0));
            java.lang.reflect.Method link = pm.getMethod("addSpringDamper3D", String.class, double.class,
                    double.class, double.class, String.class, String.class);
            for (int i = 0; i <= n; i++) {
                String a = i == 0 ? "g0" : "m" + i;
                String b = i == n ? "g" + (n + 1) : "m" + (i + 1);
                link.invoke(model, "s" + i, 0.05, 0.2, 0.0001, a, b);
            }
            pm.getMethod("init").invoke(model);
            tick = ugenTick(loader, pm, model, "m3", 1);
        }

        /** A PhyUGen of this build playing the model, listening to a mass along an axis: its bound tick. */
        private static MethodHandle ugenTick(ClassLoader loader, Class<?> pm, Object model, String mass, int axis)
                throws ReflectiveOperationException {
            Class<?> ugen = Class.forName("tactus.audio.PhyUGen", true, loader);
            Object u = ugen.getConstructor(pm).newInstance(model);
            ugen.getMethod("listenToMass", String.class, int.class, double.class, double.class)
                    .invoke(u, mass, axis, 100.0, 0.0);
            ugen.getMethod("setSampleRate", float.class).invoke(u, (float) RATE);
            return MethodHandles.publicLookup().findVirtual(ugen, "tick", MethodType.methodType(void.class, float[].class))
                    .bindTo(u).asType(MethodType.methodType(void.class, float[].class));
        }

        void render(long samples) throws Throwable {
            for (long i = 0; i < samples; i++) {
                tick.invokeExact(frame);
            }
        }
    }

    /**
     * One build's side-by-side scene ({@link tactus.bench.paper.PaperScenes}, the tools' class loaded again in the
     * build's class loader, so it links against that build), stepped by one {@code computeStep()} per step.
     */
    private static final class SceneBuild extends Build {
        final MethodHandle step;

        SceneBuild(ClassLoader loader, String sceneName) throws ReflectiveOperationException {
            super();
            String scene = sceneName;
            Class<?> ps = Class.forName("tactus.bench.paper.PaperScenes", true, loader);
            Object model;
            if (GroupScenes.isGroupScene(scene)) {
                scene = "group";
            }
            switch (scene) {
                case "group":
                    model = Class.forName("tactus.bench.GroupScenes", true, loader).getMethod("create", String.class)
                            .invoke(null, sceneName);
                    break;
                case "marbles-200":
                    model = ps.getMethod("marbles", int.class, java.util.function.Consumer.class).invoke(null, 200, null);
                    break;
                case "mesh-100":
                    model = ps.getMethod("mesh", int.class).invoke(null, 100);
                    break;
                case "string-1000":
                    model = ps.getMethod("string", int.class, int.class).invoke(null, 1000, RATE);
                    break;
                default:
                    throw new IllegalArgumentException("unknown scene " + scene
                            + " (audio, string-1000, mesh-100, marbles-200, line-N, lattice-N)");
            }
            step = MethodHandles.publicLookup().findVirtual(model.getClass(), "computeStep",
                    MethodType.methodType(void.class)).bindTo(model).asType(MethodType.methodType(void.class));
        }

        @Override
        void render(long steps) throws Throwable {
            for (long i = 0; i < steps; i++) {
                step.invokeExact();
            }
        }
    }

    /**
     * Extracts {@code src/} of a commit of this repository ({@code git archive}) and compiles it.
     *
     * @param rev a commit (any git revision)
     * @param deps the jars the library compiles against
     * @return the class path of that build (its classes and its resources)
     */
    static String compileCommit(String rev, String deps) throws IOException, InterruptedException {
        File dir = new File("build/beforeafter/" + rev.replaceAll("[^A-Za-z0-9._-]", "_"));
        File src = new File(dir, "src");
        File classes = new File(dir, "classes");
        deleteTree(dir);
        src.mkdirs();
        classes.mkdirs();
        Process git = new ProcessBuilder("sh", "-c", "git archive --format=tar \"$0\" src | tar -x -C \"$1\"", rev,
                dir.getAbsolutePath()).inheritIO().start();
        if (git.waitFor() != 0) {
            throw new IllegalStateException("git archive " + rev + " src failed (run from the repository's root)");
        }
        List<String> files = new ArrayList<>();
        try (java.util.stream.Stream<java.nio.file.Path> walk = java.nio.file.Files.walk(src.toPath())) {
            walk.filter(f -> f.toString().endsWith(".java")).forEach(f -> files.add(f.toString()));
        }
        List<String> opts = new ArrayList<>(Arrays.asList("-nowarn", "-proc:none", "-encoding", "UTF-8", "--release",
                "17", "-cp", deps, "-d", classes.getAbsolutePath()));
        opts.addAll(files);
        javax.tools.JavaCompiler javac = javax.tools.ToolProvider.getSystemJavaCompiler();
        if (javac == null || javac.run(null, null, null, opts.toArray(new String[0])) != 0) {
            throw new IllegalStateException("could not compile src/ of " + rev + " (a JDK is needed)");
        }
        System.out.println("before: " + rev + " compiled into " + classes);
        return classes.getAbsolutePath() + File.pathSeparator + src.getAbsolutePath();
    }

    private static void deleteTree(File f) {
        File[] children = f.listFiles();
        if (children != null) {
            for (File c : children) {
                deleteTree(c);
            }
        }
        f.delete();
    }

    /** @return the entries of this JVM's class path that are jars (the dependencies) or that hold a given class */
    static String classPathEntries(boolean jars, String resource) {
        StringBuilder sb = new StringBuilder();
        for (String e : System.getProperty("java.class.path").split(File.pathSeparator)) {
            boolean jar = e.endsWith(".jar");
            boolean holds = !jar && resource != null && new File(e, resource).isFile();
            if (jars ? jar : holds) {
                sb.append(sb.length() == 0 ? "" : File.pathSeparator).append(e);
            }
        }
        return sb.toString();
    }

    public static void main(String[] args) throws Throwable {
        String before = null;
        String beforeCommit = null;
        String after = classPathEntries(false, "tactus/PhysicalModel.class");
        String deps = classPathEntries(true, null);
        String scene = "audio";
        int rounds = 15;
        int forks = 1;
        boolean afterFirst = false;
        List<Integer> sizes = new ArrayList<>();
        for (String a : args) {
            if (a.startsWith("--before=")) {
                before = a.substring(9);
            } else if (a.startsWith("--before-commit=")) {
                beforeCommit = a.substring(16);
            } else if (a.startsWith("--scene=")) {
                scene = a.substring(8);
            } else if (a.startsWith("--after=")) {
                after = a.substring(8);
            } else if (a.startsWith("--deps=")) {
                deps = a.substring(7);
            } else if (a.startsWith("--forks=")) {
                forks = Integer.parseInt(a.substring(8));
            } else if (a.equals("--after-first")) {
                afterFirst = true;
            } else if (a.startsWith("--rounds=")) {
                rounds = Integer.parseInt(a.substring(9));
            } else {
                sizes.add(Integer.parseInt(a));
            }
        }
        if (beforeCommit != null) {
            before = compileCommit(beforeCommit, deps);
        }
        if (forks > 1 && before != null) {
            forkAndSummarise(forks, before, after, deps, scene, rounds, sizes);
            return;
        }
        AFTER_FIRST = afterFirst;
        if (before == null || after.isEmpty()) {
            throw new IllegalArgumentException("usage: --before=<classes> | --before-commit=<rev>, [--after=<classes>] "
                    + "[--deps=<jars>] [--scene=audio|string-1000|mesh-100|marbles-200|line-N|lattice-N] [--rounds=15] "
                    + "[N ...]");
        }
        if (sizes.isEmpty()) {
            sizes.addAll(scene.equals("audio1d") ? Arrays.asList(30, 100, 300, 1000)
                    : Arrays.asList(1000, 3000, 4000, 5000, 6000, 10000));
        }
        ClassLoader shared = new URLClassLoader(urls(deps), ClassLoader.getPlatformClassLoader());
        if (!scene.equals("audio") && !scene.equals("audio1d")) {
            // The scene's class is loaded again by each build's loader, beside that build, so that it links to it.
            String tools = classPathEntries(false, "tactus/bench/paper/PaperScenes.class");
            ClassLoader lb = new URLClassLoader(urls(before + File.pathSeparator + tools), shared);
            ClassLoader la = new URLClassLoader(urls(after + File.pathSeparator + tools), shared);
            compareScene(scene, lb, la, rounds);
            return;
        }
        ClassLoader lb = new URLClassLoader(urls(before), shared);
        ClassLoader la = new URLClassLoader(urls(after), shared);
        System.out.println("JVM " + System.getProperty("java.vm.name") + " " + System.getProperty("java.version")
                + "; load average at start " + Bench.loadavg());
        System.out.println("| string masses (elements) | before ns/sample | after ns/sample | after/before, median (min-max) "
                + "| real-time factor before | after |");
        System.out.println("|---|---|---|---|---|---|");
        for (int n : sizes) {
            boolean oneD = scene.equals("audio1d");
            Build a0 = AFTER_FIRST ? new Build(la, n, oneD) : null;
            Build b = new Build(lb, n, oneD);
            Build a = a0 != null ? a0 : new Build(la, n, oneD);
            long samples = Math.max(2000, 40_000_000L / (n + 50));
            for (int w = 0; w < 4; w++) {
                b.render(samples);
                a.render(samples);
            }
            double[] tb = new double[rounds];
            double[] ta = new double[rounds];
            double[] ratio = new double[rounds];
            for (int r = 0; r < rounds; r++) {
                Build first = r % 2 == 0 ? b : a;
                Build second = first == b ? a : b;
                long t0 = CPU.getCurrentThreadCpuTime();
                first.render(samples);
                long t1 = CPU.getCurrentThreadCpuTime();
                second.render(samples);
                long t2 = CPU.getCurrentThreadCpuTime();
                double f = (t1 - t0) / (double) samples;
                double s = (t2 - t1) / (double) samples;
                tb[r] = first == b ? f : s;
                ta[r] = first == b ? s : f;
                ratio[r] = ta[r] / tb[r];
            }
            Arrays.sort(tb);
            Arrays.sort(ta);
            Arrays.sort(ratio);
            double mb = tb[rounds / 2];
            double ma = ta[rounds / 2];
            System.out.printf(Locale.ROOT, "| %,d (%,d)%s | %,.0f | %,.0f | %.3f (%.3f-%.3f) | %.2fx | %.2fx |%n", n, 2 * n + 1,
                    oneD ? ", 1-D" : "",
                    mb, ma, ratio[rounds / 2], ratio[0], ratio[rounds - 1], 1e9 / RATE / mb, 1e9 / RATE / ma);
        }
        System.out.println("load average at end " + Bench.loadavg());
    }

    /**
     * Runs the comparison in {@code forks} fresh JVMs (same flags), alternating which build is constructed first,
     * and prints each JVM's ratios and their median per row. One JVM's paired ratio carries an offset of its own
     * (JIT decisions, memory layout; an A/A run, the same code on both sides, gave 0.88 to 1.05 with tight ranges
     * in single JVMs), which the median over JVMs averages out.
     */
    private static void forkAndSummarise(int forks, String before, String after, String deps, String scene, int rounds,
            List<Integer> sizes) throws IOException, InterruptedException {
        java.util.Map<String, List<Double>> ratios = new java.util.LinkedHashMap<>();
        for (int f = 0; f < forks; f++) {
            List<String> cmd = new ArrayList<>(Arrays.asList(
                    java.nio.file.Paths.get(System.getProperty("java.home"), "bin", "java").toString()));
            cmd.addAll(ManagementFactory.getRuntimeMXBean().getInputArguments());
            cmd.addAll(Arrays.asList("-cp", System.getProperty("java.class.path"), BeforeAfter.class.getName(),
                    "--before=" + before, "--after=" + after, "--deps=" + deps, "--scene=" + scene,
                    "--rounds=" + rounds));
            if (f % 2 == 1) {
                cmd.add("--after-first");
            }
            for (int n : sizes) {
                cmd.add(Integer.toString(n));
            }
            System.out.println("== JVM " + (f + 1) + "/" + forks + (f % 2 == 1 ? " (after built first)" : ""));
            Process p = new ProcessBuilder(cmd).redirectErrorStream(true).start();
            try (java.io.BufferedReader in = new java.io.BufferedReader(new java.io.InputStreamReader(p.getInputStream(),
                    java.nio.charset.StandardCharsets.UTF_8))) {
                for (String line; (line = in.readLine()) != null;) {
                    System.out.println("  " + line);
                    String[] cells = line.split("\\|");
                    if (line.startsWith("| ") && cells.length > 4 && cells[4].trim().matches("[0-9.]+ \\(.*")) {
                        ratios.computeIfAbsent(cells[1].trim(), k -> new ArrayList<>())
                                .add(Double.parseDouble(cells[4].trim().split(" ")[0]));
                    }
                }
            }
            if (p.waitFor() != 0) {
                throw new IllegalStateException("JVM " + (f + 1) + " failed (exit " + p.exitValue() + ")");
            }
        }
        System.out.println("| " + (scene.equals("audio") ? "string masses (elements)" : "scene")
                + " | after/before, median over " + forks + " JVMs (min-max of the JVMs' medians) |");
        System.out.println("|---|---|");
        for (java.util.Map.Entry<String, List<Double>> e : ratios.entrySet()) {
            double[] v = e.getValue().stream().mapToDouble(Double::doubleValue).sorted().toArray();
            double med = v.length % 2 == 1 ? v[v.length / 2] : 0.5 * (v[v.length / 2 - 1] + v[v.length / 2]);
            System.out.printf(Locale.ROOT, "| %s | %.3f (%.3f-%.3f) |%n", e.getKey(), med, v[0], v[v.length - 1]);
        }
    }

    /** A side-by-side scene on both builds: µs per step of CPU time, rounds alternating, ratio per round. */
    private static void compareScene(String scene, ClassLoader lb, ClassLoader la, int rounds) throws Throwable {
        System.out.println("JVM " + System.getProperty("java.vm.name") + " " + System.getProperty("java.version")
                + "; scene " + scene + " (PaperScenes, one computeStep() per step); load average at start "
                + Bench.loadavg());
        Build a0 = AFTER_FIRST ? new SceneBuild(la, scene) : null;
        Build b = new SceneBuild(lb, scene);
        Build a = a0 != null ? a0 : new SceneBuild(la, scene);
        // warm both builds up for a second before timing a step: a small scene's first 200 steps run interpreted,
        // and a round sized on them would last milliseconds
        long warm = System.nanoTime();
        while (System.nanoTime() - warm < 1_000_000_000L) {
            b.render(200);
            a.render(200);
        }
        long t = System.nanoTime();
        b.render(200);
        long steps = Math.max(200, (long) (0.3e9 / Math.max(1, (System.nanoTime() - t) / 200)));
        for (int w = 0; w < 4; w++) {
            b.render(steps);
            a.render(steps);
        }
        double[] tb = new double[rounds];
        double[] ta = new double[rounds];
        double[] ratio = new double[rounds];
        for (int r = 0; r < rounds; r++) {
            Build first = r % 2 == 0 ? b : a;
            long t0 = CPU.getCurrentThreadCpuTime();
            first.render(steps);
            long t1 = CPU.getCurrentThreadCpuTime();
            (first == b ? a : b).render(steps);
            long t2 = CPU.getCurrentThreadCpuTime();
            tb[r] = (first == b ? t1 - t0 : t2 - t1) / 1e3 / steps;
            ta[r] = (first == b ? t2 - t1 : t1 - t0) / 1e3 / steps;
            ratio[r] = ta[r] / tb[r];
        }
        Arrays.sort(tb);
        Arrays.sort(ta);
        Arrays.sort(ratio);
        System.out.println("| scene | before µs/step | after µs/step | after/before, median (min-max) |");
        System.out.println("|---|---|---|---|");
        System.out.printf(Locale.ROOT, "| %s | %.2f | %.2f | %.3f (%.3f-%.3f) |%n", scene, tb[rounds / 2],
                ta[rounds / 2], ratio[rounds / 2], ratio[0], ratio[rounds - 1]);
        System.out.println("load average at end " + Bench.loadavg());
    }

    private static URL[] urls(String path) throws java.net.MalformedURLException {
        List<URL> out = new ArrayList<>();
        for (String p : path.split(File.pathSeparator)) {
            if (!p.isEmpty()) {
                out.add(new File(p).toURI().toURL());
            }
        }
        return out.toArray(new URL[0]);
    }
}
