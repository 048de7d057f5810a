package tactus.soak;

import java.io.PrintStream;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.atomic.AtomicLong;

/**
 * What a soak run found, counted by kind, with the first few occurrences of each distinct failure kept in full
 * (thread, call, stack) and tagged with the defect of issue 15 it most likely is ({@link DefectTags}). The three
 * failure families decide the exit status: escapes, hangs and NaN outputs. Everything else is a figure.
 */
final class SoakReport {
    /** Distinct failure records kept in full; later ones are only counted. */
    static final int MAX_RECORDS = 40;

    // ---- failures
    /** Exceptions that escaped a thread: uncaught anywhere, out of a reader call, or of an undocumented type. */
    final AtomicLong escapes = new AtomicLong();
    /** API calls that took over the hang limit, and stalls of the audio output or of the model's stepping. */
    final AtomicLong hangs = new AtomicLong();
    /** NaN or infinite values reaching an output: audio samples, motor torques. */
    final AtomicLong nanOutputs = new AtomicLong();

    // ---- figures
    final AtomicLong calls = new AtomicLong();
    final AtomicLong expectedRefusals = new AtomicLong();
    final AtomicLong draws = new AtomicLong();
    final AtomicLong audioBlocks = new AtomicLong();
    final AtomicLong lateBlocks = new AtomicLong();
    final AtomicLong audioSamples = new AtomicLong();
    final AtomicLong hapticTicks = new AtomicLong();
    final AtomicLong divergences = new AtomicLong();
    final AtomicLong listenerThrows = new AtomicLong();
    final AtomicLong nanForcesFromModel = new AtomicLong();
    final AtomicLong rebuilds = new AtomicLong();
    volatile long missedHapticTicks;
    volatile String hapticTelemetry = "";
    /** How the audio output thread was scheduled ({@code AudioScheduling.status()}). */
    volatile String audioScheduling = "";
    /** The first seconds of audio (class loading, JIT compilation, the real-time requests), counted apart, ns. */
    static final long WARM_UP_NANOS = 5_000_000_000L;
    /** Late blocks after {@link #WARM_UP_NANOS}, blocks within it, and the latest a block came (ns past due). */
    final AtomicLong lateBlocksAfterWarmUp = new AtomicLong();
    volatile long blocksInWarmUp;
    volatile long worstLateNanos;
    /** The real-time threads of the JVM at the end of the run (name and priority). */
    volatile String realtimeThreads = "";
    volatile long modelSteps;

    private final Map<String, Long> refusalsByType = new LinkedHashMap<>();
    private final Map<String, Long> failureKinds = new LinkedHashMap<>();
    private final List<String> records = new ArrayList<>();
    private final PrintStream out;

    SoakReport(PrintStream out) {
        this.out = out;
    }

    /** A documented refusal (IllegalArgumentException, IllegalStateException) of a call on the caller's thread. */
    synchronized void refused(Throwable t) {
        expectedRefusals.incrementAndGet();
        refusalsByType.merge(t.getClass().getSimpleName(), 1L, Long::sum);
    }

    /** An exception that escaped: printed at once the first time its kind is seen. */
    void escape(String where, Throwable t) {
        escapes.incrementAndGet();
        record("ESCAPE", where, t.toString(), stack(t));
    }

    /** A call or a thread that stopped for longer than the limit; {@code stack} is where it was, or null. */
    void hang(String where, String what, StackTraceElement[] stack) {
        hangs.incrementAndGet();
        record("HANG", where, what, stack == null ? "" : stack(stack));
    }

    /** A non-finite value reached an output. */
    void nan(String where, String what) {
        nanOutputs.incrementAndGet();
        record("NAN", where, what, "");
    }

    private synchronized void record(String family, String where, String what, String stack) {
        String defect = DefectTags.tag(family, where + "\n" + what, stack);
        // numbers (indices, ids, steps, positions) are left out of the kind, so that one defect is one line
        String kind = family + " " + where + ": " + firstLine(what).replaceAll("[-0-9.E]*[0-9][-0-9.E]*", "#")
                + " [" + defect + "]";
        Long seen = failureKinds.merge(kind, 1L, Long::sum);
        if (seen == 1 && records.size() < MAX_RECORDS) {
            String full = family + " " + where + ": " + firstLine(what) + " [" + defect + "]"
                    + (stack.isEmpty() ? "" : "\n" + stack);
            records.add(full);
            out.println("soak: " + full);
            out.flush();
        }
    }

    /** @return true when the run must exit with a non-zero status. */
    boolean failed() {
        return escapes.get() > 0 || hangs.get() > 0 || nanOutputs.get() > 0;
    }

    /** One progress line. */
    String progress(double seconds) {
        return String.format(Locale.ROOT, "soak t=%.0f s: %d escapes, %d hangs, %d NaN outputs | %d calls (%d refused), "
                + "%d draws, %d audio blocks (%d late), %d model steps, %d haptic ticks (%d missed), %d divergences, "
                + "%d rebuilds", seconds, escapes.get(), hangs.get(), nanOutputs.get(), calls.get(),
                expectedRefusals.get(), draws.get(), audioBlocks.get(), lateBlocks.get(), modelSteps,
                hapticTicks.get(), missedHapticTicks, divergences.get(), rebuilds.get());
    }

    /** The final summary: the figures, each failure kind with its count, and the machine-readable last line. */
    synchronized String summary(double seconds, long seed) {
        StringBuilder sb = new StringBuilder();
        sb.append(String.format(Locale.ROOT, "soak finished: %.1f s, seed %d%n", seconds, seed));
        sb.append(progress(seconds)).append('\n');
        sb.append("  documented refusals by type: ").append(refusalsByType).append('\n');
        sb.append("  listener throws (on purpose): ").append(listenerThrows.get())
          .append(", NaN forces handed to the haptic loop by the model: ").append(nanForcesFromModel.get()).append('\n');
        sb.append("  haptic telemetry: ").append(hapticTelemetry).append('\n');
        sb.append("  audio output thread: ").append(audioScheduling).append('\n');
        long blocks = audioBlocks.get();
        long afterBlocks = blocks - blocksInWarmUp;
        sb.append(String.format(Locale.ROOT, "  late blocks: %d of %d (%.3f %%); after the first %d s: %d of %d "
                + "(%.3f %%); the latest came %.1f ms past due%n", lateBlocks.get(), blocks,
                100.0 * lateBlocks.get() / Math.max(1, blocks), WARM_UP_NANOS / 1_000_000_000L,
                lateBlocksAfterWarmUp.get(), afterBlocks, 100.0 * lateBlocksAfterWarmUp.get() / Math.max(1, afterBlocks),
                worstLateNanos * 1e-6));
        sb.append("  real-time threads at the end: ").append(realtimeThreads).append('\n');
        if (failureKinds.isEmpty()) {
            sb.append("  no failure\n");
        } else {
            sb.append("  failures by kind (count):\n");
            failureKinds.forEach((k, n) -> sb.append("    ").append(n).append(" x ").append(k).append('\n'));
        }
        sb.append(String.format(Locale.ROOT, "SOAK RESULT escapes=%d hangs=%d nan=%d lateBlocks=%d missedTicks=%d "
                + "lateAfterWarmUp=%d calls=%d audioBlocks=%d modelSteps=%d hapticTicks=%d seconds=%.1f", escapes.get(),
                hangs.get(), nanOutputs.get(), lateBlocks.get(), missedHapticTicks, lateBlocksAfterWarmUp.get(), calls.get(), audioBlocks.get(), modelSteps,
                hapticTicks.get(), seconds));
        return sb.toString();
    }

    private static String firstLine(String s) {
        int nl = s.indexOf('\n');
        String line = nl < 0 ? s : s.substring(0, nl);
        return line.length() > 300 ? line.substring(0, 300) + "..." : line;
    }

    static String stack(Throwable t) {
        StringWriter w = new StringWriter();
        t.printStackTrace(new PrintWriter(w));
        return trim(w.toString());
    }

    static String stack(StackTraceElement[] frames) {
        StringBuilder sb = new StringBuilder();
        for (StackTraceElement e : frames) {
            sb.append("\tat ").append(e).append('\n');
        }
        return trim(sb.toString());
    }

    private static String trim(String s) {
        String[] lines = s.split("\n");
        StringBuilder sb = new StringBuilder();
        for (int i = 0; i < lines.length && i < 25; i++) {
            sb.append("      ").append(lines[i]).append('\n');
        }
        if (lines.length > 25) {
            sb.append("      ... ").append(lines.length - 25).append(" more lines\n");
        }
        return sb.toString();
    }
}
