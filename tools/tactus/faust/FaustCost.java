package tactus.faust;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;

import tactus.PhysicalModel;
import tactus.Vect3D;
import tactus.audio.OfflineRenderer;
import tactus.audio.PhyUGen;
import tactus.audio.SteppedModel;
import tactus.export.FaustExportOptions;
import tactus.export.FaustExporter;

/**
 * Measures what an exported model costs (docs/faust.md): per sample, the compiled Faust program ({@code faust
 * -double}, {@code g++ -O3}) against Tactus stepping the same model ({@code computeStep} alone, and a
 * {@code PhyUGen} rendered offline through Minim's tick); and how long {@code faust} and {@code g++} take to
 * compile models of 100, 1,000 and 10,000 elements (masses plus interactions). Each compiler is bounded by a
 * timeout (default 600 s); a size that does not compile within it is reported as such.
 *
 * <pre>
 * java -cp build/classes/java/main:build/classes/java/tools:build/resources/tools:&lt;minim, core jars&gt; \
 *     tactus.faust.FaustCost [timeoutSeconds]
 * </pre>
 * (or {@code gradle toolsClasses} first; any class path with main, tools and Minim works).
 */
public final class FaustCost {
    private FaustCost() {
    }

    /** Runs the measurements and prints a table. */
    public static void main(String[] args) throws IOException {
        int timeout = args.length > 0 ? Integer.parseInt(args[0]) : 600;
        FaustToolchain.requireTools();
        long memoryKb = args.length > 1 ? Long.parseLong(args[1]) : 8_000_000;
        FaustToolchain.limitFaustMemory(memoryKb);
        Path dir = Files.createTempDirectory("tactus-faust-cost");
        System.out.println("Compile times (strings between two fixed points; elements = masses + interactions; faust"
                + " limited to " + timeout + " s and " + memoryKb / 1000 + " MB)");
        System.out.println("| model | elements | faust -double | g++ -O1 | g++ -O3 |");
        System.out.println("|---|---|---|---|---|");
        for (boolean threeD : new boolean[] {false, true}) {
            for (int elements : new int[] {100, 1000, 10000}) {
                int n = elements / 2 - 1;
                String dsp = FaustExporter.toDsp(string(n, threeD), options(n, threeD));
                String name = "size" + elements + (threeD ? "3d" : "1d");
                String faust;
                String o1 = "-";
                String o3 = "-";
                boolean failed = false;
                try {
                    FaustToolchain.Program p1 = FaustToolchain.compile(dsp, dir, name, true, "-O1", timeout);
                    faust = p1.faustMillis + " ms";
                    o1 = p1.gccMillis + " ms";
                    FaustToolchain.Program p3 = FaustToolchain.compile(dsp, dir, name + "o3", true, "-O3", timeout);
                    o3 = p3.gccMillis + " ms";
                } catch (IllegalStateException e) {
                    faust = "failed: " + e.getMessage().split("\n")[0];
                    failed = true;
                }
                System.out.printf(Locale.ROOT, "| %s string | %d | %s | %s | %s |%n", threeD ? "3-D" : "1-D (mi.lib)",
                        elements, faust, o1, o3);
                if (failed) {
                    break;
                }
            }
        }
        System.out.println();
        System.out.println("Cost per sample (faust -double, g++ -O3; Tactus on this JVM, one thread)");
        System.out.println("| model | Faust program | Tactus computeStep | Tactus PhyUGen (offline) |");
        System.out.println("|---|---|---|---|");
        int[][] sizes = {{100, 0}, {300, 0}, {100, 1}, {1000, 1}};
        for (int[] size : sizes) {
            int n = size[0];
            boolean threeD = size[1] == 1;
            PhysicalModel m = string(n, threeD);
            String dsp = FaustExporter.toDsp(m, options(n, threeD));
            FaustToolchain.Program p;
            try {
                p = FaustToolchain.compile(dsp, dir, "cost" + n + (threeD ? "3d" : "1d"), true, "-O3", timeout);
            } catch (IllegalStateException e) {
                System.out.printf(Locale.ROOT, "| %s string, %d masses | does not compile: %s | | |%n",
                        threeD ? "3-D" : "1-D", n, e.getMessage().split("\n")[0]);
                continue;
            }
            int samples = n <= 100 ? 2_000_000 : 200_000;
            FaustToolchain.nanosPerSample(p, samples / 10, timeout);        // warm the caches
            double faust = FaustToolchain.nanosPerSample(p, samples, timeout);
            double step = stepNanos(string(n, threeD), samples);
            double ugen = ugenNanos(string(n, threeD), threeD, samples);
            System.out.printf(Locale.ROOT, "| %s string, %d masses | %.0f ns | %.0f ns | %.0f ns |%n",
                    threeD ? "3-D" : "1-D", n, faust, step, ugen);
        }
    }

    /**
     * A string of n masses between two fixed points, struck at mass n/5 + 1: 1-D (Mass1D, SpringDamper1D, K 0.2,
     * Z 0.0005) or 3-D (Mass3D, SpringDamper3D, l0 0.8 at spacing 1, K 0.2, Z 0.0005).
     */
    public static PhysicalModel string(int n, boolean threeD) {
        PhysicalModel m = new PhysicalModel(44100);
        addString(m, "", n, threeD);
        m.init();
        m.triggerForceImpulse(struckMass(n), 0, 0, 1);
        return m;
    }

    /** @return the mass {@link #string} strikes (and takes a force input on, exported): m(n/5 + 1) */
    public static String struckMass(int n) {
        return "m" + (n / 5 + 1);
    }

    /**
     * Adds the modules of {@link #string} to a model, each name with a prefix (a voice of a {@code VoiceBank}):
     * grounds g0 and g1, masses m1..mn, links s0..sn; the strike is left to the caller.
     */
    public static void addString(PhysicalModel m, String prefix, int n, boolean threeD) {
        if (threeD) {
            m.addGround3D(prefix + "g0", new Vect3D(0, 0, 0));
            m.addGround3D(prefix + "g1", new Vect3D(n + 1, 0, 0));
        } else {
            m.addGround1D(prefix + "g0", new Vect3D(0, 0, 0));
            m.addGround1D(prefix + "g1", new Vect3D(n + 1, 0, 0));
        }
        for (int i = 1; i <= n; i++) {
            Vect3D pos = new Vect3D(i, 0, 0);
            if (threeD) {
                m.addMass3D(prefix + "m" + i, 1, pos, new Vect3D());
            } else {
                m.addMass1D(prefix + "m" + i, 1, pos, new Vect3D());
            }
        }
        for (int i = 0; i <= n; i++) {
            String a = prefix + (i == 0 ? "g0" : "m" + i);
            String b = prefix + (i == n ? "g1" : "m" + (i + 1));
            if (threeD) {
                m.addSpringDamper3D(prefix + "s" + i, 0.8, 0.2, 0.0005, a, b);
            } else {
                m.addSpringDamper1D(prefix + "s" + i, 0, 0.2, 0.0005, a, b);
            }
        }
    }

    /**
     * The paper's 1-D metal plate (as the Faust agreement test and the bench use it): n x n Osc1D (M 1, K 0.0005)
     * joined to their right and lower neighbours by SpringDamper1D (K 0.15, Z 0.00002), at rest, 44.1 kHz.
     */
    public static PhysicalModel plate(int n) {
        PhysicalModel m = new PhysicalModel(44100, 60);
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++) {
                m.addOsc1D("p" + i + "_" + j, 1, 0.0005, 0, new Vect3D(i, j, 0), new Vect3D());
            }
        }
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++) {
                if (i + 1 < n) {
                    m.addSpringDamper1D("x" + i + "_" + j, 0, 0.15, 0.00002, "p" + i + "_" + j, "p" + (i + 1) + "_" + j);
                }
                if (j + 1 < n) {
                    m.addSpringDamper1D("y" + i + "_" + j, 0, 0.15, 0.00002, "p" + i + "_" + j, "p" + i + "_" + (j + 1));
                }
            }
        }
        m.init();
        return m;
    }

    /** @return export options for {@link #string}: output mass 2n/3 + 1 along z, a force input on mass n/5 + 1. */
    public static FaustExportOptions options(int n, boolean threeD) {
        return new FaustExportOptions().listen("m" + (2 * n / 3 + 1), 2).forceInput(struckMass(n), 2);
    }

    static double stepNanos(PhysicalModel m, int samples) {
        m.computeNSteps(samples / 10);
        long t0 = System.nanoTime();
        for (int i = 0; i < samples; i++) {
            m.computeStep();
        }
        return (System.nanoTime() - t0) / (double) samples;
    }

    static double ugenNanos(PhysicalModel m, boolean threeD, int samples) {
        PhyUGen u = new PhyUGen(m);
        u.listenToMass("m2", SteppedModel.Z, 1, 0);
        OfflineRenderer.renderToArray(u, 44100, 1, samples / 10 / 44100.0);
        long t0 = System.nanoTime();
        OfflineRenderer.renderToArray(u, 44100, 1, samples / 44100.0);
        return (System.nanoTime() - t0) / (double) samples;
    }
}
