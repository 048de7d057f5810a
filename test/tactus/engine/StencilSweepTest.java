package tactus.engine;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * Stencil runs stepped in one sweep, and chains that move their own masses ({@link StencilKernel#fused}), must
 * compute the same physics as the two-pass form ({@link Engine#setStencilSweeps(boolean) sweeps off}): masses
 * first, by their own kernels, then each run's near ends, then its far ends.
 *
 * <p>Inside a chain every mass receives exactly two link forces, and a sum of two terms does not depend on the
 * order of addition, so there both forms must agree bit for bit; chain lengths around the sweep's block size
 * (256) check the hand-over of masses and forces between blocks. Where a mass receives forces from several
 * kernels (a mesh's rows and columns) the sums are added in another order, so the two forms agree to round-off.
 */
class StencilSweepTest {

    /**
     * A plucked string of n masses of one kind between two Ground3D, joined by SpringDamper3D links (tension, some
     * damping), plucked in y and z.
     */
    private static Engine string(MassKind kind, int n, boolean sweeps) {
        Engine e = new Engine();
        e.setStencilSweeps(sweeps);
        int prev = e.addMass(MassKind.GROUND3D, 1, 0, 0, 0, 0, 0, 0);
        for (int i = 1; i <= n; i++) {
            double shape = Math.min(i, n + 1 - i) / (double) n;
            int m = e.addMass(kind, 1 + 0.1 * (i % 3), i * 0.1, 0.01 * shape, kind == MassKind.MASS2D_PLANE ? 0 : 0.02 * shape,
                    0, 0.0003 * Math.sin(i), 0);
            if (kind == MassKind.OSC3D) {
                e.setOscillator(m, 0.001, 0.0001);
            }
            e.addLink(LinkKind.SPRING_DAMPER3D, prev, m, 0.2 + 0.01 * (i % 5), 0.001, 0.05);
            prev = m;
        }
        int end = e.addMass(MassKind.GROUND3D, 1, (n + 1) * 0.1, 0, 0, 0, 0, 0);
        e.addLink(LinkKind.SPRING_DAMPER3D, prev, end, 0.2, 0.001, 0.05);
        return e;
    }

    /** @return the run kernels of the plan that move their own masses. */
    private static int fusedCount(Engine e) {
        int n = 0;
        for (Kernel k : e.plan().kernels()) {
            if (k instanceof StencilKernel && ((StencilKernel) k).masses() != null) {
                n++;
            }
        }
        return n;
    }

    private static void assertSameState(Engine a, Engine b, String what) {
        StepPlan pa = a.plan();
        StepPlan pb = b.plan();
        assertArrayEquals(pb.x, pa.x, what + ": x");
        assertArrayEquals(pb.y, pa.y, what + ": y");
        assertArrayEquals(pb.z, pa.z, what + ": z");
        assertArrayEquals(pb.fx, pa.fx, what + ": fx");
        assertArrayEquals(pb.fy, pa.fy, what + ": fy");
        assertArrayEquals(pb.fz, pa.fz, what + ": fz");
    }

    @Test
    void aChainThatMovesItsMassesIsBitIdenticalToTheTwoPassForm() {
        for (int n : new int[] {33, 255, 256, 257, 258, 511, 512, 513, 700}) {
            Engine sweep = string(MassKind.MASS2D_PLANE, n, true);
            Engine twoPass = string(MassKind.MASS2D_PLANE, n, false);
            assertEquals(1, sweep.stencilRunCount(), n + " masses: the string should be one run");
            assertEquals(1, fusedCount(sweep), n + " masses: the run should move its masses");
            assertEquals(0, fusedCount(twoPass));
            String[] names = sweep.plan().kernelNames();
            assertArrayEquals(new String[] {"Fixed", "Plane2D", "StencilKernel", "SpringDamper"}, names,
                    "every Mass2DPlane is in the run: no separate mass kernel, and the run reports both computations");
            for (int block = 0; block < 8; block++) {
                sweep.step(125);
                twoPass.step(125);
                assertSameState(sweep, twoPass, n + " masses after " + 125 * (block + 1) + " steps");
            }
            // and the string moves: the comparison is not between two resting states
            double[] p = new double[3];
            int i = n / 3;
            sweep.position(i, p);
            assertTrue(Math.abs(p[1] - 0.01 * Math.min(i, n + 1 - i) / n) > 1e-7, n + " masses: the string did not move");
        }
    }

    @Test
    void everyMassKindInAChainMatchesTheTwoPassForm() {
        for (MassKind kind : new MassKind[] {MassKind.MASS3D, MassKind.MASS3D_SIMPLE, MassKind.MASS1D, MassKind.OSC3D}) {
            for (boolean medium : new boolean[] {false, true}) {
                Engine sweep = string(kind, 300, true);
                Engine twoPass = string(kind, 300, false);
                if (medium) {
                    sweep.setGravity(0, 1e-7, -2e-7);
                    sweep.setFriction(1e-4);
                    twoPass.setGravity(0, 1e-7, -2e-7);
                    twoPass.setFriction(1e-4);
                }
                assertEquals(1, fusedCount(sweep), kind + ": the run should move its masses");
                sweep.step(1000);
                twoPass.step(1000);
                assertSameState(sweep, twoPass, kind + (medium ? " with gravity and friction" : ""));
            }
        }
    }

    /** The reduced plane and line kernels (no friction, no gravity) are the exact reduction of the general ones. */
    @Test
    void reducedPlaneAndLineKernelsAreExactReductions() {
        for (MassKind kind : new MassKind[] {MassKind.MASS2D_PLANE, MassKind.MASS1D}) {
            for (int n : new int[] {6, 300}) {
                Engine plain = string(kind, n, true);
                Engine general = string(kind, n, true);
                general.setFriction(1e-300); // 1 - f/M rounds to 1: the general kernel, with the same numbers
                plain.step(3000);
                general.step(3000);
                assertSameState(plain, general, kind + ", " + n + " masses");
            }
        }
    }

    @Test
    void aRunAcrossTwoMassKindsLeavesTheMassesToTheirKernels() {
        Engine e = new Engine();
        int prev = e.addMass(MassKind.GROUND3D, 1, 0, 0, 0, 0, 0, 0);
        for (int i = 1; i <= 80; i++) {
            // 40 Mass3D then 40 Mass3DSimple: their slots are adjacent, so the chain is one run over both kinds
            int m = e.addMass(i <= 40 ? MassKind.MASS3D : MassKind.MASS3D_SIMPLE, 1, i * 0.1, 0.001 * Math.sin(i), 0, 0, 0, 0);
            e.addLink(LinkKind.SPRING_DAMPER3D, prev, m, 0.2, 0.001, 0.05);
            prev = m;
        }
        assertEquals(1, e.stencilRunCount());
        assertEquals(0, fusedCount(e));
        Engine index = new Engine();
        index.setStencilRuns(false);
        prev = index.addMass(MassKind.GROUND3D, 1, 0, 0, 0, 0, 0, 0);
        for (int i = 1; i <= 80; i++) {
            int m = index.addMass(i <= 40 ? MassKind.MASS3D : MassKind.MASS3D_SIMPLE, 1, i * 0.1, 0.001 * Math.sin(i), 0, 0, 0, 0);
            index.addLink(LinkKind.SPRING_DAMPER3D, prev, m, 0.2, 0.001, 0.05);
            prev = m;
        }
        e.step(2000);
        index.step(2000);
        double[] a = new double[3];
        double[] b = new double[3];
        for (int id = 0; id < 81; id++) {
            e.position(id, a);
            index.position(id, b);
            for (int c = 0; c < 3; c++) {
                assertEquals(b[c], a[c], 1e-13, "mass " + id + " axis " + c);
            }
        }
    }

    /**
     * A Spring3D chain and a SpringDamper3D chain over the same masses are two runs on the same slots: only one
     * may move the masses (moving them twice would be a different scheme). Each mass now has four link forces,
     * summed in another order than in the two-pass form, so the states agree to round-off.
     */
    @Test
    void twoRunsOverTheSameMassesMoveThemOnce() {
        Engine[] engines = new Engine[2];
        for (int v = 0; v < 2; v++) {
            Engine e = new Engine();
            e.setStencilSweeps(v == 0);
            int prev = e.addMass(MassKind.GROUND3D, 1, 0, 0, 0, 0, 0, 0);
            for (int i = 1; i <= 100; i++) {
                int m = e.addMass(MassKind.MASS3D, 1, i * 0.1, 0.002 * Math.sin(0.1 * i), 0.001 * Math.cos(0.3 * i), 0, 0, 0);
                e.addLink(LinkKind.SPRING_DAMPER3D, prev, m, 0.2, 0.001, 0.05);
                e.addLink(LinkKind.SPRING3D, prev, m, 0.05, 0, 0.08);
                prev = m;
            }
            engines[v] = e;
        }
        assertEquals(2, engines[0].stencilRunCount());
        assertEquals(1, fusedCount(engines[0]));
        for (int block = 0; block < 10; block++) {
            engines[0].step(200);
            engines[1].step(200);
            StepPlan a = engines[0].plan();
            StepPlan b = engines[1].plan();
            for (int s = 0; s < a.nMass; s++) {
                assertEquals(b.x[s], a.x[s], 1e-13, "x of slot " + s);
                assertEquals(b.y[s], a.y[s], 1e-13, "y of slot " + s);
                assertEquals(b.z[s], a.z[s], 1e-13, "z of slot " + s);
            }
        }
        assertEquals(EnergyMeter.discreteEnergy(engines[1].plan()), EnergyMeter.discreteEnergy(engines[0].plan()), 1e-14);
    }

    /** A sheet: rows are runs that move their masses, columns are runs of offset W; forces come from both. */
    @Test
    void aSheetMatchesTheTwoPassFormToRoundOff() {
        Engine[] engines = new Engine[2];
        int w = 30;
        int h = 20;
        for (int v = 0; v < 2; v++) {
            Engine e = new Engine();
            e.setStencilSweeps(v == 0);
            e.setFriction(1e-5);
            int[] id = new int[w * h];
            for (int j = 0; j < h; j++) {
                for (int i = 0; i < w; i++) {
                    boolean edge = i == 0 || j == 0 || i == w - 1 || j == h - 1;
                    id[j * w + i] = e.addMass(edge ? MassKind.GROUND3D : MassKind.MASS3D, 1, i * 0.1, j * 0.1,
                            0.01 * Math.sin(0.4 * i) * Math.sin(0.3 * j), 0, 0, 0);
                }
            }
            // links between two fixed nodes are left out (as in the benchmark's sheets): with them, the fixed
            // top and bottom rows would join the rows' run, which would then span two mass kinds
            for (int j = 0; j < h; j++) {
                boolean fixedRow = j == 0 || j == h - 1;
                for (int i = 0; i < w; i++) {
                    boolean fixedColumn = i == 0 || i == w - 1;
                    if (i + 1 < w && !fixedRow) {
                        e.addLink(LinkKind.SPRING_DAMPER3D, id[j * w + i], id[j * w + i + 1], 0.2, 0.001, 0.09);
                    }
                    if (j + 1 < h && !fixedColumn) {
                        e.addLink(LinkKind.SPRING_DAMPER3D, id[j * w + i], id[(j + 1) * w + i], 0.2, 0.001, 0.09);
                    }
                }
            }
            engines[v] = e;
        }
        assertTrue(fusedCount(engines[0]) >= 1, "the rows should move their masses");
        for (int block = 0; block < 10; block++) {
            engines[0].step(300);
            engines[1].step(300);
            StepPlan a = engines[0].plan();
            StepPlan b = engines[1].plan();
            for (int s = 0; s < a.nMass; s++) {
                assertEquals(b.z[s], a.z[s], 1e-13, "z of slot " + s + " after " + 300 * (block + 1) + " steps");
                assertEquals(b.x[s], a.x[s], 1e-13, "x of slot " + s);
            }
        }
        assertEquals(EnergyMeter.discreteEnergy(engines[1].plan()), EnergyMeter.discreteEnergy(engines[0].plan()), 1e-14);
    }

    /**
     * On several threads a run that moves its masses is cut into stages (masses, near ends, far ends), each split
     * across the threads; the result must be bit-identical to the one-sweep form on one thread, for any batch size.
     */
    @Test
    void parallelStagesAreBitIdenticalToTheSweep() {
        for (int threads : new int[] {2, 3}) {
            Engine serial = string(MassKind.MASS2D_PLANE, 1500, true);
            Engine parallel = string(MassKind.MASS2D_PLANE, 1500, true);
            parallel.setThreads(threads);
            parallel.setParallelThreshold(0);
            try {
                assertNotNull(parallel.plan());
                assertEquals(1, fusedCount(parallel));
                int[] batches = {1, 2, 3, 5, 64, 199};
                for (int round = 0; round < 12; round++) {
                    int n = batches[round % batches.length];
                    assertEquals(serial.step(n), parallel.step(n));
                    assertSameState(parallel, serial, threads + " threads, round " + round);
                }
            } finally {
                parallel.close();
            }
        }
    }

    /**
     * Runs stepped in one sweep are used at any size; in the two-pass form only up to 16,384 masses (above that
     * index arrays were faster). Switching recompiles the plan and carries the state over: the string goes on
     * exactly where it was.
     */
    @Test
    void sweepsUseRunsAtAnySizeAndSwitchingKeepsTheState() {
        Engine e = string(MassKind.MASS2D_PLANE, StencilPlanner.MAX_MASSES + 100, true);
        assertEquals(1, e.stencilRunCount(), "with sweeps a long string is a run");
        e.step(50);
        double[] before = new double[3];
        double[] after = new double[3];
        int probe = 777;
        e.position(probe, before);
        e.setStencilSweeps(false);
        assertEquals(0, e.stencilRunCount(), "two-pass runs stop at 16,384 masses");
        e.position(probe, after);
        assertArrayEquals(before, after);
        Engine reference = string(MassKind.MASS2D_PLANE, StencilPlanner.MAX_MASSES + 100, true);
        reference.step(50);
        e.step(50);
        reference.step(50);
        e.position(probe, after);
        reference.position(probe, before);
        // index arrays add the same two forces per mass, so the string goes on bit for bit
        assertArrayEquals(before, after);
    }
}
