package tactus.faust;

import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** A missing tool fails with a message that says what to install (the export tests never skip). */
class FaustToolchainTest {
    @Test
    void aMissingToolNamesWhatToInstall() {
        IllegalStateException e = assertThrows(IllegalStateException.class,
                () -> FaustToolchain.requireTools("tactus-no-such-faust"));
        assertTrue(e.getMessage().contains("apt-get install faust g++")
                && e.getMessage().contains("tactus-no-such-faust"), e.getMessage());
    }

    @Test
    void aHungProcessIsKilledAtItsTimeout() {
        long t0 = System.nanoTime();
        IllegalStateException e = assertThrows(IllegalStateException.class,
                () -> FaustToolchain.run(java.util.List.of("sleep", "30"), null, 1, null));
        assertTrue(e.getMessage().contains("did not finish within 1 s"), e.getMessage());
        assertTrue(System.nanoTime() - t0 < 20_000_000_000L, "bounded by its timeout");
    }
}
