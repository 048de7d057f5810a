package tactus.bench;

import java.io.File;
import java.lang.invoke.MethodHandle;
import java.lang.invoke.MethodHandles;
import java.lang.invoke.MethodType;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.lang.reflect.Constructor;
import java.lang.reflect.Method;
import java.net.URL;
import java.net.URLClassLoader;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.locks.LockSupport;

/**
 * What the render snapshot costs the thread that steps a model (issue #18): two scenes of about 20,000 elements
 * stepped one step per call at 1 kHz of simulated time, the marbles (200 Mass3D, one Contact3D per pair, a Bubble3D
 * and a plane contact each: 20,500 elements, at rest) and the mesh (100 x 100 nodes, grounded border, gravity,
 * SpringDamper3D to the right and down neighbours: 9,604 masses and 19,800 links).
 *
 * <p>Modes, each run as interleaved rounds (the order swaps every round) so that the load of a shared machine
 * cancels out in the ratios; times are the measuring thread's CPU time:
 * <ul>
 *   <li>{@code frames}: one thread steps with {@code computeStep()} and, in the "reader" variant, calls
 *       {@code getSnapshot()} once per 1/60 s of simulated time (a 60 fps reader of a 1 kHz model, without the
 *       noise of a second thread), in locked mode and in realtime mode (the stepping thread is the owner); with
 *       {@code --before}/{@code --after} two builds of the library run in one JVM, each by its own class loader;</li>
 *   <li>{@code paced}: the stepping thread paced at 1 kHz of wall-clock time, and a second thread that reads
 *       masses and interactions at 60 Hz of wall-clock time (summing every position and elongation); CPU per step
 *       of the stepping thread and per read of the reader;</li>
 *   <li>{@code publish}: the cost of one publication, masses only and with interactions, as the difference per
 *       step between {@code computeStep(); getSnapshot();} and {@code computeStep();} (locked mode, where the
 *       reading thread publishes).</li>
 * </ul>
 * Usage: {@code java -cp <tools classes>:<main classes>:<Processing core jar> tactus.bench.SnapshotCost [--before=<classes dir>
 * --after=<classes dir>] [--rounds=7] [--steps=3000] [--paced-seconds=4] [--paced-no-consume]
 * [--only=frames,paced,publish] [--scenes=marbles,mesh]}.
 */
public final class SnapshotCost {
    private static final ThreadMXBean CPU = ManagementFactory.getThreadMXBean();
    private static final int RATE = 1000;
    private static final int FPS = 60;
    /** Whether the paced reader thread reads every position and elongation of its copies (or only takes them). */
    private static boolean consume = true;

    private SnapshotCost() {
    }

    /** One model of one build, driven through method handles. */
    static final class Model {
        final Object pm;
        final MethodHandle step;
        final MethodHandle snapshot;
        final MethodHandle realtime;
        final MethodHandle endRealtime;
        final MethodHandle requestLinks;
        final MethodHandle masses;
        final MethodHandle links;
        final MethodHandle x;
        final MethodHandle elongation;
        final MethodHandle setLength;

        Model(Object pm) throws ReflectiveOperationException {
            this.pm = pm;
            MethodHandles.Lookup l = MethodHandles.publicLookup();
            Class<?> c = pm.getClass();
            Class<?> s = Class.forName("tactus.ModelSnapshot", false, c.getClassLoader());
            step = l.findVirtual(c, "computeStep", MethodType.methodType(void.class)).bindTo(pm);
            setLength = l.findVirtual(c, "setLinkDRestAt", MethodType.methodType(void.class, int.class, double.class))
                    .bindTo(pm);
            snapshot = l.findVirtual(c, "getSnapshot", MethodType.methodType(s)).bindTo(pm)
                    .asType(MethodType.methodType(Object.class));
            realtime = l.findVirtual(c, "beginRealtimeStepping", MethodType.methodType(void.class)).bindTo(pm);
            endRealtime = l.findVirtual(c, "endRealtimeStepping", MethodType.methodType(void.class)).bindTo(pm);
            MethodHandle rl;
            try {
                rl = l.findVirtual(s, "requestLinks", MethodType.methodType(void.class, boolean.class))
                        .asType(MethodType.methodType(void.class, Object.class, boolean.class));
            } catch (NoSuchMethodException e) {
                rl = null; // a build from before on-demand snapshots: interactions always copied
            }
            requestLinks = rl;
            masses = l.findVirtual(s, "getNumberOfMats", MethodType.methodType(int.class))
                    .asType(MethodType.methodType(int.class, Object.class));
            links = l.findVirtual(s, "getNumberOfLinks", MethodType.methodType(int.class))
                    .asType(MethodType.methodType(int.class, Object.class));
            x = l.findVirtual(s, "x", MethodType.methodType(double.class, int.class))
                    .asType(MethodType.methodType(double.class, Object.class, int.class));
            elongation = l.findVirtual(s, "getLinkElongation", MethodType.methodType(double.class, int.class))
                    .asType(MethodType.methodType(double.class, Object.class, int.class));
        }

        void step() throws Throwable {
            step.invokeExact();
        }

        Object snapshot() throws Throwable {
            return (Object) snapshot.invokeExact();
        }

        /** Reads what a renderer would: every position and every elongation. */
        double consume(Object s) throws Throwable {
            double sum = 0;
            int nm = (int) masses.invokeExact(s);
            for (int i = 0; i < nm; i++) {
                sum += (double) x.invokeExact(s, i);
            }
            int nl = (int) links.invokeExact(s);
            for (int i = 0; i < nl; i++) {
                sum += (double) elongation.invokeExact(s, i);
            }
            return sum;
        }

        void requestLinks(boolean on) throws Throwable {
            if (requestLinks != null) {
                requestLinks.invokeExact(snapshot(), on);
            }
        }
    }

    /** Builds the scenes through reflection, so that any build of the library can be measured. */
    static final class Builder {
        final Class<?> pmClass;
        final Constructor<?> vec;
        final Object algo;

        Builder(ClassLoader loader) throws ReflectiveOperationException {
            pmClass = Class.forName("tactus.PhysicalModel", true, loader);
            Class<?> v3 = Class.forName("tactus.Vect3D", true, loader);
            vec = v3.getConstructor(double.class, double.class, double.class);
            Class<?> units = Class.forName("tactus.paramSystem", true, loader);
            algo = units.getField("ALGO_UNITS").get(null);
        }

        Object v(double x, double y, double z) throws ReflectiveOperationException {
            return vec.newInstance(x, y, z);
        }

        Method m(String name, Class<?>... types) throws NoSuchMethodException {
            return pmClass.getMethod(name, types);
        }

        Object newModel() throws ReflectiveOperationException {
            return pmClass.getConstructor(int.class, int.class, algo.getClass()).newInstance(RATE, FPS, algo);
        }

        /** 200 marbles at rest in a bubble, one Contact3D per pair (EnclosedMarbles without the avatar). */
        Object marbles(int n) throws ReflectiveOperationException {
            Object pm = newModel();
            Class<?> v3 = vec.getDeclaringClass();
            m("setGravity", double.class).invoke(pm, 5e-5);
            m("setFriction", double.class).invoke(pm, 1e-3);
            double[][] pos = Scenes.marblePositions(n);
            Method ground = m("addGround3D", String.class, v3);
            Method mass = m("addMass3D", String.class, double.class, v3, v3);
            Method bubble = m("addBubble3D", String.class, double.class, double.class, double.class, String.class,
                    String.class);
            Method plane = m("addPlaneContact", String.class, double.class, double.class, double.class, int.class,
                    double.class, String.class);
            Method contact = m("addContact3D", String.class, double.class, double.class, double.class, String.class,
                    String.class);
            ground.invoke(pm, "centre", v(0, 0, 1));
            Random rnd = new Random(7);
            for (int i = 0; i < n; i++) {
                mass.invoke(pm, "b" + i, 7 + 3 * rnd.nextDouble(), v(pos[i][0], pos[i][1], pos[i][2]), v(0, 0, 0));
                bubble.invoke(pm, "bb" + i, 3.0, 0.1, 0.1, "b" + i, "centre");
                plane.invoke(pm, "pl" + i, 0.1, 0.01, 0.01, 2, 0.0, "b" + i);
            }
            for (int i = 0; i < n; i++) {
                for (int j = i + 1; j < n; j++) {
                    contact.invoke(pm, "c" + i + "_" + j, Scenes.MARBLE_THR, Scenes.MARBLE_K, Scenes.MARBLE_Z,
                            "b" + i, "b" + j);
                }
            }
            m("init").invoke(pm);
            return pm;
        }

        /** A w x w mesh: grounded border, Mass3D inside, SpringDamper3D right and down, gravity. */
        Object mesh(int w) throws ReflectiveOperationException {
            Object pm = newModel();
            Class<?> v3 = vec.getDeclaringClass();
            m("setGravity", double.class).invoke(pm, 1e-6);
            Method ground = m("addGround3D", String.class, v3);
            Method mass = m("addMass3D", String.class, double.class, v3, v3);
            Method spring = m("addSpringDamper3D", String.class, double.class, double.class, double.class,
                    String.class, String.class);
            for (int j = 0; j < w; j++) {
                for (int i = 0; i < w; i++) {
                    boolean border = i == 0 || j == 0 || i == w - 1 || j == w - 1;
                    if (border) {
                        ground.invoke(pm, "n" + (j * w + i), v(0.1 * i, 0.1 * j, 0));
                    } else {
                        mass.invoke(pm, "n" + (j * w + i), 1.0, v(0.1 * i, 0.1 * j, 0), v(0, 0, 0));
                    }
                }
            }
            for (int j = 0; j < w; j++) {
                for (int i = 0; i < w; i++) {
                    String a = "n" + (j * w + i);
                    if (i + 1 < w && !(edge(i, j, w) && edge(i + 1, j, w))) {
                        spring.invoke(pm, "r" + (j * w + i), 0.09, 0.2, 0.001, a, "n" + (j * w + i + 1));
                    }
                    if (j + 1 < w && !(edge(i, j, w) && edge(i, j + 1, w))) {
                        spring.invoke(pm, "d" + (j * w + i), 0.09, 0.2, 0.001, a, "n" + ((j + 1) * w + i));
                    }
                }
            }
            m("init").invoke(pm);
            return pm;
        }

        private static boolean edge(int i, int j, int w) {
            return i == 0 || j == 0 || i == w - 1 || j == w - 1;
        }

        Object scene(String name) throws ReflectiveOperationException {
            return name.equals("marbles") ? marbles(200) : mesh(100);
        }
    }

    // ================================================================ measurements

    /** Steps one at a time; with {@code read}, calls getSnapshot once per 1/60 s of simulated time. ns per step. */
    static double frames(Model m, int steps, boolean read, long[] stepBase) throws Throwable {
        long t0 = CPU.getCurrentThreadCpuTime();
        long k = stepBase[0];
        for (int i = 0; i < steps; i++) {
            m.step();
            k++;
            if (read && (k * FPS) / RATE != ((k - 1) * FPS) / RATE) {
                m.snapshot();
            }
        }
        stepBase[0] = k;
        return (CPU.getCurrentThreadCpuTime() - t0) / (double) steps;
    }

    /**
     * Steps and calls getSnapshot after every step (locked mode: this thread publishes); with {@code edit}, sets the
     * length parameter of the first interaction before every step (so that every publication copies the lengths).
     * ns per step.
     */
    static double everyStep(Model m, int steps, boolean read, boolean edit) throws Throwable {
        long t0 = CPU.getCurrentThreadCpuTime();
        for (int i = 0; i < steps; i++) {
            if (edit) {
                m.setLength.invokeExact(0, (i & 1) == 0 ? 0.2 : 0.2000001);
            }
            m.step();
            if (read) {
                m.snapshot();
            }
        }
        return (CPU.getCurrentThreadCpuTime() - t0) / (double) steps;
    }

    static double median(double[] v) {
        double[] c = v.clone();
        Arrays.sort(c);
        int n = c.length;
        return n % 2 == 1 ? c[n / 2] : (c[n / 2 - 1] + c[n / 2]) / 2;
    }

    static double min(double[] v) {
        return Arrays.stream(v).min().orElse(Double.NaN);
    }

    static double max(double[] v) {
        return Arrays.stream(v).max().orElse(Double.NaN);
    }

    /**
     * The "frames" mode for one scene over one or two builds: per build and stepping mode, ns per step without and
     * with a reader, and the ratio per round.
     */
    static void framesMode(String scene, List<String> names, List<Builder> builders, int rounds, int steps)
            throws Throwable {
        for (boolean realtime : new boolean[] {false, true}) {
            int nb = builders.size();
            Model[] ms = new Model[nb];
            long[][] base = new long[nb][1];
            for (int b = 0; b < nb; b++) {
                ms[b] = new Model(builders.get(b).scene(scene));
                if (realtime) {
                    ms[b].realtime.invokeExact();
                }
                frames(ms[b], steps, true, base[b]); // warm-up, with and without reads
                frames(ms[b], steps, false, base[b]);
            }
            double[][] none = new double[nb][rounds];
            double[][] read = new double[nb][rounds];
            for (int r = 0; r < rounds; r++) {
                for (int bi = 0; bi < nb; bi++) {
                    int b = (r % 2 == 0) ? bi : nb - 1 - bi;
                    if ((r / 2) % 2 == 0) {
                        none[b][r] = frames(ms[b], steps, false, base[b]);
                        read[b][r] = frames(ms[b], steps, true, base[b]);
                    } else {
                        read[b][r] = frames(ms[b], steps, true, base[b]);
                        none[b][r] = frames(ms[b], steps, false, base[b]);
                    }
                }
            }
            for (int b = 0; b < nb; b++) {
                double[] ratio = new double[rounds];
                for (int r = 0; r < rounds; r++) {
                    ratio[r] = read[b][r] / none[b][r];
                }
                System.out.printf(Locale.ROOT, "frames %-7s %-8s %-6s no reader %8.1f us/step, 60 fps reader %8.1f"
                        + " us/step, reader/none %.3f (%.3f-%.3f)%n", scene, realtime ? "realtime" : "locked",
                        names.get(b), median(none[b]) / 1e3, median(read[b]) / 1e3, median(ratio), min(ratio),
                        max(ratio));
            }
            if (nb == 2) {
                for (int v = 0; v < 2; v++) {
                    double[][] x = v == 0 ? none : read;
                    double[] ratio = new double[rounds];
                    for (int r = 0; r < rounds; r++) {
                        ratio[r] = x[1][r] / x[0][r];
                    }
                    System.out.printf(Locale.ROOT, "frames %-7s %-8s %s: after/before %.3f (%.3f-%.3f)%n", scene,
                            realtime ? "realtime" : "locked", v == 0 ? "no reader   " : "60 fps reader",
                            median(ratio), min(ratio), max(ratio));
                }
            }
            for (int b = 0; b < nb; b++) {
                if (realtime) {
                    ms[b].endRealtime.invokeExact();
                }
            }
        }
    }

    /** The "publish" mode: the cost of one publication, masses only and with interactions (current build). */
    static void publishMode(String scene, Builder builder, int rounds, int steps) throws Throwable {
        Object pm = builder.scene(scene);
        // no stability analysis after each length edit of the third variant (it would dwarf the publication)
        Class<?> policy = Class.forName("tactus.StabilityPolicy", true, pm.getClass().getClassLoader());
        pm.getClass().getMethod("setStabilityPolicy", policy).invoke(pm, policy.getField("OFF").get(null));
        Model m = new Model(pm);
        Object s = m.snapshot();
        int nm = (int) m.masses.invokeExact(s);
        int nl = (int) m.links.invokeExact(s);
        for (int variant = 0; variant < 3; variant++) {
            boolean links = variant > 0;
            boolean edit = variant == 2;
            m.requestLinks(links);
            everyStep(m, steps / 4, true, edit);
            everyStep(m, steps / 4, false, edit);
            double[] diff = new double[rounds];
            double[] bare = new double[rounds];
            for (int r = 0; r < rounds; r++) {
                double a;
                double b;
                if (r % 2 == 0) {
                    a = everyStep(m, steps, false, edit);
                    b = everyStep(m, steps, true, edit);
                } else {
                    b = everyStep(m, steps, true, edit);
                    a = everyStep(m, steps, false, edit);
                }
                bare[r] = a;
                diff[r] = b - a;
            }
            double d = median(diff);
            System.out.printf(Locale.ROOT, "publish %-7s %s: %.1f us per publication (step alone %.1f us); %d masses"
                    + "%s%n", scene, variant == 0 ? "masses only                   "
                    : variant == 1 ? "masses + links                "
                    : "masses + links, lengths copied", d / 1e3, median(bare) / 1e3, nm,
                    links ? ", " + nl + " links" : "");
        }
        m.requestLinks(true);
    }

    /**
     * The "paced" mode: a stepping thread at 1 kHz of wall-clock time (this thread), alone or with a reader thread
     * at 60 Hz that reads every position and elongation. Reports CPU per step of the stepping thread and CPU per
     * read of the reader.
     */
    static void pacedMode(String scene, Builder builder, boolean realtime, int rounds, double seconds)
            throws Throwable {
        Model m = new Model(builder.scene(scene));
        if (realtime) {
            m.realtime.invokeExact();
        }
        paced(m, 0.5, false); // warm-up
        paced(m, 0.5, true);
        double[] none = new double[rounds];
        double[] read = new double[rounds];
        double[] readerCpu = new double[rounds];
        for (int r = 0; r < rounds; r++) {
            if (r % 2 == 0) {
                none[r] = paced(m, seconds, false)[0];
                double[] x = paced(m, seconds, true);
                read[r] = x[0];
                readerCpu[r] = x[1];
            } else {
                double[] x = paced(m, seconds, true);
                read[r] = x[0];
                readerCpu[r] = x[1];
                none[r] = paced(m, seconds, false)[0];
            }
        }
        double[] ratio = new double[rounds];
        for (int r = 0; r < rounds; r++) {
            ratio[r] = read[r] / none[r];
        }
        System.out.printf(Locale.ROOT, "paced  %-7s %-8s stepping thread: no reader %.1f us/step, with a 60 Hz reader"
                + " thread %.1f us/step, ratio %.3f (%.3f-%.3f); reader thread %.0f us per read%n", scene,
                realtime ? "realtime" : "locked", median(none) / 1e3, median(read) / 1e3, median(ratio), min(ratio),
                max(ratio), median(readerCpu) / 1e3);
        if (realtime) {
            m.endRealtime.invokeExact();
        }
    }

    /** @return {ns of CPU per step of this thread, ns of CPU per read of the reader thread (0 without)} */
    static double[] paced(Model m, double seconds, boolean withReader) throws Throwable {
        AtomicBoolean stop = new AtomicBoolean();
        double[] reader = new double[2];
        Thread t = null;
        if (withReader) {
            t = new Thread(() -> {
                long cpu0 = CPU.getCurrentThreadCpuTime();
                long reads = 0;
                double sink = 0;
                long next = System.nanoTime();
                try {
                    while (!stop.get()) {
                        Object snap = m.snapshot();
                        if (consume) {
                            sink += m.consume(snap);
                        }
                        reads++;
                        next += 1_000_000_000L / FPS;
                        long wait = next - System.nanoTime();
                        if (wait > 0) {
                            LockSupport.parkNanos(wait);
                        }
                    }
                } catch (Throwable e) {
                    throw new IllegalStateException(e);
                }
                reader[0] = reads == 0 ? 0 : (CPU.getCurrentThreadCpuTime() - cpu0) / (double) reads;
                reader[1] = sink;
            }, "reader");
            t.start();
        }
        int steps = (int) (seconds * RATE);
        long cpu0 = CPU.getCurrentThreadCpuTime();
        long next = System.nanoTime();
        for (int i = 0; i < steps; i++) {
            m.step();
            next += 1_000_000_000L / RATE;
            long wait = next - System.nanoTime();
            if (wait > 0) {
                LockSupport.parkNanos(wait);
            }
        }
        double perStep = (CPU.getCurrentThreadCpuTime() - cpu0) / (double) steps;
        stop.set(true);
        if (t != null) {
            t.join();
        }
        return new double[] {perStep, reader[0]};
    }

    // ================================================================ main

    public static void main(String[] args) throws Throwable {
        String before = null;
        String after = null;
        int rounds = 7;
        int steps = 3000;
        double pacedSeconds = 4;
        String only = "frames,paced,publish";
        String scenes = "marbles,mesh";
        for (String a : args) {
            if (a.startsWith("--before=")) {
                before = a.substring(9);
            } else if (a.startsWith("--after=")) {
                after = a.substring(8);
            } else if (a.startsWith("--rounds=")) {
                rounds = Integer.parseInt(a.substring(9));
            } else if (a.startsWith("--steps=")) {
                steps = Integer.parseInt(a.substring(8));
            } else if (a.startsWith("--paced-seconds=")) {
                pacedSeconds = Double.parseDouble(a.substring(16));
            } else if (a.startsWith("--only=")) {
                only = a.substring(7);
            } else if (a.equals("--paced-no-consume")) {
                consume = false;
            } else if (a.startsWith("--scenes=")) {
                scenes = a.substring(9);
            } else {
                throw new IllegalArgumentException("unknown argument " + a);
            }
        }
        List<String> names = new ArrayList<>();
        List<Builder> builders = new ArrayList<>();
        if (before != null) {
            names.add("before");
            builders.add(new Builder(loader(before)));
        }
        Builder current = new Builder(after != null ? loader(after) : SnapshotCost.class.getClassLoader());
        names.add(before != null ? "after" : "this");
        builders.add(current);
        System.out.printf(Locale.ROOT, "JDK %s, %d processors, load %.2f; %d rounds of %d steps%n",
                System.getProperty("java.version"), Runtime.getRuntime().availableProcessors(),
                ManagementFactory.getOperatingSystemMXBean().getSystemLoadAverage(), rounds, steps);
        for (String scene : scenes.split(",")) {
            if (only.contains("frames")) {
                framesMode(scene, names, builders, rounds, steps);
            }
            if (only.contains("publish")) {
                publishMode(scene, current, rounds, steps);
            }
            if (only.contains("paced")) {
                pacedMode(scene, current, false, Math.max(3, rounds / 2), pacedSeconds);
                pacedMode(scene, current, true, Math.max(3, rounds / 2), pacedSeconds);
            }
        }
    }

    private static ClassLoader loader(String path) throws Exception {
        List<URL> urls = new ArrayList<>();
        for (String p : path.split(File.pathSeparator)) {
            urls.add(new File(p).toURI().toURL());
        }
        return new URLClassLoader(urls.toArray(new URL[0]), new AllButTheLibrary());
    }

    /** The class path of this program (Processing, Minim, jSerialComm) without the library's own classes. */
    private static final class AllButTheLibrary extends ClassLoader {
        AllButTheLibrary() {
            super(SnapshotCost.class.getClassLoader());
        }

        @Override
        protected Class<?> loadClass(String name, boolean resolve) throws ClassNotFoundException {
            if (name.startsWith("tactus.")) {
                throw new ClassNotFoundException(name); // each build loads its own
            }
            return super.loadClass(name, resolve);
        }
    }
}
