package tactus.bench;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** The side-by-side report's arithmetic, table and verdicts, on synthetic figures (nothing is timed). */
class SideBySideReportTest {

    /** Every variant of the report at µs per step {@code base}, three rounds of {@code runs}, scaled by round. */
    private static Map<String, List<double[]>> engine(double strings, double mesh, double marbles, double group,
            double reader) {
        Map<String, List<double[]>> m = new LinkedHashMap<>();
        put(m, "string-470/audio", strings);
        put(m, "string-1000/computeNSteps", 2 * strings);
        put(m, "mesh-100/plain", mesh);
        put(m, "mesh-100/reader", mesh * reader);
        put(m, "marbles-200/explicit", marbles);
        put(m, "marbles-200/explicit-reader", marbles * reader);
        put(m, "marbles-200/group", group);
        return m;
    }

    private static void put(Map<String, List<double[]>> m, String key, double us) {
        List<double[]> rounds = new ArrayList<>();
        for (double scale : new double[] {1.0, 1.1, 0.9}) {
            rounds.add(new double[] {us * scale, us * scale * 1.02, us * scale * 0.98});
        }
        m.put(key, rounds);
    }

    @Test
    void ratiosArePairedPerRoundAndTheirMedianIsReported() {
        Map<String, List<double[]>> paper = engine(10, 500, 200, 0, 1.2);
        Map<String, List<double[]>> tactus = engine(2.5, 100, 50, 2, 1.03);
        // a drift in one round of one engine only moves that round's ratio
        tactus.get("mesh-100/plain").set(1, new double[] {220, 220, 220});
        SideBySideReport r = new SideBySideReport(paper, tactus, new LinkedHashMap<>(), new LinkedHashMap<>());
        double[] mesh = r.ratios(SideBySideReport.ROWS.get(2));
        assertArrayEquals(new double[] {5.0, 550 / 220.0, 5.0}, mesh, 1e-9);
        assertEquals(5.0, SideBySideReport.median(mesh), 1e-9);
        assertEquals(4.0, SideBySideReport.median(r.ratios(SideBySideReport.ROWS.get(0))), 1e-9);
        assertEquals(100.0, SideBySideReport.median(r.ratios(SideBySideReport.ROWS.get(6))), 1e-9,
                "the group row compares with the paper's explicit contacts");
        String table = r.table();
        assertTrue(table.contains("**4.00×** (4.00–4.00)"), table);
        assertTrue(table.contains("**5.00×** (2.50–5.00)"), table);
        assertFalse(table.contains(SideBySideReport.NOT_COMPARED), table);
    }

    @Test
    void verdictsFollowTheThresholdsOfTheIssue() {
        SideBySideReport met = new SideBySideReport(engine(10, 500, 200, 0, 1.2), engine(2.5, 120, 58, 2, 1.04),
                new LinkedHashMap<>(), new LinkedHashMap<>());
        List<SideBySideReport.Verdict> v = met.verdicts();
        assertEquals(4, v.size());
        assertEquals("met", v.get(0).verdict, "marbles 200/58 = 3.45 ≥ 3.4");
        assertEquals("met", v.get(1).verdict, "strings 4.0 ≥ 4");
        assertEquals("met", v.get(2).verdict, "mesh 500/120 = 4.17 ≥ 4");
        assertEquals("met", v.get(3).verdict, "reader +4 % ≤ 5 %");
        SideBySideReport missed = new SideBySideReport(engine(10, 500, 200, 0, 1.2), engine(2.6, 130, 60, 2, 1.06),
                new LinkedHashMap<>(), new LinkedHashMap<>());
        for (SideBySideReport.Verdict x : missed.verdicts()) {
            assertEquals("**not met**", x.verdict, x.target + ": " + x.measured);
        }
        assertTrue(missed.verdicts().get(3).measured.startsWith("+6.0 %"), missed.verdicts().get(3).measured);
    }

    /** The same layout as the figures, every run at CPU/wall {@code share}. */
    private static Map<String, List<double[]>> shares(Map<String, List<double[]>> figures, double share) {
        Map<String, List<double[]>> m = new LinkedHashMap<>();
        for (Map.Entry<String, List<double[]>> e : figures.entrySet()) {
            List<double[]> rounds = new ArrayList<>();
            for (double[] r : e.getValue()) {
                double[] s = new double[r.length];
                Arrays.fill(s, share);
                rounds.add(s);
            }
            m.put(e.getKey(), rounds);
        }
        return m;
    }

    @Test
    void disturbedRunsAreJudgedOnTheSteppingThreadsCpuTime() {
        Map<String, List<double[]>> paper = engine(10, 500, 200, 0, 1.2);
        Map<String, List<double[]>> tactus = engine(2.5, 100, 50, 2, 1.20);
        // Tactus's plain runs were descheduled half of the time; its reader runs were not: in CPU time the reader
        // adds 4 % (CPU figures) where the wall figures say +20 %
        Map<String, List<double[]>> tShare = shares(tactus, 0.5);
        tShare.put("marbles-200/explicit-reader", shares(tactus, 0.5 * 1.04 / 1.20).get("marbles-200/explicit-reader"));
        SideBySideReport r = new SideBySideReport(paper, tactus, new LinkedHashMap<>(), new LinkedHashMap<>())
                .withCpu(shares(paper, 0.95), tShare);
        SideBySideReport.Verdict reader = r.verdicts().get(3);
        assertEquals("met", reader.verdict, reader.measured);
        assertTrue(reader.measured.startsWith("+4.0 %") && reader.measured.contains("CPU time"), reader.measured);
        // paper at 95 %, Tactus at 50 %: the mesh ratio 5.0 in wall time is 9.5 in CPU time
        SideBySideReport.Verdict mesh = r.verdicts().get(2);
        assertTrue(mesh.measured.startsWith("mesh-100: 9.50×"), mesh.measured);
        // quiet runs: judged on wall time, as measured
        SideBySideReport quiet = new SideBySideReport(paper, tactus, new LinkedHashMap<>(), new LinkedHashMap<>())
                .withCpu(shares(paper, 0.95), shares(tactus, 0.99));
        assertEquals("**not met**", quiet.verdicts().get(3).verdict, "wall time says +20 %");
        assertTrue(quiet.verdicts().get(2).measured.equals("mesh-100: 5.00×"), quiet.verdicts().get(2).measured);
        assertTrue(quiet.table().contains("| 95%; 99% | 4.80× (4.80–4.80) |"), quiet.table());
    }

    @Test
    void withoutTheJarThePaperColumnSaysNotCompared() {
        SideBySideReport r = new SideBySideReport(null, engine(2.5, 100, 50, 2, 1.03), new LinkedHashMap<>(),
                new LinkedHashMap<>());
        String table = r.table();
        for (String row : table.split("\n")) {
            if (row.startsWith("| ") && !row.startsWith("| scene")) {
                String[] cells = row.split(" \\| ");
                assertEquals(SideBySideReport.NOT_COMPARED, cells[2].trim(), "paper's column: " + row);
                assertTrue(cells[3].matches("[0-9.]+ \\([0-9.]+–[0-9.]+\\)"), "Tactus's column: " + row);
                assertEquals(SideBySideReport.NOT_COMPARED, cells[4].trim(), "ratio column: " + row);
            }
        }
        List<SideBySideReport.Verdict> v = r.verdicts();
        for (int i = 0; i < 3; i++) {
            assertEquals(SideBySideReport.NOT_COMPARED, v.get(i).verdict);
        }
        assertEquals("met", v.get(3).verdict, "the reader target needs Tactus only");
        assertTrue(r.readerTable().contains("1.030"), r.readerTable());
    }

    @Test
    void theSectionReplacesItselfAndSurvivesAStandardRewrite() throws Exception {
        SideBySideReport r = new SideBySideReport(null, engine(2.5, 100, 50, 2, 1.03), new LinkedHashMap<>(),
                new LinkedHashMap<>());
        String one = r.section("first\n", "method\n");
        String page = "# Tactus performance\n\nintro\n\n## Targets\n\ntext\n";
        String with = SideBySideReport.replaceSection(page, one);
        assertTrue(with.startsWith("# Tactus performance\n\nintro\n\n" + Bench.KEPT_BEGIN), with);
        assertTrue(with.endsWith(Bench.KEPT_END + "\n\n## Targets\n\ntext\n"), with);
        String two = r.section("second\n", "method\n");
        String again = SideBySideReport.replaceSection(with, two);
        assertEquals(with.replace(one, two), again);
        assertFalse(again.contains("first\n"));
        assertEquals(1, again.split(java.util.regex.Pattern.quote(SideBySideReport.TAG), -1).length - 1);
        assertEquals(one, SideBySideReport.replaceSection("", one));
        java.io.File f = java.io.File.createTempFile("performance", ".md");
        try {
            java.nio.file.Files.write(f.toPath(), again.getBytes(java.nio.charset.StandardCharsets.UTF_8));
            assertEquals("\n" + two.trim() + "\n", Bench.keptSections(f), "the standard bench keeps the section");
        } finally {
            f.delete();
        }
        String keptFirst = "# T\n\n" + Bench.KEPT_BEGIN + "\n## How to\n" + Bench.KEPT_END + "\n## Targets\n";
        assertEquals("# T\n\n" + one + "\n" + keptFirst.substring(5), SideBySideReport.replaceSection(keptFirst, one),
                "a new section goes before a kept block, never inside it");
    }

    @Test
    void thePaperCopyChangesTheImportLineOnly() {
        String src = "package p;\n\nimport tactus.*;\n\nclass A { String s = \"import tactus.*;\"; }\n";
        assertEquals(src.replace("\nimport tactus.*;\n", "\nimport miPhysics.*;\n"), SideBySide.paperSource(src));
        assertThrows(IllegalArgumentException.class, () -> SideBySide.paperSource("package p;\nclass A {}\n"));
        assertThrows(IllegalArgumentException.class,
                () -> SideBySide.paperSource("import tactus.*;\nimport tactus.*;\n"));
    }

    @Test
    void scenesSelectTheParts() {
        Bench.Selection all = new Bench.Selection(null);
        assertTrue(all.standard);
        assertEquals(Arrays.asList(tactus.bench.paper.PaperScenes.SCENES), all.paper);
        Bench.Selection paper = new Bench.Selection("paper");
        assertFalse(paper.standard);
        assertEquals(4, paper.paper.size());
        Bench.Selection some = new Bench.Selection("paper/mesh-100,chain-470");
        assertTrue(some.standard);
        assertEquals(Arrays.asList("chain-470"), some.only);
        assertEquals(Arrays.asList("mesh-100"), some.paper);
        assertThrows(IllegalArgumentException.class, () -> new Bench.Selection("paper/nothing"));
    }
}
