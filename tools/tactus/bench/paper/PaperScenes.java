package tactus.bench.paper;

import tactus.*;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import java.util.concurrent.locks.LockSupport;
import java.util.function.Consumer;

/**
 * The side-by-side benchmark scenes, written once against the paper's API ({@code PhysicalModel}, {@code addMass3D},
 * {@code addSpringDamper3D}, {@code addContact3D}, ...) in the style of the authors' sketches, and the child program
 * that times them. This one source is compiled twice: as it is, against Tactus (the tools source set), and, by
 * {@link tactus.bench.SideBySide}, with its engine import line replaced by the paper engine's, against a
 * {@code miPhysics.jar} built from the authors' repository. Nothing else differs between the two builds: the same
 * scenes, the same stepping calls, the same timing code.
 *
 * <p>Only calls that exist in both engines are used; the {@code add*} methods are called as statements (the paper's
 * engine returns {@code int 0}, Tactus returns the module). The two Tactus-only parts (a contact group, and a reader
 * of {@code getSnapshot()}) are loaded by class name, so that this source compiles against the paper's engine too.
 *
 * <p>Child usage: {@code java -cp <engine classpath> tactus.bench.paper.PaperScenes <scene> [--quick]
 * [--reader=lock|snapshot] [--group]}. It prints one {@value #RESULT} line per variant (µs per step of every
 * measured run) and one {@value #INFO} line; everything else is progress.
 */
public final class PaperScenes {
    /** Tag of a result line. */
    public static final String RESULT = "@@SIDE";
    /** Tag of the information line. */
    public static final String INFO = "@@SIDEINFO";
    /** The scenes, in report order. */
    public static final String[] SCENES = {"string-470", "string-1000", "mesh-100", "marbles-200"};
    /** Reads per simulated second of a reader (a sketch drawing at 60 frames per second). */
    public static final int READER_FPS = 60;
    /** Class name of the Tactus contact-group hook (a {@code Consumer<Object>} given the model). */
    public static final String GROUP_HOOK = "tactus.bench.paper.ContactGroupHook";
    /** Class name of the Tactus snapshot reader (a {@code Runnable} built from the model). */
    public static final String SNAPSHOT_READER = "tactus.bench.paper.SnapshotReader";

    private static final ThreadMXBean CPU = ManagementFactory.getThreadMXBean();

    private PaperScenes() {
    }

    // ============================================================================================== scenes

    /**
     * A 3D string after the paper's sketches: {@code masses} Mass3D (M 1) between two Ground3D, spaced 0.1 on x,
     * {@code masses + 1} SpringDamper3D (l0 0.08, K 0.4, Z 0.001), air friction 1e-5, plucked in y and z.
     *
     * @param masses number of Mass3D
     * @param rate simulation rate (Hz)
     * @return the model, initialised
     */
    public static PhysicalModel string(int masses, int rate) {
        PhysicalModel mdl = new PhysicalModel(rate);
        mdl.setFriction(0.00001);
        int apex = Math.max(1, masses / 3);
        for (int i = 0; i <= masses + 1; i++) {
            if (i == 0 || i == masses + 1) {
                mdl.addGround3D(node(i, masses), new Vect3D(0.1 * i, 0, 0));
            } else {
                double a = i <= apex ? (double) i / apex : (double) (masses + 1 - i) / (masses + 1 - apex);
                mdl.addMass3D(node(i, masses), 1, new Vect3D(0.1 * i, 0.02 * a, 0.01 * a), new Vect3D(0, 0, 0));
            }
        }
        for (int i = 0; i <= masses; i++) {
            mdl.addSpringDamper3D("spring" + i, 0.08, 0.4, 0.001, node(i, masses), node(i + 1, masses));
        }
        mdl.init();
        return mdl;
    }

    private static String node(int i, int masses) {
        return i == 0 || i == masses + 1 ? "gnd" + i : "mass" + i;
    }

    /**
     * A mesh of {@code w} x {@code w} nodes spaced 0.1, its border grounded (Ground3D), the others Mass3D (M 1) with a
     * Gaussian bump in z; a SpringDamper3D (l0 0.09, K 0.2, Z 0.001) to the right and lower neighbours (none between
     * two grounded nodes); gravity 1e-5, friction 1e-5, at 1 kHz.
     *
     * @param w nodes per side
     * @return the model, initialised
     */
    public static PhysicalModel mesh(int w) {
        PhysicalModel mdl = new PhysicalModel(1000);
        mdl.setGravity(0.00001);
        mdl.setFriction(0.00001);
        double c = (w - 1) / 2.0;
        for (int i = 0; i < w; i++) {
            for (int j = 0; j < w; j++) {
                Vect3D pos = new Vect3D(0.1 * i, 0.1 * j, 0);
                if (border(i, j, w)) {
                    mdl.addGround3D("n" + i + "_" + j, pos);
                } else {
                    double r2 = ((i - c) * (i - c) + (j - c) * (j - c)) / (0.01 * w * w);
                    pos.z = 0.05 * Math.exp(-r2);
                    mdl.addMass3D("n" + i + "_" + j, 1, pos, new Vect3D(0, 0, 0));
                }
            }
        }
        for (int i = 0; i < w; i++) {
            for (int j = 0; j < w; j++) {
                if (i + 1 < w && !(border(i, j, w) && border(i + 1, j, w))) {
                    mdl.addSpringDamper3D("r" + i + "_" + j, 0.09, 0.2, 0.001, "n" + i + "_" + j, "n" + (i + 1) + "_" + j);
                }
                if (j + 1 < w && !(border(i, j, w) && border(i, j + 1, w))) {
                    mdl.addSpringDamper3D("d" + i + "_" + j, 0.09, 0.2, 0.001, "n" + i + "_" + j, "n" + i + "_" + (j + 1));
                }
            }
        }
        mdl.init();
        return mdl;
    }

    private static boolean border(int i, int j, int w) {
        return i == 0 || j == 0 || i == w - 1 || j == w - 1;
    }

    /**
     * The authors' EnclosedMarbles without its haptic avatar: {@code n} Mass3D (M 7-10) at random in the cube
     * [-1, 1]³ (fixed seed), gravity 5e-5, friction 1e-3, at 1 kHz; a Ground3D "gnd" at (0, 0, 1), a Bubble3D per marble
     * to it (R 3, K 0.1, Z 0.1), a PlaneContact per marble on z = 0 (l0 0, K 0.01, Z 0.01), and, for every
     * unordered pair, either one Contact3D (threshold 0.2, K 0.02, Z 0.01; the sketch adds both orders) or, when
     * {@code group} is given, a mass subset "marbles" handed to {@code group} (Tactus: one contact group).
     *
     * @param n number of marbles
     * @param group null for explicit Contact3D links; else called with the model once the subset exists
     * @return the model, initialised
     */
    public static PhysicalModel marbles(int n, Consumer<Object> group) {
        PhysicalModel mdl = new PhysicalModel(1000);
        mdl.setGravity(0.00005);
        mdl.setFriction(0.001);
        Random random = new Random(7);
        for (int i = 0; i < n; i++) {
            Vect3D pos = new Vect3D(2 * random.nextDouble() - 1, 2 * random.nextDouble() - 1, 2 * random.nextDouble() - 1);
            mdl.addMass3D("mass" + i, 7 + 3 * random.nextDouble(), pos, new Vect3D(0, 0, 0));
        }
        mdl.addGround3D("gnd", new Vect3D(0, 0, 1));
        for (int i = 0; i < n; i++) {
            mdl.addBubble3D("bub" + i, 3, 0.1, 0.1, "gnd", "mass" + i);
            mdl.addPlaneContact("plane" + i, 0, 0.01, 0.01, 2, 0, "mass" + i);
            if (group == null) {
                for (int j = 0; j < i; j++) {
                    mdl.addContact3D("cont" + i + "_" + j, 0.2, 0.02, 0.01, "mass" + j, "mass" + i);
                }
            }
        }
        if (group != null) {
            mdl.createMatSubset("marbles");
            for (int i = 0; i < n; i++) {
                mdl.addMatToSubset("mass" + i, "marbles");
            }
            group.accept(mdl);
        }
        mdl.init();
        return mdl;
    }

    /**
     * What the paper's renderer reads each frame, read the way it does: under the model's lock ({@code ModelRenderer}
     * copies every mass position and every link's two end positions, elongation and rest length inside
     * {@code synchronized (mdl.getLock())}). The stepping thread waits while it reads.
     */
    public static final class LockedReader implements Runnable {
        private final PhysicalModel mdl;
        /** Sum of what was read (keeps the reads alive). */
        public double sink;

        /** @param mdl the model to read */
        public LockedReader(PhysicalModel mdl) {
            this.mdl = mdl;
        }

        @Override
        public void run() {
            synchronized (mdl.getLock()) {
                int mats = mdl.getNumberOfMats();
                for (int i = 0; i < mats; i++) {
                    Vect3D p = mdl.getMatPosAt(i);
                    sink += p.x + p.y + p.z;
                }
                int links = mdl.getNumberOfLinks();
                for (int l = 0; l < links; l++) {
                    Vect3D a = mdl.getLinkPos1At(l);
                    Vect3D b = mdl.getLinkPos2At(l);
                    sink += a.x + b.z + mdl.getLinkElongationAt(l) + mdl.getLinkDRestAt(l);
                }
            }
        }
    }

    // ============================================================================================== timing

    /** One way of stepping a model for {@code n} steps, as a sketch would. */
    private interface Stepping {
        void run(PhysicalModel mdl, int n);
    }

    /** The scene's models and how they are stepped: one variant = one model stepped with or without a reader. */
    private static final class Variant {
        final String name;
        final PhysicalModel mdl;
        final Stepping stepping;
        final Runnable reader;
        final int simRate;
        double nsPerStep;
        long steps;
        int reads;
        final List<Double> micros = new ArrayList<>();
        final List<Double> cpuShare = new ArrayList<>();

        Variant(String name, PhysicalModel mdl, Stepping stepping, Runnable reader, int simRate) {
            this.name = name;
            this.mdl = mdl;
            this.stepping = stepping;
            this.reader = reader;
            this.simRate = simRate;
        }
    }

    /** A thread calling a reader {@value #READER_FPS} times per simulated second of the model being stepped. */
    private static final class ReaderThread extends Thread {
        private final Runnable read;
        private final long periodNs;
        private volatile boolean stop;
        int reads;

        ReaderThread(Runnable read, long periodNs) {
            super("bench-reader");
            this.read = read;
            this.periodNs = Math.max(1, periodNs);
            setDaemon(true);
        }

        @Override
        public void run() {
            long next = System.nanoTime() + periodNs;
            while (!stop) {
                long wait = next - System.nanoTime();
                if (wait > 0) {
                    LockSupport.parkNanos(wait);
                    continue;
                }
                read.run();
                reads++;
                next += periodNs;
            }
        }

        int finish() throws InterruptedException {
            stop = true;
            interrupt();
            join();
            return reads;
        }
    }

    private static double sink;

    private static final Stepping ONE_STEP_AT_A_TIME = (mdl, n) -> {
        for (int k = 0; k < n; k++) {
            mdl.computeStep();
        }
    };

    private static final Stepping N_STEPS = (mdl, n) -> mdl.computeNSteps(n);

    /**
     * Builds the variants of a scene.
     *
     * @param scene one of {@link #SCENES}
     * @param reader "lock" (the paper's renderer), "snapshot" (Tactus's {@code getSnapshot()}) or null (no reader
     *     variant)
     * @param group add the Tactus contact-group variant of the marbles
     * @return the variants, in measuring order
     */
    static List<Variant> variants(String scene, String reader, boolean group) throws ReflectiveOperationException {
        List<Variant> v = new ArrayList<>();
        switch (scene) {
            case "string-470": {
                PhysicalModel mdl = string(470, 44100);
                int listen = 470 / 3;
                v.add(new Variant("audio", mdl, (m, n) -> {
                    for (int k = 0; k < n; k++) {
                        m.computeStep();
                        sink += m.getMatPosAt(listen).y;
                    }
                }, null, 44100));
                break;
            }
            case "string-1000":
                v.add(new Variant("computeNSteps", string(1000, 44100), N_STEPS, null, 44100));
                break;
            case "mesh-100": {
                PhysicalModel mdl = mesh(100);
                v.add(new Variant("plain", mdl, ONE_STEP_AT_A_TIME, null, 1000));
                if (reader != null) {
                    v.add(new Variant("reader", mdl, ONE_STEP_AT_A_TIME, readerOf(reader, mdl), 1000));
                }
                break;
            }
            case "marbles-200": {
                PhysicalModel mdl = marbles(200, null);
                v.add(new Variant("explicit", mdl, ONE_STEP_AT_A_TIME, null, 1000));
                if (reader != null) {
                    v.add(new Variant("explicit-reader", mdl, ONE_STEP_AT_A_TIME, readerOf(reader, mdl), 1000));
                }
                if (group) {
                    @SuppressWarnings("unchecked")
                    Consumer<Object> hook = (Consumer<Object>) Class.forName(GROUP_HOOK).getConstructor().newInstance();
                    v.add(new Variant("group", marbles(200, hook), ONE_STEP_AT_A_TIME, null, 1000));
                }
                break;
            }
            default:
                throw new IllegalArgumentException("unknown scene " + scene);
        }
        return v;
    }

    private static Runnable readerOf(String kind, PhysicalModel mdl) throws ReflectiveOperationException {
        if (kind.equals("lock")) {
            return new LockedReader(mdl);
        }
        if (kind.equals("snapshot")) {
            return (Runnable) Class.forName(SNAPSHOT_READER).getConstructor(Object.class).newInstance(mdl);
        }
        throw new IllegalArgumentException("unknown reader " + kind + " (lock or snapshot)");
    }

    /** @return true when every mass position of the model is finite */
    public static boolean finite(PhysicalModel mdl) {
        int mats = mdl.getNumberOfMats();
        for (int i = 0; i < mats; i++) {
            Vect3D p = mdl.getMatPosAt(i);
            if (!Double.isFinite(p.x) || !Double.isFinite(p.y) || !Double.isFinite(p.z)) {
                return false;
            }
        }
        return true;
    }

    /** Times one run of a variant: µs per step (wall) and the thread's CPU share over it. */
    private static void measure(Variant v, int steps) throws InterruptedException {
        ReaderThread rt = null;
        if (v.reader != null) {
            rt = new ReaderThread(v.reader, (long) (v.nsPerStep * v.simRate / READER_FPS));
            rt.start();
        }
        long c0 = CPU.getCurrentThreadCpuTime();
        long t0 = System.nanoTime();
        v.stepping.run(v.mdl, steps);
        long t1 = System.nanoTime();
        long c1 = CPU.getCurrentThreadCpuTime();
        if (rt != null) {
            v.reads += rt.finish();
        }
        v.steps += steps;
        v.micros.add((t1 - t0) / 1e3 / steps);
        v.cpuShare.add((double) (c1 - c0) / Math.max(1, t1 - t0));
    }

    /** Steps a variant in doubling chunks for at least {@code seconds}; sets its ns per step from the last chunk. */
    private static void warmUp(Variant v, double seconds) {
        long end = System.nanoTime() + (long) (seconds * 1e9);
        int chunk = 8;
        while (true) {
            long t0 = System.nanoTime();
            v.stepping.run(v.mdl, chunk);
            long t1 = System.nanoTime();
            v.nsPerStep = (double) (t1 - t0) / chunk;
            if (t1 >= end) {
                return;
            }
            if (t1 - t0 < 100_000_000L) {
                chunk *= 2;
            }
        }
    }

    /**
     * The child program: builds the scene's variants, warms them up, then measures {@code rounds} rounds of one run
     * per variant (the variants interleaved, their order rotating per round), and prints the results.
     *
     * @param args scene, then {@code --quick}, {@code --reader=lock|snapshot}, {@code --group}
     */
    public static void main(String[] args) throws Exception {
        String scene = args[0];
        boolean quick = false;
        boolean group = false;
        String reader = null;
        for (int i = 1; i < args.length; i++) {
            if (args[i].equals("--quick")) {
                quick = true;
            } else if (args[i].equals("--group")) {
                group = true;
            } else if (args[i].startsWith("--reader=")) {
                reader = args[i].substring(9);
            } else {
                throw new IllegalArgumentException("unknown option " + args[i]);
            }
        }
        long b0 = System.nanoTime();
        List<Variant> vs = variants(scene, reader, group);
        double build = (System.nanoTime() - b0) * 1e-9;
        System.gc();
        double warm = quick ? 1.5 : 3.0;
        double run = quick ? 0.4 : 0.8;
        int rounds = quick ? 5 : 7;
        for (Variant v : vs) {
            warmUp(v, v.reader != null ? warm / 2 : warm);
            if (v.reader != null) {
                for (Variant plain : vs) {
                    if (plain.mdl == v.mdl && plain.reader == null) {
                        v.nsPerStep = plain.nsPerStep;
                    }
                }
                for (int k = 0; k < 200; k++) {
                    v.reader.run();
                }
            }
        }
        for (int r = 0; r < rounds; r++) {
            for (int k = 0; k < vs.size(); k++) {
                Variant v = vs.get((k + r) % vs.size());
                measure(v, (int) Math.max(1, Math.min(Integer.MAX_VALUE, run * 1e9 / v.nsPerStep)));
            }
        }
        System.out.println(INFO + "\tengine=" + PhysicalModel.class.getName() + "\tscene=" + scene
                + "\tbuild_s=" + String.format(Locale.ROOT, "%.2f", build) + "\tjava=" + System.getProperty("java.version"));
        for (Variant v : vs) {
            System.out.println(RESULT + "\tscene=" + scene + "\tvariant=" + v.name + "\tmats=" + v.mdl.getNumberOfMats()
                    + "\tlinks=" + v.mdl.getNumberOfLinks() + "\tsteps=" + v.steps + "\treads=" + v.reads
                    + "\tfinite=" + finite(v.mdl) + "\tus=" + join(v.micros) + "\tcpu=" + join(v.cpuShare));
        }
        if (sink == 42.4242) {
            System.out.println();
        }
    }

    private static String join(List<Double> values) {
        StringBuilder sb = new StringBuilder();
        for (double d : values) {
            if (sb.length() > 0) {
                sb.append(',');
            }
            sb.append(String.format(Locale.ROOT, "%.6g", d));
        }
        return sb.toString();
    }
}
