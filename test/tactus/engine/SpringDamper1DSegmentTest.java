package tactus.engine;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * SpringDamper1D links that form a chain in batch order run as one loop per chain (a segment, see
 * {@link LinkKernels.SpringDamper1D}); with stencil sweeps off every link runs one by one. The two must agree bit
 * for bit, in positions, forces and the links' previous elongations, through parameter changes, moves by hand and
 * masses of both 1-D kinds, and wherever the chain meets links that are not in it (the ends, a plate's columns, a
 * reversed link, links of other kinds on the same masses).
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class SpringDamper1DSegmentTest {

    /** A struck 1-D string of n masses of a kind between two Ground1D, with varied parameters and rest lengths. */
    static Engine string(MassKind kind, int n, boolean sweeps, int[] ids) {
        return string(kind, n, sweeps, ids, false);
    }

    /** @param uniform true: every inner link with the same stiffness, damping and length (a uniform string) */
    private static Engine string(MassKind kind, int n, boolean sweeps, int[] ids, boolean uniform) {
        Engine e = new Engine();
        e.setStencilSweeps(sweeps);
        int g0 = e.addMass(MassKind.GROUND1D, 1, 0, 0, 0, 0, 0, 0);
        int prev = g0;
        for (int i = 1; i <= n; i++) {
            int m = e.addMass(kind, 1 + 0.1 * (i % 3), i, 0, 0.01 * Math.sin(i * 0.7), 0, 0, 0.0003 * Math.cos(i));
            if (kind == MassKind.OSC1D) {
                e.setOscillator(m, 0.001 * (1 + i % 4), 0.0001);
            }
            ids[i] = m;
            if (uniform) {
                e.addLink(LinkKind.SPRING_DAMPER1D, prev, m, 0.2, 0.0005, 0.001);
            } else {
                e.addLink(LinkKind.SPRING_DAMPER1D, prev, m, 0.2 + 0.01 * (i % 5), 0.0005 * (i % 3), 0.001 * (i % 2));
            }
            prev = m;
        }
        int g1 = e.addMass(MassKind.GROUND1D, 1, n + 1, 0, 0, 0, 0, 0);
        e.addLink(LinkKind.SPRING_DAMPER1D, prev, g1, 0.2, 0.0005, 0);
        return e;
    }

    private static int segments(Engine e) {
        int n = 0;
        for (Kernel k : e.plan().kernels()) {
            if (k instanceof LinkKernels.SpringDamper1D) {
                n += ((LinkKernels.SpringDamper1D) k).segments();
            }
        }
        return n;
    }

    private static void assertSame(Engine a, Engine b, String what) {
        StepPlan pa = a.plan();
        StepPlan pb = b.plan();
        assertArrayEquals(pb.z, pa.z, what + ": z");
        assertArrayEquals(pb.pz, pa.pz, what + ": previous z");
        assertArrayEquals(pb.fx, pa.fx, what + ": fx");
        assertArrayEquals(pb.fy, pa.fy, what + ": fy");
        assertArrayEquals(pb.fz, pa.fz, what + ": fz");
        LinkBatch ba = pa.batch(LinkKind.SPRING_DAMPER1D);
        LinkBatch bb = pb.batch(LinkKind.SPRING_DAMPER1D);
        assertArrayEquals(bb.dp, ba.dp, what + ": previous elongations");
    }

    /** Steps both engines in lockstep, comparing every step, with changes of parameters and positions on the way. */
    private static void lockstep(Engine seg, Engine ref, int[] ids, int n, String what) {
        for (int step = 0; step < 600; step++) {
            if (step == 100) {
                for (Engine e : new Engine[] {seg, ref}) {
                    for (int l = 0; l < e.linkIdCount(); l += 3) {
                        if (e.isLink(l)) {
                            e.setLinkParams(l, 0.31, 0.002, 0.0005);
                        }
                    }
                }
            }
            if (step == 250) {
                for (Engine e : new Engine[] {seg, ref}) {
                    e.setPosition(ids[n / 2], n / 2, 0, 0.05);
                }
            }
            seg.step(1);
            ref.step(1);
            assertSame(seg, ref, what + ", step " + step);
        }
    }

    @Test
    void aStringRunAsASegmentIsBitIdenticalToLinkByLink() {
        for (MassKind kind : new MassKind[] {MassKind.MASS1D, MassKind.OSC1D}) {
            for (int n : new int[] {9, 10, 30, 100, 257}) {
                int[] ids = new int[n + 1];
                Engine seg = string(kind, n, true, ids);
                Engine ref = string(kind, n, false, new int[n + 1]);
                seg.compile();
                ref.compile();
                assertEquals(1, segments(seg), kind + ", " + n + " masses: the inner links should be one segment");
                assertEquals(0, segments(ref), "sweeps off: no segment");
                lockstep(seg, ref, ids, n, kind + ", " + n + " masses");
                assertNotEquals(0.0, seg.plan().z[ids[n / 3]], "the string should move");
            }
        }
    }

    /**
     * A uniform string (its segment's parameters held as constants), made non-uniform by one link's change and
     * uniform again, then changed as a whole: the same bits as link by link at every step.
     */
    @Test
    void aUniformStringStaysBitIdenticalThroughParameterChanges() {
        for (int n : new int[] {9, 64, 300}) {
            int[] ids = new int[n + 1];
            Engine seg = string(MassKind.MASS1D, n, true, ids, true);
            Engine ref = string(MassKind.MASS1D, n, false, new int[n + 1], true);
            seg.compile();
            ref.compile();
            assertEquals(1, segments(seg));
            int link = n / 2; // an inner link (link ids follow the order they were added)
            for (int step = 0; step < 500; step++) {
                for (Engine e : new Engine[] {seg, ref}) {
                    if (step == 50) {
                        e.setLinkParams(link, 0.25, 0.0005, 0.001);
                    } else if (step == 150) {
                        e.setLinkParams(link, 0.2, 0.0005, 0.001);
                    } else if (step == 250) {
                        for (int l = 0; l < e.linkIdCount(); l++) {
                            e.setLinkParams(l, 0.15, 0.002, 0);
                        }
                    } else if (step == 350) {
                        e.setLinkParams(link, 0.15, 0.002, -0.0);
                    }
                }
                seg.step(1);
                ref.step(1);
                assertSame(seg, ref, "uniform string of " + n + ", step " + step);
            }
            assertNotEquals(0.0, seg.plan().z[0] - 0.01 * Math.sin(0.7), "the string should move");
        }
    }

    @Test
    void shortChainsStayLinkByLink() {
        int[] ids = new int[7];
        Engine e = string(MassKind.MASS1D, 6, true, ids);
        e.compile();
        assertEquals(0, segments(e), "5 inner links are fewer than MIN_SEGMENT (8)");
    }

    /**
     * A plate of Osc1D with right and down neighbours (rows are chains in batch order, columns are not), a link
     * added the other way round in the middle of a row, and Contact3D links on some of the same masses: segments
     * for the rows' stretches, everything else one by one, and the same bits.
     */
    @Test
    void aPlateWithReversedAndOtherLinksIsBitIdenticalToLinkByLink() {
        Engine seg = plate(true);
        Engine ref = plate(false);
        seg.compile();
        ref.compile();
        assertTrue(segments(seg) >= 8, "the rows' stretches should be segments, got " + segments(seg));
        assertEquals(0, segments(ref));
        for (int step = 0; step < 500; step++) {
            if (step == 200) {
                for (Engine e : new Engine[] {seg, ref}) {
                    e.setLinkParams(5, 0.4, 0.001, 0.002);
                }
            }
            seg.step(1);
            ref.step(1);
            assertSame(seg, ref, "plate, step " + step);
        }
    }

    /**
     * The Faust bench's plate (8 x 8 Osc1D, each tied to its right and lower neighbour, the two links of a mass one
     * after the other, so no segment), all links alike: stepped with the shared parameters as constants, the same
     * bits as link by link, through a change that makes one link different, back, and a change of all of them.
     */
    @Test
    void aUniformPlateRunsItsLinksWithConstantsAndTheSameBits() {
        Engine seg = uniformPlate(true);
        Engine ref = uniformPlate(false);
        seg.step(1);
        ref.step(1);
        assertTrue(uniformLinks(seg), "every link alike: constants");
        assertFalse(uniformLinks(ref), "sweeps off: the link-by-link reference");
        double z0 = seg.plan().z[27];
        for (int step = 0; step < 600; step++) {
            for (Engine e : new Engine[] {seg, ref}) {
                if (step == 100) {
                    e.setLinkParams(37, 0.2, 0.00002, 0);
                } else if (step == 200) {
                    e.setLinkParams(37, 0.15, 0.00002, 0);
                } else if (step == 300) {
                    for (int l = 0; l < e.linkIdCount(); l++) {
                        e.setLinkParams(l, 0.1, 0.0001, 0.0005);
                    }
                }
            }
            seg.step(1);
            ref.step(1);
            assertSame(seg, ref, "uniform plate, step " + step);
            boolean alike = step < 100 || step >= 200;
            assertEquals(alike, uniformLinks(seg), "constants exactly while every link is alike, step " + step);
        }
        assertNotEquals(z0, seg.plan().z[27], "the plate should move");
    }

    private static boolean uniformLinks(Engine e) {
        for (Kernel k : e.plan().kernels()) {
            if (k instanceof LinkKernels.SpringDamper1D) {
                return ((LinkKernels.SpringDamper1D) k).uniformLinks();
            }
        }
        throw new AssertionError("no SpringDamper1D kernel");
    }

    private static Engine uniformPlate(boolean sweeps) {
        int n = 8;
        Engine e = new Engine();
        e.setStencilSweeps(sweeps);
        int[][] id = new int[n][n];
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++) {
                double z = i == 2 && j == 2 ? 0.01 : 0;   // struck at p2_2
                id[i][j] = e.addMass(MassKind.OSC1D, 1, i, j, z, 0, 0, 0);
                e.setOscillator(id[i][j], 0.0005, 0);
            }
        }
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++) {
                if (i + 1 < n) {
                    e.addLink(LinkKind.SPRING_DAMPER1D, id[i][j], id[i + 1][j], 0.15, 0.00002, 0);
                }
                if (j + 1 < n) {
                    e.addLink(LinkKind.SPRING_DAMPER1D, id[i][j], id[i][j + 1], 0.15, 0.00002, 0);
                }
            }
        }
        return e;
    }

    private static Engine plate(boolean sweeps) {
        int w = 12;
        Engine e = new Engine();
        e.setStencilSweeps(sweeps);
        int[][] id = new int[w][w];
        for (int r = 0; r < w; r++) {
            for (int c = 0; c < w; c++) {
                id[r][c] = e.addMass(MassKind.OSC1D, 1, c, r, 0.001 * ((r * 7 + c * 3) % 5), 0, 0, 0);
                e.setOscillator(id[r][c], 0.01, 0.0001);
            }
        }
        for (int r = 0; r < w; r++) {
            for (int c = 0; c + 1 < w; c++) {
                if (r == 4 && c == 6) {
                    e.addLink(LinkKind.SPRING_DAMPER1D, id[r][c + 1], id[r][c], 0.2, 0.0005, 0.001); // reversed
                } else {
                    e.addLink(LinkKind.SPRING_DAMPER1D, id[r][c], id[r][c + 1], 0.2, 0.0005, 0);
                }
            }
            for (int c = 0; r + 1 < w && c < w; c++) {
                e.addLink(LinkKind.SPRING_DAMPER1D, id[r][c], id[r + 1][c], 0.2, 0.0005, 0);
            }
        }
        for (int c = 0; c < w; c += 3) {
            e.addLink(LinkKind.CONTACT3D, id[2][c], id[3][c], 0.5, 0.01, 0.001);
        }
        return e;
    }
}
