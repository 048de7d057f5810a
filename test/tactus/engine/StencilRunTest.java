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

    @Test
    void removingALinkInsideARunMatchesAModelBuiltWithoutIt() {
        int victim = 517;
        Engine running = sheet(40, 12, true, -1);
        Engine fresh = sheet(40, 12, true, victim);
        // The link ids of 'running' are in insertion order; link 'victim' is the one 'fresh' never had.
        running.removeLink(victim);
        double[] a = new double[3];
        double[] b = new double[3];
        for (int step = 0; step < 3000; step++) {
            running.step();
            fresh.step();
        }
        for (int id = 0; id < 480; id++) {
            running.position(id, a);
            fresh.position(id, b);
            for (int c = 0; c < 3; c++) {
                assertEquals(b[c], a[c], 0.0, "mass " + id + " axis " + c);
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
