package tactus.bench;

import ddf.minim.ugens.Summer;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Locale;
import tactus.audio.PhyUGen;
import tactus.audio.SteppedModel;

/**
 * What a PhyUGen's block ({@link PhyUGen#setBlockSize(int)}) saves per sample: for each model of the Faust side by
 * side (the 30-mass 1-D string, the 8x8 plate, the 100-mass 1-D string, 16 voices of the 30-mass string), a PhyUGen
 * per voice on a Summer at block 1 and at block 64, ticked in alternating rounds of about 0.3 s in one JVM; prints
 * the CPU ns per sample of each and the ratio per round, with the median and the machine's load. Run:
 * {@code gradle blockBench} (about a minute).
 */
public final class BlockSizeBench {
    private BlockSizeBench() {
    }

    private static Summer voices(String id, int block) {
        PhyUGen[] us = new PhyUGen[FaustSideBySide.voices(id)];
        for (int i = 0; i < us.length; i++) {
            us[i] = new PhyUGen(FaustSideBySide.model(id));
            us[i].setBlockSize(block);
            us[i].listenToMass(FaustSideBySide.listened(id), SteppedModel.Z, 1, 0);
        }
        return AudioProfile.summing(us);
    }

    /** CPU ns per sample over about the given time. */
    private static double time(Summer root, float[] frame, double seconds, ThreadMXBean cpu) {
        long t0 = cpu.getCurrentThreadCpuTime();
        long wall = System.nanoTime();
        long n = 0;
        double sink = 0;
        while (System.nanoTime() - wall < seconds * 1e9) {
            for (int i = 0; i < 4096; i++) {
                frame[0] = 0;
                root.tick(frame);
                sink += frame[0];
            }
            n += 4096;
        }
        if (sink == 42.4242) {
            System.out.print("");
        }
        return (cpu.getCurrentThreadCpuTime() - t0) / (double) n;
    }

    private static String load() {
        try {
            return Files.readString(Path.of("/proc/loadavg")).trim();
        } catch (Exception e) {
            return "unknown";
        }
    }

    /** Runs the comparison and prints a Markdown table. */
    public static void main(String[] args) {
        Locale.setDefault(Locale.ROOT);
        ThreadMXBean cpu = ManagementFactory.getThreadMXBean();
        int rounds = 7;
        System.out.println("load at start: " + load() + "; " + Runtime.getRuntime().availableProcessors() + " cores");
        System.out.println("| model | block 1 (ns/sample, cpu) | block 64 | block 1 / block 64 (median, range) |");
        System.out.println("|---|---|---|---|");
        for (String id : new String[] {"string1d-30", "plate-8x8", "string1d-100", "voices16-string1d-30"}) {
            Summer one = voices(id, 1);
            Summer block = voices(id, 64);
            float[] frame = new float[1];
            time(one, frame, 1, cpu);   // warm-up
            time(block, frame, 1, cpu);
            List<Double> a = new ArrayList<>();
            List<Double> b = new ArrayList<>();
            List<Double> r = new ArrayList<>();
            for (int k = 0; k < rounds; k++) {
                double x = time(one, frame, 0.3, cpu);
                double y = time(block, frame, 0.3, cpu);
                a.add(x);
                b.add(y);
                r.add(x / y);
                System.err.printf("%s round %d: block 1 %.0f ns, block 64 %.0f ns%n", id, k + 1, x, y);
            }
            Collections.sort(a);
            Collections.sort(b);
            Collections.sort(r);
            System.out.printf("| %s | %.0f | %.0f | %.2f (%.2f-%.2f) |%n", id, a.get(rounds / 2), b.get(rounds / 2),
                    r.get(rounds / 2), r.get(0), r.get(rounds - 1));
        }
        System.out.println("load at end: " + load());
    }
}
