package tactus.bench;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * The side-by-side section of {@code docs/performance.md}: µs per step of each scene on the paper's engine and on
 * Tactus, the paired ratio per round, the targets of issue #18 as verdicts, and what a reader costs. Pure: it only
 * formats what it is given (see {@link SideBySide} for the measuring).
 *
 * <p>Data: for each engine, a map from "scene/variant" to its rounds, each round the µs per step of the runs that
 * the round's child measured (the variants of a child are interleaved, so run i of two variants of one round are
 * paired). The paper engine's map is null when no {@code miPhysics.jar} was given: its column then says
 * "not compared".
 */
final class SideBySideReport {
    /** First line inside the kept block that holds this section: how the section is found again. */
    static final String TAG = "<!-- side by side with the paper's engine (gradle bench) -->";
    /** Cell text of the paper's engine when no jar was given. */
    static final String NOT_COMPARED = "not compared";

    /** One table row: a label, the paper engine's variant key and Tactus's variant key. */
    static final class Row {
        final String label;
        final String paperKey;
        final String tactusKey;

        Row(String label, String paperKey, String tactusKey) {
            this.label = label;
            this.paperKey = paperKey;
            this.tactusKey = tactusKey;
        }
    }

    /** The rows, in report order. */
    static final List<Row> ROWS = Arrays.asList(
            new Row("string, 470 masses, 44.1 kHz: one `computeStep()` and one `getMatPosAt()` per sample",
                    "string-470/audio", "string-470/audio"),
            new Row("string, 1,000 masses, `computeNSteps`", "string-1000/computeNSteps", "string-1000/computeNSteps"),
            new Row("mesh 100×100, gravity, grounded border, `computeStep()`", "mesh-100/plain", "mesh-100/plain"),
            new Row("mesh 100×100, with a reader at 60 frames per simulated second", "mesh-100/reader",
                    "mesh-100/reader"),
            new Row("200 marbles, one `Contact3D` per pair, `computeStep()`", "marbles-200/explicit",
                    "marbles-200/explicit"),
            new Row("200 marbles, one `Contact3D` per pair, with a reader at 60 frames per simulated second",
                    "marbles-200/explicit-reader", "marbles-200/explicit-reader"),
            new Row("200 marbles, contact group (Tactus only: the paper's engine has none, so its column is its one "
                    + "`Contact3D` per pair)", "marbles-200/explicit", "marbles-200/group"));

    /** Pairs (plain variant, reader variant) whose cost ratio is reported, with the model's description. */
    static final String[][] READER_PAIRS = {
        {"marbles-200/explicit", "marbles-200/explicit-reader", "200 marbles, one Contact3D per pair (1 kHz)"},
        {"mesh-100/plain", "mesh-100/reader", "mesh 100×100 (1 kHz)"},
    };

    private final Map<String, List<double[]>> paper;
    private final Map<String, List<double[]>> tactus;
    private final Map<String, String> elements;
    private final Map<String, String> problems;
    private Map<String, List<double[]>> paperCpu;
    private Map<String, List<double[]>> tactusCpu;

    /**
     * @param paper the paper engine's runs (null: not compared)
     * @param tactus Tactus's runs
     * @param elements "scene/variant" → element count text (masses + interactions as the engines count them)
     * @param problems "scene/variant" → a problem to show in the row (a failed child, non-finite positions)
     */
    SideBySideReport(Map<String, List<double[]>> paper, Map<String, List<double[]>> tactus, Map<String, String> elements,
            Map<String, String> problems) {
        this.paper = paper;
        this.tactus = tactus;
        this.elements = elements;
        this.problems = problems;
    }

    /**
     * Adds the stepping thread's CPU time / wall time of every run (same layout as the µs per step), shown per row so
     * that runs disturbed by other load can be told apart.
     *
     * @param paperShare the paper engine's shares (null: none)
     * @param tactusShare Tactus's shares
     * @return this report
     */
    SideBySideReport withCpu(Map<String, List<double[]>> paperShare, Map<String, List<double[]>> tactusShare) {
        this.paperCpu = paperShare;
        this.tactusCpu = tactusShare;
        return this;
    }

    /** Median CPU/wall share from which runs count as undisturbed. */
    static final double QUIET_SHARE = 0.9;

    /** @return the stepping thread's CPU µs per step of every run (wall µs x CPU/wall), or null */
    static Map<String, List<double[]>> cpuTimes(Map<String, List<double[]>> wall, Map<String, List<double[]>> share) {
        if (wall == null || share == null) {
            return null;
        }
        Map<String, List<double[]>> out = new java.util.LinkedHashMap<>();
        for (Map.Entry<String, List<double[]>> e : wall.entrySet()) {
            List<double[]> s = share.get(e.getKey());
            if (s == null) {
                continue;
            }
            List<double[]> rounds = new ArrayList<>();
            for (int r = 0; r < Math.min(s.size(), e.getValue().size()); r++) {
                double[] w = e.getValue().get(r);
                double[] c = new double[Math.min(w.length, s.get(r).length)];
                for (int i = 0; i < c.length; i++) {
                    c[i] = w[i] * s.get(r)[i];
                }
                rounds.add(c);
            }
            out.put(e.getKey(), rounds);
        }
        return out;
    }

    /** @return true when the key's runs had a median CPU/wall of at least {@link #QUIET_SHARE} (or none is known) */
    static boolean quiet(Map<String, List<double[]>> share, String key) {
        if (share == null || !share.containsKey(key)) {
            return true;
        }
        List<Double> all = new ArrayList<>();
        for (double[] round : share.get(key)) {
            for (double x : round) {
                all.add(x);
            }
        }
        return median(all.stream().mapToDouble(Double::doubleValue).toArray()) >= QUIET_SHARE;
    }

    private static String share(Map<String, List<double[]>> cpu, String key) {
        if (cpu == null || !cpu.containsKey(key)) {
            return "–";
        }
        List<Double> all = new ArrayList<>();
        for (double[] round : cpu.get(key)) {
            for (double x : round) {
                all.add(x);
            }
        }
        return f("%.0f%%", 100 * median(all.stream().mapToDouble(Double::doubleValue).toArray()));
    }

    // ==================================================================================== statistics

    static double median(double[] v) {
        if (v.length == 0) {
            return Double.NaN;
        }
        double[] s = v.clone();
        Arrays.sort(s);
        int n = s.length;
        return n % 2 == 1 ? s[n / 2] : 0.5 * (s[n / 2 - 1] + s[n / 2]);
    }

    static double min(double[] v) {
        return Arrays.stream(v).min().orElse(Double.NaN);
    }

    static double max(double[] v) {
        return Arrays.stream(v).max().orElse(Double.NaN);
    }

    /** @return the median of each round's runs (empty when the key is absent) */
    static double[] roundMedians(Map<String, List<double[]>> engine, String key) {
        if (engine == null || !engine.containsKey(key)) {
            return new double[0];
        }
        List<double[]> rounds = engine.get(key);
        double[] m = new double[rounds.size()];
        for (int r = 0; r < m.length; r++) {
            m[r] = median(rounds.get(r));
        }
        return m;
    }

    /** @return paper / Tactus per round (wall time), over the rounds both engines measured */
    double[] ratios(Row row) {
        return ratios(row, paper, tactus);
    }

    /** @return paper / Tactus per round of the given figures, over the rounds both engines measured */
    static double[] ratios(Row row, Map<String, List<double[]>> paperFigures, Map<String, List<double[]>> tactusFigures) {
        double[] p = roundMedians(paperFigures, row.paperKey);
        double[] t = roundMedians(tactusFigures, row.tactusKey);
        double[] r = new double[Math.min(p.length, t.length)];
        for (int i = 0; i < r.length; i++) {
            r[i] = p[i] / t[i];
        }
        return r;
    }

    /** @return with-reader / without-reader of every paired run (run i of each round), or empty */
    static double[] readerRatios(Map<String, List<double[]>> engine, String plainKey, String readerKey) {
        if (engine == null || !engine.containsKey(plainKey) || !engine.containsKey(readerKey)) {
            return new double[0];
        }
        List<double[]> plain = engine.get(plainKey);
        List<double[]> reader = engine.get(readerKey);
        List<Double> r = new ArrayList<>();
        for (int k = 0; k < Math.min(plain.size(), reader.size()); k++) {
            for (int i = 0; i < Math.min(plain.get(k).length, reader.get(k).length); i++) {
                r.add(reader.get(k)[i] / plain.get(k)[i]);
            }
        }
        return r.stream().mapToDouble(Double::doubleValue).toArray();
    }

    // ==================================================================================== verdicts

    /** One target of issue #18 and how it came out. */
    static final class Verdict {
        final String target;
        final String measured;
        final String verdict;

        Verdict(String target, String measured, String verdict) {
            this.target = target;
            this.measured = measured;
            this.verdict = verdict;
        }
    }

    private static final String CPU_BASIS = " (stepping thread's CPU time: the runs were disturbed by other load, "
            + "CPU/wall below 90 %)";

    private Verdict ratioTarget(String target, double min, Row... rows) {
        if (paper == null) {
            return new Verdict(target, NOT_COMPARED + " (no `-PmiPhysicsJar`)", NOT_COMPARED);
        }
        boolean quiet = true;
        for (Row row : rows) {
            quiet &= quiet(paperCpu, row.paperKey) && quiet(tactusCpu, row.tactusKey);
        }
        Map<String, List<double[]>> p = quiet ? paper : cpuTimes(paper, paperCpu);
        Map<String, List<double[]>> t = quiet ? tactus : cpuTimes(tactus, tactusCpu);
        StringBuilder measured = new StringBuilder();
        boolean met = true;
        for (Row row : rows) {
            double[] r = ratios(row, p, t);
            if (measured.length() > 0) {
                measured.append("; ");
            }
            String name = row.paperKey.substring(0, row.paperKey.indexOf('/'));
            if (r.length == 0) {
                measured.append(name).append(": not measured");
                return new Verdict(target, measured.toString(), "not measured");
            }
            measured.append(name).append(": ").append(f("%.2f×", median(r)));
            met &= median(r) >= min;
        }
        return new Verdict(target, measured + (quiet ? "" : CPU_BASIS), met ? "met" : "**not met**");
    }

    /** @return the targets of issue #18, judged on the medians of the paired ratios */
    List<Verdict> verdicts() {
        List<Verdict> v = new ArrayList<>();
        v.add(ratioTarget("200 marbles, one Contact3D per pair: ≥ 3.4× the paper's engine", 3.4, ROWS.get(4)));
        v.add(ratioTarget("strings: ≥ 4× the paper's engine", 4.0, ROWS.get(0), ROWS.get(1)));
        v.add(ratioTarget("mesh: ≥ 4× the paper's engine", 4.0, ROWS.get(2)));
        String plain = READER_PAIRS[0][0];
        String reading = READER_PAIRS[0][1];
        boolean quiet = quiet(tactusCpu, plain) && quiet(tactusCpu, reading);
        double[] r = readerRatios(quiet ? tactus : cpuTimes(tactus, tactusCpu), plain, reading);
        String target = "a snapshot reader at 60 fps adds ≤ 5 % to a 1 kHz model of 20,000 elements (200 marbles, "
                + "Tactus with reader / without, paired runs)";
        if (r.length == 0) {
            v.add(new Verdict(target, "not measured", "not measured"));
        } else {
            v.add(new Verdict(target, f("%+.1f %% (%+.1f to %+.1f %%)", 100 * (median(r) - 1), 100 * (min(r) - 1),
                    100 * (max(r) - 1)) + (quiet ? "" : CPU_BASIS), median(r) <= 1.05 ? "met" : "**not met**"));
        }
        return v;
    }

    // ==================================================================================== markdown

    private static String f(String fmt, Object... a) {
        return String.format(Locale.ROOT, fmt, a);
    }

    private static String us(double x) {
        return x >= 100 ? f("%.0f", x) : x >= 10 ? f("%.1f", x) : f("%.2f", x);
    }

    static String spreadUs(double[] v) {
        if (v.length == 0) {
            return "–";
        }
        return us(median(v)) + " (" + us(min(v)) + "–" + us(max(v)) + ")";
    }

    static String spreadRatio(double[] v) {
        if (v.length == 0) {
            return "–";
        }
        return f("**%.2f×** (%.2f–%.2f)", median(v), min(v), max(v));
    }

    /** @return the table of µs per step and ratios */
    String table() {
        StringBuilder sb = new StringBuilder();
        sb.append("| scene | elements | paper's engine, µs per step, median (min–max) | Tactus, µs per step, median "
                + "(min–max) | ratio paper / Tactus, median (min–max) | CPU/wall of the stepping thread, median (paper; Tactus) | "
                + "ratio in the stepping thread's CPU time |\n|---|---|---|---|---|---|---|\n");
        Map<String, List<double[]>> pc = cpuTimes(paper, paperCpu);
        Map<String, List<double[]>> tc = cpuTimes(tactus, tactusCpu);
        for (Row row : ROWS) {
            String p = paper == null ? NOT_COMPARED : spreadUs(roundMedians(paper, row.paperKey));
            String t = spreadUs(roundMedians(tactus, row.tactusKey));
            String r = paper == null ? NOT_COMPARED : spreadRatio(ratios(row));
            String problem = problems.getOrDefault(row.tactusKey, "");
            if (paper != null && problems.containsKey("paper:" + row.paperKey)) {
                problem += (problem.isEmpty() ? "" : "; ") + "paper's engine: " + problems.get("paper:" + row.paperKey);
            }
            sb.append("| ").append(row.label).append(problem.isEmpty() ? "" : " (" + problem + ")").append(" | ")
                    .append(elements.getOrDefault(row.tactusKey, "–")).append(" | ").append(p).append(" | ").append(t)
                    .append(" | ").append(r).append(" | ").append(paper == null ? NOT_COMPARED : share(paperCpu, row.paperKey))
                    .append("; ").append(share(tactusCpu, row.tactusKey)).append(" | ")
                    .append(paper == null ? NOT_COMPARED : pc == null || tc == null ? "–" : spreadRatio(ratios(row, pc, tc))
                            .replace("**", "")).append(" |\n");
        }
        return sb.toString();
    }

    /** @return the verdict table */
    String verdictTable() {
        StringBuilder sb = new StringBuilder("| target (issue #18) | measured (median of the paired ratios) | verdict |\n"
                + "|---|---|---|\n");
        for (Verdict v : verdicts()) {
            sb.append("| ").append(v.target).append(" | ").append(v.measured).append(" | ").append(v.verdict)
                    .append(" |\n");
        }
        return sb.toString();
    }

    /** @return what a reader adds, per engine */
    String readerTable() {
        StringBuilder sb = new StringBuilder("| model | Tactus: with reader / without, paired runs, median (min–max) | "
                + "Tactus, in the stepping thread's CPU time | paper's engine: with reader / without |\n"
                + "|---|---|---|---|\n");
        Map<String, List<double[]>> tc = cpuTimes(tactus, tactusCpu);
        for (String[] pair : READER_PAIRS) {
            sb.append("| ").append(pair[2]).append(" | ").append(spread3(readerRatios(tactus, pair[0], pair[1])))
                    .append(" | ").append(spread3(readerRatios(tc, pair[0], pair[1]))).append(" | ")
                    .append(paper == null ? NOT_COMPARED : spread3(readerRatios(paper, pair[0], pair[1]))).append(" |\n");
        }
        return sb.toString();
    }

    private static String spread3(double[] v) {
        return v.length == 0 ? "–" : f("%.3f (%.3f–%.3f)", median(v), min(v), max(v));
    }

    /**
     * @param header the lines above the tables (date, engines, machine, load)
     * @param method the method bullets
     * @return the whole section, in a kept block (markers included)
     */
    String section(String header, String method) {
        return Bench.KEPT_BEGIN + "\n" + TAG + "\n## Side by side with the paper's engine (issue #18)\n\n" + header
                + table() + "\n### Targets\n\n" + verdictTable() + "\n### What a reader costs\n\n" + readerTable() + "\n"
                + method + Bench.KEPT_END + "\n";
    }

    /**
     * Puts a section into a report: in place of the previous side-by-side block, else before the first level-2
     * heading or kept block, whichever comes first (else at the end).
     *
     * @param report the report's current text ("" when it does not exist)
     * @param section the new section, from {@link #section}
     * @return the new text
     */
    static String replaceSection(String report, String section) {
        return replaceSection(report, section, TAG);
    }

    /** As {@link #replaceSection(String, String)}, for the kept block that carries {@code marker}. */
    static String replaceSection(String report, String section, String marker) {
        int tag = report.indexOf(marker);
        if (tag >= 0) {
            int begin = report.lastIndexOf(Bench.KEPT_BEGIN, tag);
            int end = report.indexOf(Bench.KEPT_END, tag);
            if (begin >= 0 && end >= 0) {
                int after = end + Bench.KEPT_END.length();
                if (after < report.length() && report.charAt(after) == '\n') {
                    after++;
                }
                return report.substring(0, begin) + section + report.substring(after);
            }
        }
        int h2 = report.startsWith("## ") ? 0 : report.indexOf("\n## ");
        h2 = h2 > 0 ? h2 + 1 : h2;
        int kept = report.indexOf(Bench.KEPT_BEGIN);
        int at = h2 < 0 ? kept : kept < 0 ? h2 : Math.min(h2, kept);
        if (at < 0) {
            return report + (report.isEmpty() || report.endsWith("\n\n") ? "" : "\n") + section;
        }
        return report.substring(0, at) + section + "\n" + report.substring(at);
    }
}
