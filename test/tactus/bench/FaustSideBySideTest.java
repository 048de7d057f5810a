package tactus.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import tactus.PhysicalModel;
import tactus.faust.FaustToolchain;

/**
 * The harness of the side by side with Faust (no timing): every model builds and exports, the voices are counted,
 * its report section replaces only its own kept block, and a compiled program is reused while its source stays the
 * same and renders several voices in benchmark mode.
 */
@Timeout(value = 120, unit = TimeUnit.SECONDS)
class FaustSideBySideTest {

    @Test
    void everyModelBuildsAndExportsWithOneOutput() {
        for (String id : FaustSideBySide.MODELS) {
            PhysicalModel m = FaustSideBySide.model(id);
            assertTrue(m.matExists(FaustSideBySide.listened(id)), id + ": the listening mass exists");
            String dsp = FaustSideBySide.dsp(id.startsWith("voices") ? FaustSideBySide.voice(id) : id);
            assertTrue(dsp.contains("process"), id + ": a Faust program");
        }
        assertEquals(16, FaustSideBySide.voices("voices16-string1d-100"));
        assertEquals(8, FaustSideBySide.voices("voices8-string1d-100"));
        assertEquals(1, FaustSideBySide.voices("string3d-100"));
        assertEquals("string1d-100", FaustSideBySide.voice("voices8-string1d-100"));
        // issue #36's targets
        assertEquals(1, FaustSideBySide.target("string1d-30"), 0);
        assertEquals(2, FaustSideBySide.target("string1d-100"), 0);
        assertEquals(3, FaustSideBySide.target("string1d-300"), 0);
        assertEquals(3, FaustSideBySide.target("string3d-100"), 0);
        assertEquals(1, FaustSideBySide.target("plate-8x8"), 0);
        assertEquals(1, FaustSideBySide.target("voices16-string1d-100"), 0);
        // the per-element column's element counts: masses plus interactions, all voices
        assertEquals(30 + 2 + 31, FaustSideBySide.elements("string1d-30"));
        assertEquals(64 + 112, FaustSideBySide.elements("plate-8x8"));
        assertEquals(16 * (100 + 2 + 101), FaustSideBySide.elements("voices16-string1d-100"));
    }

    @Test
    void itsSectionReplacesOnlyItsOwnKeptBlock() {
        String tag = "<!-- side by side with Faust (gradle bench) -->";
        String paper = Bench.KEPT_BEGIN + "\n" + SideBySideReport.TAG + "\npaper\n" + Bench.KEPT_END + "\n";
        String report = "# title\n\n" + paper + "\n" + Bench.KEPT_BEGIN + "\n" + tag + "\nold\n" + Bench.KEPT_END + "\n\nafter\n";
        String next = SideBySideReport.replaceSection(report, Bench.KEPT_BEGIN + "\n" + tag + "\nnew\n" + Bench.KEPT_END + "\n",
                tag);
        assertTrue(next.contains("\nnew\n") && !next.contains("\nold\n"), next);
        assertTrue(next.contains(paper) && next.endsWith("\nafter\n"), next);
    }

    @Test
    void aCompiledProgramIsReusedAndRendersVoices(@TempDir Path dir) throws Exception {
        FaustToolchain.requireTools();
        Path[] exe = FaustSideBySide.compile("string1d-30", dir, 300);
        FileTime first = Files.getLastModifiedTime(exe[0]);
        Path[] again = FaustSideBySide.compile("string1d-30", dir, 300);
        assertEquals(first, Files.getLastModifiedTime(again[0]), "the same source is not compiled again");
        double[] one = FaustToolchain.benchmark(exe[0], 20_000, 1, 60);
        double[] four = FaustToolchain.benchmark(exe[1], 20_000, 4, 60);
        assertTrue(one[0] > 0 && one[1] >= 0 && four[0] > 0, "ns per sample: " + one[0] + ", " + four[0]);
    }
}
