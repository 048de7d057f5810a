package tactus.stress;

import java.io.BufferedReader;
import java.io.File;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The haptic-stall stress tool: runs {@link StallChild} in many fresh JVMs, one after the other, beside a CPU
 * hog, and counts the runs in which a tick of the haptic loop came more than 20 ms late. It is not part of
 * {@code gradle test}; run it with {@code gradle hapticStress} (see build.gradle for the -P options) or directly:
 *
 * <pre>java -cp CLASSPATH tactus.stress.HapticStallStress [--runs=300] [--seconds=2] [--garbage=0]
 *      [--telemetry=0] [--hog=free|core0|core1|none] [--jvm="-XX:+UseZGC ..."] [--out=FILE]</pre>
 *
 * <ul>
 * <li>{@code --garbage=MB}: a thread in the run's JVM makes that many MB of garbage a second;</li>
 * <li>{@code --telemetry=MS}: a thread reads {@code HapticLoop.telemetry()} every MS milliseconds;</li>
 * <li>{@code --hog}: a {@code yes > /dev/null} process at normal priority, free to move or pinned to a core with
 * {@code taskset}.</li>
 * </ul>
 *
 * The hog and every run are started at normal priority ({@code chrt -o 0}) whatever this JVM's own policy, so
 * that only the haptic loop asks for real-time scheduling, as in a sketch (a shell left at SCHED_FIFO would make
 * every process it starts real-time, and the measurement meaningless). It prints one line per run and a summary,
 * and writes the summary to {@code --out} (default {@code build/stress/haptic-stall.txt}). Exit status 1 when a
 * run stalled past 20 ms or failed.
 */
public final class HapticStallStress {
    private static final Pattern RESULT = Pattern.compile(
            "RESULT ticks=(\\d+) worstLateMs=([\\d.]+) over20=(\\d+) gcPauses=(\\d+) gcMaxMs=([\\d.]+) "
                    + "lateMs=([\\d.]+) lateInGcMs=([\\d.]+) lateInSafepointsMs=([\\d.]+) stealMs=(\\d+) failure=(.*) "
                    + "sched=(.*)");

    /** The group of RESULT that holds the steal time; failure and scheduling follow it. */
    private static final int STEAL = 9;

    private HapticStallStress() {
    }

    /**
     * Runs the stress and prints the summary.
     *
     * @param args options as above
     * @throws Exception if a run cannot be started
     */
    public static void main(String[] args) throws Exception {
        int runs = 300;
        double seconds = 2;
        int garbage = 0;
        int telemetry = 0;
        String hog = "free";
        String jvm = "";
        String out = "build/stress/haptic-stall.txt";
        for (String a : args) {
            String v = a.substring(a.indexOf('=') + 1);
            if (a.startsWith("--runs=")) {
                runs = Integer.parseInt(v);
            } else if (a.startsWith("--seconds=")) {
                seconds = Double.parseDouble(v);
            } else if (a.startsWith("--garbage=")) {
                garbage = Integer.parseInt(v);
            } else if (a.startsWith("--telemetry=")) {
                telemetry = Integer.parseInt(v);
            } else if (a.startsWith("--hog=")) {
                hog = v;
            } else if (a.startsWith("--jvm=")) {
                jvm = v.trim();
            } else if (a.startsWith("--out=")) {
                out = v;
            } else {
                throw new IllegalArgumentException("HapticStallStress: unknown option " + a);
            }
        }
        String java = ProcessHandle.current().info().command().orElse("java");
        String classpath = System.getProperty("java.class.path");
        String setting = String.format(Locale.ROOT, "%d runs of %.1f s, garbage %d MB/s, telemetry read every %d ms, "
                + "hog %s, JVM options [%s]", runs, seconds, garbage, telemetry, hog, jvm);
        System.out.println("haptic stall stress: " + setting);
        Process hogProcess = startHog(hog);
        double[] worst = new double[runs];
        int stalled = 0;
        int failed = 0;
        int gcPauses = 0;
        double gcMax = 0;
        double late = 0;
        double lateInGc = 0;
        double lateInSafepoints = 0;
        String sched = "";
        long stolenInStalls = 0;
        int stalledWithSteal = 0;
        long t0 = System.nanoTime();
        try {
            for (int i = 0; i < runs; i++) {
                List<String> cmd = new ArrayList<>(Arrays.asList("chrt", "-o", "0", java, "-cp", classpath,
                        "-Djava.awt.headless=true"));
                if (!jvm.isEmpty()) {
                    cmd.addAll(Arrays.asList(jvm.split("\\s+")));
                }
                File log = File.createTempFile("tactus-stall-safepoints", ".log");
                cmd.add(1 + cmd.indexOf("-Djava.awt.headless=true"),
                        "-Xlog:safepoint:file=" + log.getPath() + ":timenanos");
                cmd.addAll(Arrays.asList(StallChild.class.getName(), Double.toString(seconds),
                        Integer.toString(garbage), Integer.toString(telemetry), log.getPath()));
                String line = runOnce(cmd, (long) (seconds * 1000) + 30_000);
                Files.deleteIfExists(log.toPath());
                Matcher m = line == null ? null : RESULT.matcher(line);
                if (m == null || !m.find()) {
                    failed++;
                    worst[i] = Double.POSITIVE_INFINITY;
                    System.out.printf(Locale.ROOT, "run %d/%d: FAILED (%s)%n", i + 1, runs, line);
                    continue;
                }
                worst[i] = Double.parseDouble(m.group(2));
                boolean over = Integer.parseInt(m.group(3)) > 0 || worst[i] > 20;
                if (over) {
                    stalled++;
                    stolenInStalls += Long.parseLong(m.group(STEAL));
                    if (Long.parseLong(m.group(STEAL)) > 0) {
                        stalledWithSteal++;
                    }
                }
                if (!"null".equals(m.group(STEAL + 1))) {
                    failed++;
                }
                gcPauses += Integer.parseInt(m.group(4));
                gcMax = Math.max(gcMax, Double.parseDouble(m.group(5)));
                late += Double.parseDouble(m.group(6));
                lateInGc += Double.parseDouble(m.group(7));
                lateInSafepoints += Double.parseDouble(m.group(8));
                sched = m.group(STEAL + 2);
                System.out.printf(Locale.ROOT, "run %d/%d: worst tick %.2f ms late%s, %s GC pauses (max %s ms), "
                                + "%s ms stolen by the hypervisor, %.0f s elapsed%s%n", i + 1, runs, worst[i],
                        over ? " STALL" : "", m.group(4), m.group(5), m.group(STEAL), (System.nanoTime() - t0) / 1e9,
                        "null".equals(m.group(STEAL + 1)) ? "" : ", FAILED: " + m.group(STEAL + 1));
            }
        } finally {
            if (hogProcess != null) {
                hogProcess.destroyForcibly();
            }
        }
        double[] sorted = worst.clone();
        Arrays.sort(sorted);
        String summary = String.format(Locale.ROOT, "haptic stall stress: %s%n"
                        + "scheduling of the loop: %s%n"
                        + "runs with a tick more than 20 ms late: %d of %d; failed runs: %d%n"
                        + "worst lateness per run: p50 %.2f ms, p90 %.2f ms, p99 %.2f ms, max %.2f ms%n"
                        + "lateness above one period, all runs: %.1f ms, of which %.1f ms (%.0f %%) inside GC pauses "
                        + "(%d pauses, longest %.1f ms) and %.1f ms (%.0f %%) inside any safepoint%n"
                        + "runs with a stall during which the hypervisor took CPU time from this machine: %d of %d "
                        + "(%d ms in all, counted in 10 ms jiffies of /proc/stat's steal)%n",
                setting, sched, stalled, runs, failed, q(sorted, 0.5), q(sorted, 0.9), q(sorted, 0.99),
                sorted.length == 0 ? 0 : sorted[sorted.length - 1], late, lateInGc,
                late > 0 ? 100 * lateInGc / late : 0, gcPauses, gcMax, lateInSafepoints,
                late > 0 ? 100 * lateInSafepoints / late : 0, stalledWithSteal, stalled, stolenInStalls);
        System.out.print(summary);
        File f = new File(out);
        if (f.getParentFile() != null) {
            Files.createDirectories(f.getParentFile().toPath());
        }
        Files.write(f.toPath(), summary.getBytes(StandardCharsets.UTF_8));
        System.out.println("written to " + f.getPath());
        System.exit(stalled == 0 && failed == 0 ? 0 : 1);
    }

    private static double q(double[] sorted, double p) {
        return sorted.length == 0 ? 0 : sorted[Math.max(0, (int) Math.ceil(p * sorted.length) - 1)];
    }

    private static Process startHog(String hog) throws IOException {
        List<String> cmd = new ArrayList<>(Arrays.asList("chrt", "-o", "0"));
        switch (hog) {
            case "none":
                return null;
            case "free":
                break;
            case "core0":
            case "core1":
                cmd.addAll(Arrays.asList("taskset", "-c", hog.substring(4)));
                break;
            default:
                throw new IllegalArgumentException("HapticStallStress: --hog must be none, free, core0 or core1, got "
                        + hog);
        }
        cmd.add("yes");
        return new ProcessBuilder(cmd).redirectOutput(ProcessBuilder.Redirect.DISCARD)
                .redirectError(ProcessBuilder.Redirect.DISCARD).start();
    }

    /** Runs one child and returns its RESULT line (or the last line it printed), null if it printed nothing. */
    private static String runOnce(List<String> cmd, long timeoutMs) throws IOException, InterruptedException {
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).start();
        String[] last = new String[1];
        Thread reader = new Thread(() -> {
            try (BufferedReader r = new BufferedReader(new InputStreamReader(p.getInputStream(),
                    StandardCharsets.UTF_8))) {
                for (String s; (s = r.readLine()) != null; ) {
                    if (s.startsWith("late tick") || s.startsWith("stalled tick") || s.startsWith("stall-")) {
                        System.out.println("  " + s);     // -Dtactus.stress.verbose=true in --jvm
                    }
                    if (last[0] == null || !last[0].startsWith("RESULT")) {
                        last[0] = s;
                    }
                }
            } catch (IOException ignored) {
                // the child was killed
            }
        });
        reader.start();
        if (!p.waitFor(timeoutMs, TimeUnit.MILLISECONDS)) {
            p.destroyForcibly();
            reader.join(2000);
            return "timed out after " + timeoutMs + " ms: " + last[0];
        }
        reader.join(2000);
        return last[0];
    }
}
