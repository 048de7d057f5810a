package tactus.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import org.junit.jupiter.api.Test;

/** A new benchmark report keeps the hand-written sections of the old one, markers included, and nothing else. */
class KeptSectionsTest {

    @Test
    void keepsEveryMarkedSectionAndNothingElse() throws Exception {
        File f = File.createTempFile("performance", ".md");
        try {
            String one = Bench.KEPT_BEGIN + "\n## Sweeps\n\n| a | b |\n" + Bench.KEPT_END;
            String two = Bench.KEPT_BEGIN + "\nsecond\n" + Bench.KEPT_END;
            String old = "# Report\n\ngenerated text\n" + one + "\nmore generated text\n" + two + "\ntrailer\n"
                    + Bench.KEPT_BEGIN + "\nunterminated";
            Files.write(f.toPath(), old.getBytes(StandardCharsets.UTF_8));
            assertEquals("\n" + one + "\n" + "\n" + two + "\n", Bench.keptSections(f));
        } finally {
            f.delete();
        }
    }

    @Test
    void aMissingReportKeepsNothing() {
        assertEquals("", Bench.keptSections(new File("/nonexistent/dir/performance.md")));
    }
}
