package tactus.sketch;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.TimeUnit;

import javax.imageio.ImageIO;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

import tactus.haptics.emulator.Hand3D;
import tactus.haptics.emulator.InverseServiceEmulator;
import tactus.haptics.emulator.SimulatedInverse3;

/**
 * A 2-D example, unchanged, on an Inverse3: the Inverse Service emulator runs in this JVM (a hand touring the
 * workspace in three dimensions), the sketch runs as in {@link ExamplesTest} with the service's address as a
 * system property, finds the Inverse3 first, and drives it in its vertical plane: the forces arrive at the
 * service, none along the free depth, and the scene moves with the hand.
 */
@Timeout(value = 5, unit = TimeUnit.MINUTES)
class TwoDExampleOnInverse3Test {

    @Test
    void heavyMassChainRunsUnchangedOnAnInverse3() throws Exception {
        SimulatedInverse3 device = new SimulatedInverse3();
        double[] h = SimulatedInverse3.HOME;
        double[] e = SimulatedInverse3.HALF_EXTENT;
        device.setHand(Hand3D.followingScript((t, out) -> {
            out[0] = h[0] + 0.5 * e[0] * Math.sin(2 * Math.PI * t / 3);
            out[1] = h[1] + 0.5 * e[1] * Math.sin(2 * Math.PI * t / 5);
            out[2] = h[2] + 0.5 * e[2] * Math.sin(2 * Math.PI * t / 2);
        }, 300, 3));
        try (InverseServiceEmulator service = InverseServiceEmulator.start(0, device)) {
            service.setRecording(true);
            Path dir = ExamplesTest.examplesRoot().resolve("Haptics/HeavyMassChain");
            if (!Files.isDirectory(dir)) {
                dir = Path.of("examples/Haptics/HeavyMassChain");
            }
            String classpath = SketchHarness.sketchClasspath();
            SketchHarness.requireXvfb();
            SketchHarness.JavaSketch sketch = SketchHarness.preprocess(dir);
            Path work = SketchHarness.workDir(sketch.className + "OnInverse3");
            Path classes = SketchHarness.compile(sketch, work, classpath);
            Path png = work.resolve("frame.png");
            SketchHarness.Run run = SketchHarness.run(sketch.className, classes, classpath, ExamplesTest.FRAMES, png,
                    ExamplesTest.TIMEOUT_SECONDS, dir, Map.of("tactus.haptics.inverse.uri", service.uri().toString()));
            SketchHarness.check(run, ExamplesTest.FRAMES);
            BufferedImage mid = ImageIO.read(SketchHarness.midFramePath(png).toFile());
            double changed = FrameAndSoundChecks.changedShare(mid, run.image, ExamplesTest.CHANGE_TOLERANCE);
            List<double[]> forces = service.receivedForces();
            long depth = forces.stream().filter(f -> f[1] != 0).count();
            long pushing = forces.stream().filter(f -> f[0] != 0 || f[2] != 0).count();
            String summary = String.format(Locale.ROOT, "%s on the emulated Inverse3: %d forces received, %d pushing, "
                    + "%d along the depth; %.1f %% of the pixels changed", sketch.className, forces.size(), pushing,
                    depth, 100 * changed);
            System.out.println(summary);
            assertTrue(forces.size() > 500, "the sketch drove the Inverse3: " + summary + "\n" + run.logs());
            assertTrue(pushing > 0, "the chain pushed back: " + summary);
            assertTrue(depth == 0, "the depth is free: " + summary);
            assertTrue(changed >= ExamplesTest.MIN_CHANGED_SHARE, "the scene moved with the hand: " + summary);
        }
    }
}
