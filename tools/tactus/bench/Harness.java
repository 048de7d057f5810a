package tactus.bench;

import java.io.PrintStream;
import java.lang.management.ManagementFactory;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;

/**
 * The measuring loop of a child JVM. For the workloads of one scene:
 * <ol>
 *   <li>warm-up, each workload in turn: advance in growing chunks until at least {@link Config#warmupSeconds}
 *       and {@link Config#warmupMinSteps} (or {@link Config#warmupMaxSeconds} at most); the rate of the last
 *       chunks sizes the measured runs to about {@link Config#runSeconds} each;</li>
 *   <li>rounds; in each round every workload does one measured run, the order rotating from round to round, so
 *       that variants compared with each other see the same machine load. A round in which some run got less than
 *       {@link Config#minCpuShare} of CPU time over wall time (the thread was descheduled: other load) is
 *       disturbed and repeated, until {@link Config#runs} undisturbed rounds or {@link Config#maxRounds} rounds;
 *       the first {@code runs} undisturbed rounds are kept (if there are too few, the least disturbed);</li>
 *   <li>per run: wall time (System.nanoTime), this thread's CPU time, and this thread's allocated bytes
 *       (com.sun.management.ThreadMXBean) around one {@link Workload#advance(int)} call, the counter's own
 *       cost (two back-to-back reads) subtracted.</li>
 * </ol>
 */
final class Harness {
    private static volatile double sink;

    private Harness() {
    }

    /** How long to warm up and measure. */
    static final class Config {
        double warmupSeconds = 2.0;
        long warmupMinSteps = 10_000;
        double warmupMaxSeconds = 6.0;
        int runs = 7;
        double runSeconds = 0.6;
        /** If &gt; 0: exactly this many warm-up steps (no timing), for tests. */
        long fixedWarmupSteps;
        /** If &gt; 0: exactly this many steps per measured run, for tests. */
        int fixedRunSteps;
        /** Seconds of per-kernel profiling after the runs (0: none). */
        double profileSeconds = 0.5;
        /**
         * A round counts as undisturbed when every run in it got at least this share of CPU time over wall time;
         * disturbed rounds are repeated, up to {@link #maxRounds} in all.
         */
        double minCpuShare = 0.9;
        /** Most rounds measured to collect {@link #runs} undisturbed ones. */
        int maxRounds = 14;

        static Config full() {
            return new Config();
        }

        static Config quick() {
            Config c = new Config();
            c.warmupSeconds = 0.5;
            c.warmupMinSteps = 1000;
            c.warmupMaxSeconds = 2.0;
            c.runs = 5;
            c.maxRounds = 8;
            c.runSeconds = 0.2;
            c.profileSeconds = 0.2;
            return c;
        }

        /** Fixed step counts and no profiling: for the smoke test. */
        static Config steps(long warmup, int perRun, int runs) {
            Config c = new Config();
            c.fixedWarmupSteps = warmup;
            c.fixedRunSteps = perRun;
            c.runs = runs;
            c.maxRounds = runs;
            c.minCpuShare = 0;
            c.profileSeconds = 0;
            return c;
        }
    }

    /** The measurements of one workload. */
    static final class Outcome {
        String variant;
        long elements;
        double buildSeconds;
        double warmupSeconds;
        long warmupSteps;
        int stepsPerRun;
        /** Per run: wall ns per element update, steps per second, bytes allocated per step, CPU time / wall time. */
        double[] nsPerElement;
        double[] stepsPerSecond;
        double[] bytesPerStep;
        double[] cpuShare;
        /** Bytes allocated in each kept run (after subtracting the counter's own cost). */
        long[] bytesRun;
        /** Total bytes allocated over the kept runs. */
        long bytesTotal;
        /** Rounds measured, and the CPU/wall share of this variant's run in every one of them (kept or not). */
        int roundsMeasured;
        double[] cpuAll;
        double probe;
        String profile = "";
        String extra = "";
    }

    private static com.sun.management.ThreadMXBean mx() {
        return (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
    }

    /**
     * Measures the workloads (already built) interleaved.
     *
     * @param buildSeconds build time of each workload, carried into the outcomes
     * @param log where progress goes (one line per phase and per run)
     * @param tag prefix of the progress lines, for example {@code "[chain-470 | JDK 17]"}
     */
    static List<Outcome> measure(List<Workload> ws, double[] buildSeconds, Config c, PrintStream log, String tag) {
        com.sun.management.ThreadMXBean mx = mx();
        if (!mx.isThreadAllocatedMemoryEnabled()) {
            mx.setThreadAllocatedMemoryEnabled(true);
        }
        if (!mx.isThreadCpuTimeEnabled()) {
            mx.setThreadCpuTimeEnabled(true);
        }
        long tid = Thread.currentThread().getId();
        int nw = ws.size();
        List<Outcome> out = new ArrayList<>();
        for (int w = 0; w < nw; w++) {
            Outcome o = new Outcome();
            o.variant = ws.get(w).variant();
            o.elements = ws.get(w).elements();
            o.buildSeconds = buildSeconds[w];
            out.add(o);
        }
        // 1. warm-up
        for (int w = 0; w < nw; w++) {
            Workload wl = ws.get(w);
            Outcome o = out.get(w);
            if (c.fixedWarmupSteps > 0) {
                long t0 = System.nanoTime();
                long left = c.fixedWarmupSteps;
                while (left > 0) {
                    int n = (int) Math.min(left, 1 << 20);
                    wl.advance(n);
                    left -= n;
                }
                o.warmupSteps = c.fixedWarmupSteps;
                o.warmupSeconds = (System.nanoTime() - t0) * 1e-9;
                o.stepsPerRun = c.fixedRunSteps;
            } else {
                long t0 = System.nanoTime();
                long steps = 0;
                int chunk = 1;
                double rate = 0;
                double[] recent = new double[5];
                int nRecent = 0;
                while (true) {
                    long a = System.nanoTime();
                    wl.advance(chunk);
                    long b = System.nanoTime();
                    steps += chunk;
                    double dt = (b - a) * 1e-9;
                    recent[nRecent++ % recent.length] = chunk / Math.max(dt, 1e-9);
                    rate = median(Arrays.copyOf(recent, Math.min(nRecent, recent.length)));
                    double elapsed = (b - t0) * 1e-9;
                    if (elapsed >= c.warmupMaxSeconds
                            || (elapsed >= c.warmupSeconds && steps >= c.warmupMinSteps)) {
                        break;
                    }
                    // grow chunks to about 50 ms of work, never past the warm-up's end by much
                    double target = Math.min(0.05, Math.max(0.001, c.warmupSeconds - elapsed));
                    double last = recent[(nRecent - 1) % recent.length];
                    chunk = (int) Math.max(1, Math.min(Integer.MAX_VALUE / 2, Math.min(2.0 * chunk, last * target)));
                }
                o.warmupSteps = steps;
                o.warmupSeconds = (System.nanoTime() - t0) * 1e-9;
                o.stepsPerRun = (int) Math.max(1, Math.min(Integer.MAX_VALUE / 2, rate * c.runSeconds));
            }
            double p = wl.probe();
            sink += p;
            log.println(String.format(Locale.ROOT, "%s %s: warm-up %.2f s, %d steps; %d steps per run",
                    tag, o.variant, o.warmupSeconds, o.warmupSteps, o.stepsPerRun));
        }
        // 2. measured runs, interleaved; disturbed rounds are repeated (up to maxRounds)
        int maxRounds = Math.max(c.runs, c.maxRounds);
        double[][] ns = new double[nw][maxRounds];
        double[][] sps = new double[nw][maxRounds];
        double[][] bps = new double[nw][maxRounds];
        double[][] cpu = new double[nw][maxRounds];
        long[][] bytesRun = new long[nw][maxRounds];
        double[] worst = new double[maxRounds];
        int rounds = 0;
        int clean = 0;
        while (rounds < maxRounds && clean < c.runs) {
            int r = rounds;
            StringBuilder line = new StringBuilder();
            line.append(String.format(Locale.ROOT, "%s round %d (%d/%d undisturbed so far):", tag, r + 1, clean, c.runs));
            worst[r] = Double.POSITIVE_INFINITY;
            for (int q = 0; q < nw; q++) {
                int w = (q + r) % nw;
                Workload wl = ws.get(w);
                Outcome o = out.get(w);
                int steps = o.stepsPerRun;
                long c0 = mx.getCurrentThreadCpuTime();
                long b0 = mx.getThreadAllocatedBytes(tid);
                long b1 = mx.getThreadAllocatedBytes(tid);
                long a0 = mx.getThreadAllocatedBytes(tid);
                long t0 = System.nanoTime();
                wl.advance(steps);
                long t1 = System.nanoTime();
                long a1 = mx.getThreadAllocatedBytes(tid);
                long c1 = mx.getCurrentThreadCpuTime();
                long bytes = Math.max(0, (a1 - a0) - (b1 - b0));
                double wall = t1 - t0;
                ns[w][r] = wall / ((double) steps * o.elements);
                sps[w][r] = steps / (wall * 1e-9);
                bps[w][r] = (double) bytes / steps;
                cpu[w][r] = (c1 - c0) / wall;
                bytesRun[w][r] = bytes;
                worst[r] = Math.min(worst[r], cpu[w][r]);
            }
            for (int w = 0; w < nw; w++) {
                Outcome o = out.get(w);
                line.append(String.format(Locale.ROOT, "  %s %.3f ns/el, %.3g steps/s, %d B, cpu %.0f%%;",
                        o.variant, ns[w][r], sps[w][r], bytesRun[w][r], 100 * cpu[w][r]));
            }
            if (worst[r] >= c.minCpuShare) {
                clean++;
            } else {
                line.append(" disturbed, repeated");
            }
            log.println(line);
            rounds++;
        }
        // keep the first `runs` undisturbed rounds; if there are too few, the `runs` least disturbed ones
        Integer[] order = new Integer[rounds];
        for (int r = 0; r < rounds; r++) {
            order[r] = r;
        }
        final double threshold = c.minCpuShare;
        Arrays.sort(order, (a, b) -> {
            boolean ca = worst[a] >= threshold, cb = worst[b] >= threshold;
            if (ca != cb) {
                return ca ? -1 : 1;
            }
            return ca ? Integer.compare(a, b) : Double.compare(worst[b], worst[a]);
        });
        int keep = Math.min(c.runs, rounds);
        int[] kept = new int[keep];
        for (int i = 0; i < keep; i++) {
            kept[i] = order[i];
        }
        Arrays.sort(kept);
        if (clean < c.runs) {
            log.println(String.format(Locale.ROOT, "%s only %d of %d rounds undisturbed (CPU/wall >= %.0f%%); "
                    + "keeping the %d least disturbed", tag, clean, rounds, 100 * c.minCpuShare, keep));
        }
        for (int w = 0; w < nw; w++) {
            Outcome o = out.get(w);
            o.nsPerElement = pick(ns[w], kept);
            o.stepsPerSecond = pick(sps[w], kept);
            o.bytesPerStep = pick(bps[w], kept);
            o.cpuShare = pick(cpu[w], kept);
            o.bytesRun = new long[keep];
            for (int i = 0; i < keep; i++) {
                o.bytesRun[i] = bytesRun[w][kept[i]];
                o.bytesTotal += o.bytesRun[i];
            }
            o.roundsMeasured = rounds;
            o.cpuAll = Arrays.copyOf(cpu[w], rounds);
        }
        for (int w = 0; w < nw; w++) {
            Workload wl = ws.get(w);
            Outcome o = out.get(w);
            o.probe = wl.probe();
            if (!Double.isFinite(o.probe)) {
                throw new IllegalStateException(o.variant + ": the state is not finite after the runs");
            }
            if (c.profileSeconds > 0 && wl.model() != null) {
                try {
                    o.profile = KernelProfiler.profile(wl.model(), c.profileSeconds);
                } catch (ReflectiveOperationException | RuntimeException e) {
                    o.profile = "";
                    log.println(tag + " " + o.variant + ": per-kernel profile unavailable (" + e + ")");
                }
            }
            if (wl instanceof Scenes.MarblesWorkload) {
                Scenes.MarblesWorkload mw = (Scenes.MarblesWorkload) wl;
                double[] eg = mw.engaged();
                o.extra = String.format(Locale.ROOT, "engaged=%.2f;minZ=%.3f;stirrer=%.2f", eg[0], eg[1],
                        mw.stirrerSpeed());
            }
        }
        return out;
    }

    private static double[] pick(double[] v, int[] idx) {
        double[] out = new double[idx.length];
        for (int i = 0; i < idx.length; i++) {
            out[i] = v[idx[i]];
        }
        return out;
    }

    // ============================================================================================ statistics

    static double median(double[] v) {
        double[] s = v.clone();
        Arrays.sort(s);
        int n = s.length;
        if (n == 0) {
            return Double.NaN;
        }
        return (n & 1) == 1 ? s[n / 2] : 0.5 * (s[n / 2 - 1] + s[n / 2]);
    }

    static double min(double[] v) {
        double m = Double.POSITIVE_INFINITY;
        for (double d : v) {
            m = Math.min(m, d);
        }
        return m;
    }

    static double max(double[] v) {
        double m = Double.NEGATIVE_INFINITY;
        for (double d : v) {
            m = Math.max(m, d);
        }
        return m;
    }
}
