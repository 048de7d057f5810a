package tactus.bench;

import java.io.BufferedReader;
import java.io.File;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import tactus.PhysicalModel;

/**
 * Parallel stepping on two cores: the 300x300 and 367x367 sheets of {@link Scenes#sheetWorkload} stepped with
 * one thread and with two ({@code PhysicalModel.setThreads(2)}), interleaved, in a forked JVM. Parallel work is
 * measured in wall-clock time (the worker thread's CPU time is not the caller's), median of 7 runs after a
 * warm-up.
 */
final class ParallelBench {
    private ParallelBench() {
    }

    /** Runs the measurement in a forked JVM and returns its markdown section (or a line saying why not). */
    static String section() {
        String java = new File(System.getProperty("java.home"), "bin/java").getPath();
        List<String> cmd = new ArrayList<>(Arrays.asList(java, "-Xms2g", "-Xmx2g", "-XX:+UseParallelGC",
                "-Djava.awt.headless=true", "-cp", System.getProperty("java.class.path"), ParallelBench.class.getName()));
        StringBuilder out = new StringBuilder();
        try {
            Process p = new ProcessBuilder(cmd).redirectErrorStream(true).start();
            try (BufferedReader r = new BufferedReader(new InputStreamReader(p.getInputStream(),
                    StandardCharsets.UTF_8))) {
                String line;
                while ((line = r.readLine()) != null) {
                    if (line.startsWith("progress:")) {
                        System.out.println("ParallelBench: " + line.substring(9).trim());
                    } else {
                        out.append(line).append('\n');
                    }
                }
            }
            if (p.waitFor() != 0) {
                return "\n## Parallel stepping\n\nThe parallel benchmark failed (exit " + p.exitValue() + "):\n\n```\n"
                        + out + "```\n";
            }
        } catch (IOException | InterruptedException e) {
            return "\n## Parallel stepping\n\nThe parallel benchmark could not run: " + e + "\n";
        }
        return out.toString();
    }

    /** The child: measures and prints the markdown section on stdout (progress lines are prefixed). */
    public static void main(String[] args) {
        StringBuilder md = new StringBuilder();
        md.append("\n## Parallel stepping on two cores\n\n");
        md.append("The sheets of the mesh scenes, stepped by `computeNSteps` with one thread and with two "
                + "(`setThreads(2)`), interleaved in one forked JVM (JDK ").append(System.getProperty("java.version"))
                .append("), wall-clock time, median (min-max) of 7 runs after a 3 s warm-up. With one thread a "
                + "sheet this large uses index arrays (it streams from memory); with two it uses stencil runs, "
                + "whose phases split across the threads (for one plan, parallel stepping is bit-identical to one thread: "
                + "ParallelStepTest checks it).\n\n");
        md.append("| sheet | elements | 1 thread ns/element | 2 threads ns/element | speed-up |\n|---|---|---|---|---|\n");
        for (int w : new int[] {100, 300, 367}) {
            System.out.println("progress: sheet " + w + "x" + w);
            Workload one = Scenes.sheetWorkload(w, false);
            Workload two = Scenes.sheetWorkload(w, false);
            ((PhysicalModel) two.model()).setThreads(2);
            long elements = one.elements();
            int steps = (int) Math.max(20, 2e8 / elements / 4);
            long until = System.nanoTime() + 3_000_000_000L;
            while (System.nanoTime() < until) {
                one.advance(steps);
                two.advance(steps);
            }
            double[] a = new double[7];
            double[] b = new double[7];
            for (int r = 0; r < 7; r++) {
                long t0 = System.nanoTime();
                one.advance(steps);
                long t1 = System.nanoTime();
                two.advance(steps);
                long t2 = System.nanoTime();
                a[r] = (t1 - t0) / (double) steps / elements;
                b[r] = (t2 - t1) / (double) steps / elements;
            }
            double[] ratio = new double[7];
            for (int r = 0; r < 7; r++) {
                ratio[r] = a[r] / b[r];
            }
            md.append(String.format(Locale.ROOT, "| %dx%d | %,d | %.2f (%.2f-%.2f) | %.2f (%.2f-%.2f) | %.2fx%s |%n", w, w,
                    elements, Harness.median(a), Harness.min(a), Harness.max(a), Harness.median(b), Harness.min(b),
                    Harness.max(b), Harness.median(ratio), Double.isFinite(two.probe()) ? "" : " (diverged)"));
            ((PhysicalModel) two.model()).setThreads(1);
        }
        md.append("\nSmall models stay on one thread: below 20,000 elements the barriers between phases cost more "
                + "than they save.\n");
        System.out.print(md);
    }
}
