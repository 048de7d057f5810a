package tactus.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import tactus.PhysicalModel;
import tactus.Vect3D;
import tactus.engine.Engine;

/**
 * The benchmark harness works (no timing is asserted): a scene's child logic runs a few hundred steps, its result
 * line survives the round trip to the parent, the chain allocates nothing per step, and the hand-written reference
 * loop of the overhead scene computes the same motion as the engine.
 */
class BenchSmokeTest {

    @Test
    void chainChildLogicRunsAndAllocatesNothing() {
        Scenes.Scene scene = Scenes.byId("chain-470");
        assertNotNull(scene);
        Workload w = scene.variants.get(0).get();
        assertEquals(941, w.elements(), "470 masses + 471 links");
        ByteArrayOutputStream log = new ByteArrayOutputStream();
        List<Harness.Outcome> res = Harness.measure(Collections.singletonList(w), new double[] {0.0},
                Harness.Config.steps(300, 200, 3), new PrintStream(log, true), "[smoke]");
        assertEquals(1, res.size());
        Harness.Outcome o = res.get(0);
        assertEquals(3, o.nsPerElement.length);
        for (int r = 0; r < 3; r++) {
            assertTrue(o.nsPerElement[r] > 0 && Double.isFinite(o.nsPerElement[r]), "ns per element of run " + r);
            assertTrue(o.stepsPerSecond[r] > 0, "steps per second of run " + r);
        }
        // A real per-step allocation would show in every run; a one-off JIT event in at most one.
        double least = Harness.min(o.bytesPerStep);
        assertEquals(0.0, least, "bytes per step of the three runs: " + java.util.Arrays.toString(o.bytesPerStep));
        assertTrue(log.toString(StandardCharsets.UTF_8).contains("round 3 "), "progress lines are printed");

        String line = Bench.format(Bench.RESULT, Bench.resultMap(scene, o, "0.1 0.2 0.3"));
        assertTrue(line.startsWith(Bench.RESULT + "\t"));
        assertFalse(line.contains("\n"));
        Map<String, String> back = Bench.parse(line);
        assertEquals("chain-470", back.get("scene"));
        assertEquals("941", back.get("elements"));
        assertEquals(3, Bench.splitArray(back.get("ns")).length);
        assertEquals(o.nsPerElement[1], Bench.splitArray(back.get("ns"))[1], 1e-5 * o.nsPerElement[1]);
    }

    @Test
    void handLoopComputesTheSameMotionAsTheEngine() {
        int n = 40;
        HandChain arrays = new HandChain(n, false);
        HandChain constants = new HandChain(n, true);
        Engine on = Scenes.springChainEngine(n, true);
        Engine off = Scenes.springChainEngine(n, false);
        PhysicalModel pm = Scenes.chainModel(n, true);
        int steps = 400;
        arrays.advance(steps);
        constants.advance(steps);
        on.step(steps);
        off.step(steps);
        pm.computeNSteps(steps);
        double[] h = new double[3];
        double[] c = new double[3];
        double[] e = new double[3];
        double[] f = new double[3];
        Vect3D v = new Vect3D();
        double moved = 0;
        for (int i = 1; i <= n; i++) {
            arrays.position(i, h);
            constants.position(i, c);
            on.position(i, e);
            off.position(i, f);
            pm.getMatPosition("m" + i, v);
            double[] g = {v.x, v.y, v.z};
            double[] start = Scenes.chainNode(i, n);
            for (int k = 0; k < 3; k++) {
                moved = Math.max(moved, Math.abs(h[k] - start[k]));
                assertEquals(h[k], c[k], 1e-12, "constants vs arrays, mass " + i);
                assertEquals(h[k], e[k], 1e-12, "engine (stencil runs) vs hand loop, mass " + i);
                assertEquals(h[k], f[k], 1e-12, "engine (index arrays) vs hand loop, mass " + i);
                assertEquals(h[k], g[k], 1e-12, "PhysicalModel vs hand loop, mass " + i);
            }
        }
        assertTrue(moved > 1e-3, "the chain moved: " + moved);
    }

    @Test
    void kernelProfileAndSceneListWork() throws Exception {
        PhysicalModel pm = Scenes.chainModel(60, false);
        pm.computeNSteps(10);
        String prof = KernelProfiler.profile(pm, 0.0);
        assertTrue(prof.startsWith("step~0~"), prof);
        assertTrue(prof.contains("|guard~0~"), prof);
        List<String> unknown = new ArrayList<>();
        for (String id : Scenes.ids()) {
            if (Scenes.byId(id) == null) {
                unknown.add(id);
            }
        }
        assertTrue(unknown.isEmpty(), "scenes without a builder: " + unknown);
        assertEquals(5000, Scenes.marblePositions(5000).length);
    }
}
