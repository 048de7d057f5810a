package tactus.engine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * The stencil planner must keep every link on its own two masses whatever the slot numbers: it used to pack
 * (offset, lower slot, link index) into 21-bit fields of one long and checked only the link count, so beyond
 * 2^21 masses a lower slot spilled into the offset field and a run connected the wrong masses.
 */
class StencilPlannerTest {

    /** A batch of two chains of {@code len} springs (offset 1): one at slots from {@code lowStart}, one from {@code highStart}. */
    private static LinkBatch twoChains(int lowStart, int highStart, int len) {
        LinkBatch b = new LinkBatch(LinkKind.SPRING_DAMPER3D, 2 * len);
        for (int i = 0; i < len; i++) {
            b.id[i] = i;
            b.a[i] = highStart + i;
            b.b[i] = highStart + i + 1;
            b.id[len + i] = len + i;
            b.a[len + i] = lowStart + i + 1; // reversed endpoints: the planner swaps them
            b.b[len + i] = lowStart + i;
        }
        return b;
    }

    private static void assertLinksKeepTheirMasses(LinkBatch in, LinkBatch out) {
        assertEquals(in.n, out.n);
        boolean[] seen = new boolean[in.n];
        for (int w = 0; w < out.n; w++) {
            int id = out.id[w];
            assertTrue(!seen[id], "link " + id + " appears twice");
            seen[id] = true;
            int lo = Math.min(in.a[id], in.b[id]);
            int hi = Math.max(in.a[id], in.b[id]);
            assertEquals(lo, Math.min(out.a[w], out.b[w]), "link " + id + " lower mass");
            assertEquals(hi, Math.max(out.a[w], out.b[w]), "link " + id + " upper mass");
        }
    }

    @Test
    void slotsBeyondTwoToTheTwentyOneKeepTheirLinks() {
        int len = 64;
        int high = (1 << 21) + 100; // the last mass is at 2^21 + 164, as in a 2^21 + 200-mass model
        LinkBatch in = twoChains(1000, high, len);
        LinkBatch out = StencilPlanner.organize(in);
        assertLinksKeepTheirMasses(in, out);
        assertEquals(2, out.runs.length, "both chains become runs");
        assertEquals(0, out.nIrregular);
        StencilRun upper = out.runs[0].s > out.runs[1].s ? out.runs[0] : out.runs[1];
        assertEquals(high, upper.s);
        assertEquals(high + len, upper.e);
        assertEquals(1, upper.o);
    }

    @Test
    void offsetsBeyondTwoToTheTwentyOneKeepTheirLinks() {
        // links between slot i and slot i + 2^21 + 7 (a mesh column of a very wide sheet)
        int len = 40;
        int o = (1 << 21) + 7;
        LinkBatch in = new LinkBatch(LinkKind.SPRING3D, len);
        for (int i = 0; i < len; i++) {
            in.id[i] = i;
            in.a[i] = 10 + i;
            in.b[i] = 10 + i + o;
        }
        LinkBatch out = StencilPlanner.organize(in);
        assertEquals(1, out.runs.length);
        assertEquals(o, out.runs[0].o);
        assertLinksKeepTheirMasses(in, out);
    }

    @Test
    void smallBatchesAreOrderedByOffsetThenSlotThenInsertion() {
        // a duplicated pair cannot sit in a run (a run holds one link per slot): irregular links keep insertion order
        LinkBatch in = twoChains(0, 200, 40);
        LinkBatch dup = new LinkBatch(LinkKind.SPRING3D, in.n + 2);
        for (int j = 0; j < in.n; j++) {
            dup.id[j] = j;
            dup.a[j] = in.a[j];
            dup.b[j] = in.b[j];
        }
        for (int j = in.n; j < in.n + 2; j++) {
            dup.id[j] = j;
            dup.a[j] = 205;
            dup.b[j] = 206;
        }
        LinkBatch out = StencilPlanner.organize(dup);
        assertLinksKeepTheirMasses(dup, out);
        assertTrue(out.nIrregular >= 2 && out.runs.length >= 1, out.nIrregular + " irregular");
        for (int w = 1; w < out.nIrregular; w++) {
            assertTrue(out.id[w - 1] < out.id[w], "irregular links in insertion order");
        }
        for (StencilRun r : out.runs) {
            assertEquals(1, r.o);
        }
    }

    // The end-to-end case of the issue: a model of 2^21 + 200 masses (the last 200 a chain of spring-dampers,
    // the rest free masses at rest, of the same kind so that the chain's slots come last) stepped on 2 threads, where the chain becomes a stencil run whose slots lie beyond
    // 2^21. Its 200 masses must move exactly like the same chain built alone (slots 0..199) on one thread. The
    // old planner connected the run to masses 2^21 lower and the chain stayed put. (About 1.2 GB of heap and a
    // few seconds: the mass table alone holds 2.1 million masses.)
    @Test
    void aChainBeyondTwoToTheTwentyOneMassesOnTwoThreadsMovesLikeTheSameChainAlone() {
        int n = (1 << 21) + 200;
        int first = n - 200;
        Engine big = new Engine();
        try {
            big.setThreads(2);
            big.setParallelThreshold(0);
            for (int i = 0; i < first; i++) {
                big.addMass(MassKind.MASS3D, 1, i, 0, 0, 0, 0, 0); // free masses at rest: nothing moves them
            }
            Engine alone = new Engine();
            for (int i = first; i < n; i++) {
                big.addMass(MassKind.MASS3D, 1, i, 0, 0.01 * Math.sin(i), 0, 0, 0);
                alone.addMass(MassKind.MASS3D, 1, i, 0, 0.01 * Math.sin(i), 0, 0, 0);
            }
            for (int i = 0; i < 199; i++) {
                big.addLink(LinkKind.SPRING_DAMPER3D, first + i, first + i + 1, 0.1, 0.001, 1);
                alone.addLink(LinkKind.SPRING_DAMPER3D, i, i + 1, 0.1, 0.001, 1);
            }
            assertEquals(10, big.step(10));
            alone.step(10);
            assertEquals(1, big.stencilRunCount(), "the chain is a stencil run");
            double[] p = new double[3];
            double[] q = new double[3];
            for (int i = 0; i < 200; i++) {
                big.position(first + i, p);
                alone.position(i, q);
                for (int c = 0; c < 3; c++) {
                    assertEquals(q[c], p[c], 1e-12, "mass " + (first + i) + " axis " + c);
                }
            }
        } finally {
            big.close();
        }
    }
}
