package tactus.engine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * Dense blocks of spring-damper links are stepped as stencil runs. The physics must be the same as with
 * index arrays (sums are added in another order, so round-off differs), coincident masses must stay
 * finite, and a topology change inside a run must leave the rest moving exactly like a model built
 * without the removed link.
 */
class StencilRunTest {

    /** A W x H sheet of Mass3D with horizontal, vertical and diagonal SpringDamper3D, fixed on two sides. */
    private static Engine sheet(int w, int h, boolean stencils, int skipLink) {
        Engine e = new Engine();
        e.setStencilRuns(stencils);
        int[] id = new int[w * h];
        for (int j = 0; j < h; j++) {
            for (int i = 0; i < w; i++) {
                double zz = 0.01 * Math.sin(0.7 * i) * Math.cos(0.3 * j);
                MassKind kind = (i == 0 || i == w - 1) ? MassKind.GROUND3D : MassKind.MASS3D;
                id[j * w + i] = e.addMass(kind, 1.0 + 0.01 * ((i * 7 + j * 3) % 5), i, j, zz, 0, 0, 0);
            }
        }
        int n = 0;
        for (int j = 0; j < h; j++) {
            for (int i = 0; i < w; i++) {
                int a = id[j * w + i];
                if (i + 1 < w && n++ != skipLink) {
                    e.addLink(LinkKind.SPRING_DAMPER3D, a, id[j * w + i + 1], 0.2, 0.003, 0.95);
                }
                if (j + 1 < h && n++ != skipLink) {
                    e.addLink(LinkKind.SPRING_DAMPER3D, a, id[(j + 1) * w + i], 0.15, 0.002, 1.0);
                }
                if (i + 1 < w && j + 1 < h && n++ != skipLink) {
                    e.addLink(LinkKind.SPRING3D, a, id[(j + 1) * w + i + 1], 0.05, 0, 1.4);
                }
            }
        }
        return e;
    }

    @Test
    void runsGiveTheSamePhysicsAsIndexArrays() {
        Engine runs = sheet(40, 12, true, -1);
        Engine plain = sheet(40, 12, false, -1);
        assertTrue(runs.stencilRunCount() >= 3, "the sheet should compile into stencil runs");
        assertEquals(0, plain.stencilRunCount());
        double[] a = new double[3];
        double[] b = new double[3];
        for (int step = 0; step < 20; step++) {
            runs.step(100);
            plain.step(100);
            for (int id = 0; id < 480; id++) {
                runs.position(id, a);
                plain.position(id, b);
                for (int c = 0; c < 3; c++) {
                    assertEquals(b[c], a[c], 1e-11 * (1 + Math.abs(b[c])), "mass " + id + " axis " + c);
                }
            }
        }
        assertEquals(EnergyMeter.discreteEnergy(plain.plan()), EnergyMeter.discreteEnergy(runs.plan()), 1e-12);
    }

    /**
     * A link inside a stencil run is removed from a running sheet, after {@code before} steps. The reference is
     * a sheet built without that link, given the running sheet's exact state at the removal point (positions,
     * previous positions, pending forces and every remaining link's damper history, copied bit for bit from the
     * plan as it was just before the removal). From there both must evolve bit-identically: the removal
     * recompiles the plan, which must carry every mass's state and every surviving link's history across, and
     * the surviving links form the same runs in the same order as in the sheet built without the link, so every
     * sum is added in the same order. The pending forces of the running sheet still contain the removed link's
     * last contribution (it was computed before the removal, and the scheme applies forces one step later);
     * copying them makes the reference apply it too.
     */
    @Test
    void removingALinkInsideARunMatchesAModelBuiltWithoutIt() {
        int[][] cases = {{517, 1}, {517, 250}, {40, 37}, {1000, 999}};   // {victim link id, steps before removal}
        for (int[] c : cases) {
            int victim = c[0];
            int before = c[1];
            Engine running = sheet(40, 12, true, -1);
            Engine fresh = sheet(40, 12, true, victim);
            running.step(before);
            StepPlan at = running.plan();
            LinkBatch batch = at.batches[LinkKind.SPRING_DAMPER3D.ordinal()];
            int j = indexOf(batch, victim);
            if (j < 0) {
                batch = at.batches[LinkKind.SPRING3D.ordinal()];
                j = indexOf(batch, victim);
            }
            assertTrue(j >= 0 && batch.runOf[j] >= 0, "link " + victim + " must lie inside a stencil run");
            copyState(at, victim, fresh.plan());
            running.removeLink(victim);
            assertTrue(running.stencilRunCount() >= 3, "the sheet still compiles into runs");
            double[] a = new double[3];
            double[] b = new double[3];
            for (int block = 0; block < 30; block++) {
                running.step(100);
                fresh.step(100);
                for (int id = 0; id < 480; id++) {
                    running.position(id, a);
                    fresh.position(id, b);
                    for (int k = 0; k < 3; k++) {
                        assertEquals(b[k], a[k], 0.0, "victim " + victim + " removed after " + before
                                + " steps: mass " + id + " axis " + k + " after " + (100 * (block + 1)) + " more");
                    }
                }
            }
            // and the removal changed something: the full sheet, stepped as long, is elsewhere
            Engine full = sheet(40, 12, true, -1);
            full.step(before + 3000);
            double moved = 0;
            for (int id = 0; id < 480; id++) {
                full.position(id, a);
                running.position(id, b);
                moved = Math.max(moved, Math.abs(a[2] - b[2]));
            }
            assertTrue(moved > 1e-6, "removing link " + victim + " made no difference: " + moved);
        }
    }

    private static int indexOf(LinkBatch b, int linkId) {
        if (b == null) {
            return -1;
        }
        for (int j = 0; j < b.n; j++) {
            if (b.id[j] == linkId) {
                return j;
            }
        }
        return -1;
    }

    /**
     * Copies the state of plan {@code from} into {@code to}, whose scene is the same without link {@code victim}
     * (so link ids above the victim are one lower in {@code to}). Mass ids are the same in both.
     */
    private static void copyState(StepPlan from, int victim, StepPlan to) {
        int[] slotOf = new int[480];
        for (int s = 0; s < from.nMass; s++) {
            slotOf[from.massId[s]] = s;
        }
        assertEquals(from.nMass, to.nMass);
        for (int s = 0; s < to.nMass; s++) {
            int f = slotOf[to.massId[s]];
            to.x[s] = from.x[f];
            to.y[s] = from.y[f];
            to.z[s] = from.z[f];
            to.px[s] = from.px[f];
            to.py[s] = from.py[f];
            to.pz[s] = from.pz[f];
            to.fx[s] = from.fx[f];
            to.fy[s] = from.fy[f];
            to.fz[s] = from.fz[f];
        }
        for (LinkKind kind : new LinkKind[] {LinkKind.SPRING_DAMPER3D, LinkKind.SPRING3D}) {
            LinkBatch src = from.batches[kind.ordinal()];
            LinkBatch dst = to.batches[kind.ordinal()];
            for (int j = 0; j < dst.n; j++) {
                int id = dst.id[j] >= victim ? dst.id[j] + 1 : dst.id[j];
                int o = indexOf(src, id);
                assertTrue(o >= 0, "link " + id);
                dst.setPrev(j, src.prev(o));
            }
        }
    }

    @Test
    void coincidentMassesInARunStayFinite() {
        Engine e = new Engine();
        int prev = e.addMass(MassKind.GROUND3D, 1, 0, 0, 0, 0, 0, 0);
        for (int i = 0; i < 64; i++) {
            // every other mass sits exactly on its predecessor, with a zero-length spring
            int m = e.addMass(MassKind.MASS3D, 1, (i + 1) / 2, 0, 0, 0, 0, 0);
            e.addLink(LinkKind.SPRING_DAMPER3D, prev, m, 0.1, 0.01, 0.0);
            prev = m;
        }
        assertTrue(e.stencilRunCount() >= 1);
        e.step(10_000);
        double[] p = new double[3];
        for (int id = 0; id < 65; id++) {
            e.position(id, p);
            assertTrue(Double.isFinite(p[0]) && Double.isFinite(p[1]) && Double.isFinite(p[2]), "mass " + id);
        }
        assertEquals(-1, e.divergedMass());
    }
}
