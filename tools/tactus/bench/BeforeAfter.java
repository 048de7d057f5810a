package tactus.bench;

import java.io.File;
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
 * <p>Usage: {@code java -cp <tools classes>:<dependency jars> tactus.bench.BeforeAfter
 * --before=<classes dir or jar> --after=<classes dir or jar> --deps=<jar:jar...> [--rounds=15] [N ...]}.
 * Not part of {@code gradle bench}: the "before" build has to be compiled by hand from an older commit.
 */
public final class BeforeAfter {
    private static final int RATE = 44100;
    private static final ThreadMXBean CPU = ManagementFactory.getThreadMXBean();

    private BeforeAfter() {
    }

    /** One build's string, ready to render: a bound {@code tick(float[])} handle. */
    private static final class Build {
        final MethodHandle tick;
        final float[] frame = new float[1];

        Build(ClassLoader loader, int n) throws ReflectiveOperationException {
            Class<?> pm = Class.forName("tactus.PhysicalModel", true, loader);
            Class<?> v3 = Class.forName("tactus.Vect3D", true, loader);
            Object model = pm.getConstructor(int.class).newInstance(RATE);
            java.lang.reflect.Constructor<?> vec = v3.getConstructor(double.class, double.class, double.class);
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
            Class<?> ugen = Class.forName("tactus.audio.PhyUGen", true, loader);
            Object u = ugen.getConstructor(pm).newInstance(model);
            ugen.getMethod("listenToMass", String.class, int.class, double.class, double.class)
                    .invoke(u, "m3", 1, 100.0, 0.0);
            ugen.getMethod("setSampleRate", float.class).invoke(u, (float) RATE);
            tick = MethodHandles.publicLookup().findVirtual(ugen, "tick", MethodType.methodType(void.class, float[].class))
                    .bindTo(u).asType(MethodType.methodType(void.class, float[].class));
        }

        void render(long samples) throws Throwable {
            for (long i = 0; i < samples; i++) {
                tick.invokeExact(frame);
            }
        }
    }

    public static void main(String[] args) throws Throwable {
        String before = null;
        String after = null;
        String deps = "";
        int rounds = 15;
        List<Integer> sizes = new ArrayList<>();
        for (String a : args) {
            if (a.startsWith("--before=")) {
                before = a.substring(9);
            } else if (a.startsWith("--after=")) {
                after = a.substring(8);
            } else if (a.startsWith("--deps=")) {
                deps = a.substring(7);
            } else if (a.startsWith("--rounds=")) {
                rounds = Integer.parseInt(a.substring(9));
            } else {
                sizes.add(Integer.parseInt(a));
            }
        }
        if (before == null || after == null) {
            throw new IllegalArgumentException("usage: --before=<classes> --after=<classes> --deps=<jars> [N ...]");
        }
        if (sizes.isEmpty()) {
            sizes.addAll(Arrays.asList(1000, 3000, 4000, 5000, 6000, 10000));
        }
        ClassLoader shared = new URLClassLoader(urls(deps), ClassLoader.getPlatformClassLoader());
        ClassLoader lb = new URLClassLoader(urls(before), shared);
        ClassLoader la = new URLClassLoader(urls(after), shared);
        System.out.println("JVM " + System.getProperty("java.vm.name") + " " + System.getProperty("java.version")
                + "; load average at start " + Bench.loadavg());
        System.out.println("| string masses (elements) | before ns/sample | after ns/sample | after/before, median (min-max) "
                + "| real-time factor before | after |");
        System.out.println("|---|---|---|---|---|---|");
        for (int n : sizes) {
            Build b = new Build(lb, n);
            Build a = new Build(la, n);
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
            System.out.printf(Locale.ROOT, "| %,d (%,d) | %,.0f | %,.0f | %.3f (%.3f-%.3f) | %.2fx | %.2fx |%n", n, 2 * n + 1,
                    mb, ma, ratio[rounds / 2], ratio[0], ratio[rounds - 1], 1e9 / RATE / mb, 1e9 / RATE / ma);
        }
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
