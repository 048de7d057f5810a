package tactus.bench;

import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Method;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.List;
import java.util.Random;
import java.util.function.Supplier;
import tactus.Mass;
import tactus.PhysicalModel;
import tactus.Vect3D;
import tactus.engine.Engine;
import tactus.engine.LinkKind;
import tactus.engine.MassKind;
import tactus.paramSystem;

/**
 * The benchmark scenes. Every scene is built through the public {@link PhysicalModel} API in ALGO_UNITS (except
 * the engine-level variants of the overhead scene), with parameters inside the stability bound and the kind of
 * values the miPhysics examples use.
 *
 * <p>Counting: an element update is one inertial mass moved or one interaction computed. Fixed points (Ground3D)
 * are stepped by the engine (their force buffers are cleared every step) and that time is included, but they are
 * not counted as elements, so figures for scenes with many fixed points are slightly pessimistic.
 */
final class Scenes {
    /** Chain parameters (per step): mass, stiffness, damping, rest length, spacing. Tensioned: l0 < spacing. */
    static final double CHAIN_M = 1.0;
    static final double CHAIN_K = 0.4;
    static final double CHAIN_Z = 0.001;
    static final double CHAIN_L0 = 0.08;
    static final double CHAIN_DX = 0.1;
    /** Air friction of the audio-style scenes (string, sheet), per step. */
    static final double AIR = 1e-5;

    private Scenes() {
    }

    /** A scene: one child JVM measures its variants interleaved (round-robin), so they see the same load. */
    static final class Scene {
        final String id;
        final String family;
        final String title;
        final List<Supplier<Workload>> variants;

        Scene(String id, String family, String title, List<Supplier<Workload>> variants) {
            this.id = id;
            this.family = family;
            this.title = title;
            this.variants = variants;
        }
    }

    /** @return every scene id, in the order the full benchmark runs them. */
    static List<String> ids() {
        return Arrays.asList("chain-470", "chain-1000", "chain-10000", "sheet-100", "sheet-100-diag", "sheet-300",
                "sheet-367", "plate-50", "marbles-200", "marbles-200-rest", "marbles-600", "marbles-600-rest", "marbles-5000",
                "marbles-5000-rest", "overhead", "audio-500",
                "audio-1000", "audio-5000");
    }

    /** @return true when {@code PhysicalModel.addContactGroup(String, double, double, double)} exists. */
    static boolean hasContactGroup() {
        return contactGroupMethod() != null;
    }

    private static Method contactGroupMethod() {
        try {
            return PhysicalModel.class.getMethod("addContactGroup", String.class, double.class, double.class,
                    double.class);
        } catch (NoSuchMethodException e) {
            return null;
        }
    }

    /** @return the scene with this id, or null if the id is unknown. */
    static Scene byId(String id) {
        String[] parts = id.split("-");
        switch (parts[0]) {
            case "chain": {
                int n = Integer.parseInt(parts[1]);
                return new Scene(id, "chain", "3D string, " + n + " Mass3D + " + (n + 1) + " SpringDamper3D",
                        list(() -> new ModelWorkload("PhysicalModel", chainModel(n, false), 2L * n + 1, "m" + (n / 3))));
            }
            case "sheet": {
                int w = Integer.parseInt(parts[1]);
                boolean diag = id.endsWith("-diag");
                return new Scene(id, "mesh", "sheet " + w + "x" + w + (diag ? ", right + down + diagonal" : ", right + down"),
                        list(() -> sheetWorkload(w, diag)));
            }
            case "plate": {
                int w = Integer.parseInt(parts[1]);
                return new Scene(id, "mesh", "plate " + w + "x" + w + " Osc1D + SpringDamper1D",
                        list(() -> plateWorkload(w)));
            }
            case "marbles": {
                int n = Integer.parseInt(parts[1]);
                boolean stir = !id.endsWith("-rest");
                List<Supplier<Workload>> v = new ArrayList<>();
                if (n <= 600) {
                    v.add(() -> marblesWorkload(n, false, stir));
                }
                if (hasContactGroup()) {
                    v.add(() -> marblesWorkload(n, true, stir));
                }
                return new Scene(id, "marbles", "enclosed marbles, " + n + " Mass3D" + (stir ? ", stirred" : ", at rest"),
                        v);
            }
            case "overhead": {
                int n = 1000;
                List<Supplier<Workload>> v = new ArrayList<>();
                v.add(() -> new ModelWorkload("PhysicalModel", chainModel(n, true), 2L * n + 1, "m" + (n / 3)));
                v.add(() -> new EngineWorkload("Engine, stencil runs on", springChainEngine(n, true), 2L * n + 1));
                v.add(() -> new EngineWorkload("Engine, stencil runs off", springChainEngine(n, false), 2L * n + 1));
                v.add(() -> new HandChain(n, false));
                v.add(() -> new HandChain(n, true));
                return new Scene(id, "overhead", "springs-only chain, 1000 Mass3D + 1001 Spring3D, no damping, no gravity",
                        v);
            }
            case "audio": {
                int n = Integer.parseInt(parts[1]);
                List<Supplier<Workload>> v = new ArrayList<>();
                v.add(() -> new AudioWorkload(n, true));
                v.add(() -> new AudioWorkload(n, false));
                return new Scene(id, "audio", "audio rate, 1 sample per call: " + n + " Mass3D + " + (n + 1)
                        + " SpringDamper3D, one listening point", v);
            }
            default:
                return null;
        }
    }

    @SafeVarargs
    private static List<Supplier<Workload>> list(Supplier<Workload>... s) {
        return Collections.unmodifiableList(Arrays.asList(s));
    }

    // =========================================================================================== chain / string

    /**
     * Position of chain node i of a chain with n inertial masses (nodes 0 and n + 1 are the fixed ends): along x
     * with spacing {@link #CHAIN_DX}, plucked into a triangle in y (peak 0.05 at a third of the length) plus a
     * smaller sine in z, so all three coordinates move.
     */
    static double[] chainNode(int i, int n) {
        if (i == 0 || i == n + 1) {
            return new double[] {CHAIN_DX * i, 0, 0};
        }
        double u = (double) i / (n + 1);
        double tri = u < 1.0 / 3 ? 3 * u : 1.5 * (1 - u);
        return new double[] {CHAIN_DX * i, 0.05 * tri, 0.02 * Math.sin(3 * Math.PI * u)};
    }

    /**
     * A 3D string: masses m1..mn (Mass3D, M = 1) between fixed ends m0 and m(n+1) (Ground3D), each neighbour pair
     * linked by a SpringDamper3D (K 0.4, Z 0.001, l0 0.08 at spacing 0.1: under tension), with air friction 1e-5
     * (the Medium3D mass kernel). With {@code springsOnly}: Spring3D (K 0.4, l0 0.08), no damping, no friction,
     * no gravity (the Free3D mass kernel), i.e. exactly the equations of {@link HandChain}.
     * Counted elements: n masses + (n + 1) links.
     */
    static PhysicalModel chainModel(int n, boolean springsOnly) {
        PhysicalModel pm = new PhysicalModel(44100, 30, paramSystem.ALGO_UNITS);
        if (!springsOnly) {
            pm.setFriction(AIR);
        }
        Vect3D zero = new Vect3D();
        for (int i = 0; i <= n + 1; i++) {
            double[] p = chainNode(i, n);
            Vect3D pos = new Vect3D(p[0], p[1], p[2]);
            if (i == 0 || i == n + 1) {
                pm.addGround3D("m" + i, pos);
            } else {
                pm.addMass3D("m" + i, CHAIN_M, pos, zero);
            }
            if (i > 0) {
                if (springsOnly) {
                    pm.addSpring3D("s" + i, CHAIN_L0, CHAIN_K, "m" + (i - 1), "m" + i);
                } else {
                    pm.addSpringDamper3D("s" + i, CHAIN_L0, CHAIN_K, CHAIN_Z, "m" + (i - 1), "m" + i);
                }
            }
        }
        pm.init();
        return pm;
    }

    /** The springs-only chain built on the engine directly (no facade), with stencil runs on or off. */
    static Engine springChainEngine(int n, boolean stencils) {
        Engine e = new Engine();
        e.setStencilRuns(stencils);
        int prev = -1;
        for (int i = 0; i <= n + 1; i++) {
            double[] p = chainNode(i, n);
            MassKind kind = (i == 0 || i == n + 1) ? MassKind.GROUND3D : MassKind.MASS3D;
            int id = e.addMass(kind, CHAIN_M, p[0], p[1], p[2], 0, 0, 0);
            if (prev >= 0) {
                e.addLink(LinkKind.SPRING3D, prev, id, CHAIN_K, 0, CHAIN_L0);
            }
            prev = id;
        }
        e.compile();
        return e;
    }

    // =========================================================================================== meshes

    /**
     * A w x w sheet of nodes at spacing 0.1 in the z = 0 plane: the border is fixed (Ground3D), the interior is
     * Mass3D (M = 1) with a small Gaussian bump in z. SpringDamper3D to the right and down neighbours (K 0.2,
     * Z 0.001, l0 0.09: a tensioned membrane), and with {@code diag} also to the down-right neighbour (K 0.1,
     * Z 0.0005, l0 0.09 sqrt 2). Links between two fixed nodes are left out. Air friction 1e-5.
     * Counted elements: (w - 2)^2 masses + every link.
     */
    static Workload sheetWorkload(int w, boolean diag) {
        PhysicalModel pm = new PhysicalModel(44100, 30, paramSystem.ALGO_UNITS);
        pm.setFriction(AIR);
        Vect3D zero = new Vect3D();
        double ci = 0.37 * (w - 1), cj = 0.61 * (w - 1), sig = Math.max(2.0, w / 20.0);
        for (int j = 0; j < w; j++) {
            for (int i = 0; i < w; i++) {
                boolean border = i == 0 || j == 0 || i == w - 1 || j == w - 1;
                double bump = border ? 0 : 0.01 * Math.exp(-((i - ci) * (i - ci) + (j - cj) * (j - cj)) / (2 * sig * sig));
                Vect3D pos = new Vect3D(0.1 * i, 0.1 * j, bump);
                if (border) {
                    pm.addGround3D("n" + (j * w + i), pos);
                } else {
                    pm.addMass3D("n" + (j * w + i), 1.0, pos, zero);
                }
            }
        }
        long links = 0;
        for (int j = 0; j < w; j++) {
            for (int i = 0; i < w; i++) {
                String a = "n" + (j * w + i);
                if (i + 1 < w && !(fixedNode(i, j, w) && fixedNode(i + 1, j, w))) {
                    pm.addSpringDamper3D("r" + (j * w + i), 0.09, 0.2, 0.001, a, "n" + (j * w + i + 1));
                    links++;
                }
                if (j + 1 < w && !(fixedNode(i, j, w) && fixedNode(i, j + 1, w))) {
                    pm.addSpringDamper3D("d" + (j * w + i), 0.09, 0.2, 0.001, a, "n" + ((j + 1) * w + i));
                    links++;
                }
                if (diag && i + 1 < w && j + 1 < w && !(fixedNode(i, j, w) && fixedNode(i + 1, j + 1, w))) {
                    pm.addSpringDamper3D("x" + (j * w + i), 0.09 * Math.sqrt(2), 0.1, 0.0005, a,
                            "n" + ((j + 1) * w + i + 1));
                    links++;
                }
            }
        }
        pm.init();
        long masses = (long) (w - 2) * (w - 2);
        int mid = (w / 2) * w + w / 2;
        return new ModelWorkload("PhysicalModel", pm, masses + links, "n" + mid);
    }

    private static boolean fixedNode(int i, int j, int w) {
        return i == 0 || j == 0 || i == w - 1 || j == w - 1;
    }

    /**
     * A w x w plate like miPhysics' MetalPlate1D: every node an Osc1D (M 1, K 0.01, Z 0.0001 to its rest
     * position), SpringDamper1D (K 0.2, Z 0.0005, rest 0) to the right and down neighbours, struck by an
     * initial z displacement. Counted elements: w^2 oscillators + 2 w (w - 1) links.
     */
    static Workload plateWorkload(int w) {
        PhysicalModel pm = new PhysicalModel(44100, 30, paramSystem.ALGO_UNITS);
        Vect3D zero = new Vect3D();
        double ci = 0.3 * (w - 1), cj = 0.55 * (w - 1);
        for (int j = 0; j < w; j++) {
            for (int i = 0; i < w; i++) {
                double bump = 0.01 * Math.exp(-((i - ci) * (i - ci) + (j - cj) * (j - cj)) / 8.0);
                pm.addOsc1D("p" + (j * w + i), 1.0, 0.01, 0.0001, new Vect3D(0.1 * i, 0.1 * j, bump), zero);
            }
        }
        long links = 0;
        for (int j = 0; j < w; j++) {
            for (int i = 0; i < w; i++) {
                String a = "p" + (j * w + i);
                if (i + 1 < w) {
                    pm.addSpringDamper1D("r" + (j * w + i), 0, 0.2, 0.0005, a, "p" + (j * w + i + 1));
                    links++;
                }
                if (j + 1 < w) {
                    pm.addSpringDamper1D("d" + (j * w + i), 0, 0.2, 0.0005, a, "p" + ((j + 1) * w + i));
                    links++;
                }
            }
        }
        pm.init();
        return new ModelWorkload("PhysicalModel", pm, (long) w * w + links, "p" + ((w / 2) * w + w / 3));
    }

    // =========================================================================================== marbles

    /** Contact parameters of the marbles (threshold, K, Z), as in miPhysics' EnclosedMarbles. */
    static final double MARBLE_THR = 0.2;
    static final double MARBLE_K = 0.02;
    static final double MARBLE_Z = 0.01;
    /**
     * The stirrer: mass, stiffness of its arm to the hub (a zero-length Spring3D: a harmonic central force, so a
     * circular orbit of period 2 pi sqrt(M/K), about 3,000 steps = 3 s at 1 kHz), orbit radius, height of its plane,
     * and the threshold of its contacts with the marbles (the avatar's 0.5 in EnclosedMarbles).
     */
    static final double STIR_M = 1e6;
    static final double STIR_K = 4.39;
    static final double STIR_R = 1.2;
    static final double STIR_Z = 0.3;
    static final double STIR_THR = 0.5;

    /**
     * Initial marble positions: the n lowest points of a lattice with spacing 0.21 (no contact engaged at start)
     * inside a sphere of radius 2.7 about (0, 0, 1) and above z = 0.15, each jittered by up to 0.004: the marbles
     * start as a loose pile in the bottom of the bubble.
     */
    static double[][] marblePositions(int n) {
        List<double[]> pts = new ArrayList<>();
        double h = 0.21;
        for (int a = -14; a <= 14; a++) {
            for (int b = -14; b <= 14; b++) {
                for (int c = 0; c <= 30; c++) {
                    double x = a * h, y = b * h, z = 0.15 + c * h;
                    double r2 = x * x + y * y + (z - 1) * (z - 1);
                    if (r2 < 2.7 * 2.7) {
                        pts.add(new double[] {x, y, z});
                    }
                }
            }
        }
        pts.sort((p, q) -> p[2] != q[2] ? Double.compare(p[2], q[2])
                : Double.compare(p[0] * p[0] + p[1] * p[1], q[0] * q[0] + q[1] * q[1]));
        if (pts.size() < n) {
            throw new IllegalStateException("only " + pts.size() + " lattice points for " + n + " marbles");
        }
        Random rnd = new Random(42);
        double[][] out = new double[n][];
        for (int i = 0; i < n; i++) {
            double[] p = pts.get(i);
            out[i] = new double[] {p[0] + 0.004 * (2 * rnd.nextDouble() - 1), p[1] + 0.004 * (2 * rnd.nextDouble() - 1),
                p[2] + 0.004 * (2 * rnd.nextDouble() - 1)};
        }
        return out;
    }

    /**
     * Enclosed marbles after miPhysics' EnclosedMarbles: n Mass3D (M 7..10), gravity 5e-5, friction 1e-3; per marble
     * a Bubble3D to a fixed centre at (0, 0, 1) (R 3, K 0.1, Z 0.1) and a PlaneContact on z = 0 (l0 0.1, K 0.01,
     * Z 0.01); contacts (threshold 0.2, K 0.02, Z 0.01) between every unordered pair (i &lt; j), either as explicit
     * Contact3D links or as one contact group over the subset of all marbles. In place of the haptic avatar, a
     * stirrer: a Mass2DPlane of mass 1e6 in the plane z = 0.3 (so gravity does not pull it), on a zero-length
     * Spring3D to a fixed hub, launched into a circular orbit of radius 1.2 (period about 3 s), with a Contact3D to
     * every marble (threshold 0.5, K 0.02, Z 0.01): it keeps ploughing through the pile, so the marbles keep moving.
     * Without {@code stir} the marbles settle and rest (the cheapest state for a contact group).
     * Counted elements (both variants, so per-element figures compare): n + 1 masses + n (n - 1) / 2 pair contacts
     * + n bubbles + n plane contacts + n stirrer contacts + 1 arm (without the stirrer: n + n (n - 1) / 2 + 2 n).
     */
    static Workload marblesWorkload(int n, boolean group, boolean stir) {
        PhysicalModel pm = new PhysicalModel(1000, 30, paramSystem.ALGO_UNITS);
        pm.setGravity(5e-5);
        pm.setFriction(1e-3);
        Random rnd = new Random(7);
        double[][] pos = marblePositions(n);
        pm.addGround3D("centre", new Vect3D(0, 0, 1));
        Vect3D zero = new Vect3D();
        for (int i = 0; i < n; i++) {
            pm.addMass3D("b" + i, 7 + 3 * rnd.nextDouble(), new Vect3D(pos[i][0], pos[i][1], pos[i][2]), zero);
            pm.addBubble3D("bb" + i, 3, 0.1, 0.1, "b" + i, "centre");
            pm.addPlaneContact("pl" + i, 0.1, 0.01, 0.01, 2, 0, "b" + i);
        }
        if (stir) {
            // a heavy mass orbiting through the pile, standing in for the haptic avatar of EnclosedMarbles
            pm.addGround3D("hub", new Vect3D(0, 0, STIR_Z));
            double omega = Math.sqrt(STIR_K / STIR_M);
            pm.addMass2DPlane("stirrer", STIR_M, new Vect3D(STIR_R, 0, STIR_Z),
                    new Vect3D(0, omega * STIR_R * 1000, 0));
            pm.addSpring3D("arm", 0, STIR_K, "hub", "stirrer");
            for (int i = 0; i < n; i++) {
                pm.addContact3D("sc" + i, STIR_THR, MARBLE_K, MARBLE_Z, "stirrer", "b" + i);
            }
        }
        if (group) {
            pm.createMatSubset("marbles");
            for (int i = 0; i < n; i++) {
                pm.addMatToSubset("b" + i, "marbles");
            }
            try {
                contactGroupMethod().invoke(pm, "marbles", MARBLE_THR, MARBLE_K, MARBLE_Z);
            } catch (IllegalAccessException e) {
                throw new IllegalStateException(e);
            } catch (InvocationTargetException e) {
                throw new IllegalStateException("addContactGroup failed", e.getCause());
            }
        } else {
            for (int i = 0; i < n; i++) {
                for (int j = i + 1; j < n; j++) {
                    pm.addContact3D("c" + i + "_" + j, MARBLE_THR, MARBLE_K, MARBLE_Z, "b" + i, "b" + j);
                }
            }
        }
        pm.init();
        long elements = (stir ? 4L * n + 2 : 3L * n) + (long) n * (n - 1) / 2;
        return new MarblesWorkload(group ? "contact group" : "explicit Contact3D", pm, elements, n);
    }

    // =========================================================================================== workloads

    /** A PhysicalModel advanced with computeNSteps(n); the probe reads one mass's y with the allocation-free getter. */
    static class ModelWorkload implements Workload {
        final String variant;
        final PhysicalModel pm;
        final long elements;
        final Mass probeMass;
        final Vect3D out = new Vect3D();

        ModelWorkload(String variant, PhysicalModel pm, long elements, String probeName) {
            this.variant = variant;
            this.pm = pm;
            this.elements = elements;
            this.probeMass = pm.getMass(probeName);
        }

        @Override
        public String variant() {
            return variant;
        }

        @Override
        public long elements() {
            return elements;
        }

        @Override
        public void advance(int steps) {
            pm.computeNSteps(steps);
        }

        @Override
        public double probe() {
            return probeMass.getPosition(out).y + out.z;
        }

        @Override
        public Object model() {
            return pm;
        }
    }

    /** The marbles: also reports how many pair contacts are engaged (a cost driver of the contact group). */
    static final class MarblesWorkload extends ModelWorkload {
        final int n;

        MarblesWorkload(String variant, PhysicalModel pm, long elements, int n) {
            super(variant, pm, elements, "b" + (n / 2));
            this.n = n;
        }

        @Override
        public double probe() {
            return probeMass.getPosition(out).z;
        }

        /** @return the stirrer's speed, in units per second (about 2.5 at launch), or NaN without a stirrer. */
        double stirrerSpeed() {
            if (!pm.matExists("stirrer")) {
                return Double.NaN;
            }
            Vect3D v = pm.getMatVelocity("stirrer");
            return Math.sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
        }

        /** @return engaged pair contacts (d &lt; threshold) per marble, counted brute force, and the lowest z. */
        double[] engaged() {
            double[] x = new double[n], y = new double[n], z = new double[n];
            Vect3D v = new Vect3D();
            double minZ = Double.MAX_VALUE;
            for (int i = 0; i < n; i++) {
                pm.getMatPosition("b" + i, v);
                x[i] = v.x;
                y[i] = v.y;
                z[i] = v.z;
                minZ = Math.min(minZ, v.z);
            }
            long c = 0;
            double t2 = MARBLE_THR * MARBLE_THR;
            for (int i = 0; i < n; i++) {
                for (int j = i + 1; j < n; j++) {
                    double dx = x[i] - x[j], dy = y[i] - y[j], dz = z[i] - z[j];
                    if (dx * dx + dy * dy + dz * dz < t2) {
                        c++;
                    }
                }
            }
            return new double[] {2.0 * c / n, minZ};
        }
    }

    /** An Engine advanced with step(n). */
    static final class EngineWorkload implements Workload {
        private final String variant;
        private final Engine engine;
        private final long elements;
        private final int probeId;
        private final double[] out = new double[3];

        EngineWorkload(String variant, Engine engine, long elements) {
            this.variant = variant;
            this.engine = engine;
            this.elements = elements;
            this.probeId = (int) ((elements - 1) / 2) / 3;
        }

        @Override
        public String variant() {
            return variant;
        }

        @Override
        public long elements() {
            return elements;
        }

        @Override
        public void advance(int steps) {
            engine.step(steps);
        }

        @Override
        public double probe() {
            engine.position(probeId, out);
            return out[1] + out[2];
        }

        @Override
        public Object model() {
            return engine;
        }

        Engine engine() {
            return engine;
        }
    }

    /**
     * Audio-rate stepping as an audio callback does it: one computeStep() per sample, then the listening mass's
     * position read with an allocation-free getter (the Mass handle's getPosition(Vect3D), or
     * PhysicalModel.getMatPosition(String, Vect3D) by name), summed into an output value.
     */
    static final class AudioWorkload implements Workload {
        private final PhysicalModel pm;
        private final int n;
        private final boolean handle;
        private final Mass listen;
        private final String listenName;
        private final Vect3D out = new Vect3D();
        private double acc;

        AudioWorkload(int n, boolean handle) {
            this.n = n;
            this.handle = handle;
            this.pm = chainModel(n, false);
            this.listenName = "m" + (n / 3);
            this.listen = pm.getMass(listenName);
        }

        @Override
        public String variant() {
            return handle ? "Mass.getPosition(Vect3D)" : "getMatPosition(String, Vect3D)";
        }

        @Override
        public long elements() {
            return 2L * n + 1;
        }

        @Override
        public void advance(int samples) {
            double a = acc;
            if (handle) {
                for (int s = 0; s < samples; s++) {
                    pm.computeStep();
                    a += listen.getPosition(out).y;
                }
            } else {
                for (int s = 0; s < samples; s++) {
                    pm.computeStep();
                    a += pm.getMatPosition(listenName, out).y;
                }
            }
            acc = a * 0.5;
        }

        @Override
        public double probe() {
            return acc + out.y;
        }

        @Override
        public Object model() {
            return pm;
        }
    }
}
