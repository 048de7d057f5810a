package tactus.stability;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import tactus.engine.Engine;
import tactus.engine.LinkKind;
import tactus.engine.MassKind;
import tactus.engine.StabilityAnalyzer;
import tactus.engine.StabilityReport;

/**
 * The analyser's verdict on large networks whose lambda max lies within 1e-4 of the bound 4, on both sides.
 * Their spectra are clustered at the top (a 10^4-mass chain's two largest eigenvalues differ by ~3e-7), where
 * Lanczos creeps towards lambda max: it used to stop when its estimate changed by less than 1e-6 between two
 * checks, and called a 5,000-mass chain with lambda max = 4.0000476 stable at 3.99999. Expected eigenvalues
 * come from the closed forms of the discrete Laplacian with fixed ends:
 * chain of N masses, lambda max = (K/M) 2 (1 - cos(pi N/(N+1)));
 * W x H membrane (one scalar network per coordinate, which is what the analyser bounds),
 * lambda max = (K/M) [2 (1 - cos(pi W/(W+1))) + 2 (1 - cos(pi H/(H+1)))].
 */
class LanczosNearBoundTest {

    private static double chainLambda(int n, double k) {
        return k * 2 * (1 - Math.cos(Math.PI * n / (n + 1)));
    }

    private static double membraneLambda(int w, int h, double k) {
        return k * (2 * (1 - Math.cos(Math.PI * w / (w + 1))) + 2 * (1 - Math.cos(Math.PI * h / (h + 1))));
    }

    /** N unit Mass1D between two Ground1D, SpringDamper1D of stiffness k (undamped, a linear network). */
    private static Engine chain(int n, double k) {
        Engine e = new Engine();
        int prev = e.addMass(MassKind.GROUND1D, 1, 0, 0, 0, 0, 0, 0);
        for (int i = 1; i <= n; i++) {
            int m = e.addMass(MassKind.MASS1D, 1, i, 0, 0, 0, 0, 0);
            e.addLink(LinkKind.SPRING_DAMPER1D, prev, m, k, 0, 0);
            prev = m;
        }
        int g = e.addMass(MassKind.GROUND1D, 1, n + 1, 0, 0, 0, 0, 0);
        e.addLink(LinkKind.SPRING_DAMPER1D, prev, g, k, 0, 0);
        return e;
    }

    /** W x H unit masses in the plane, each tied to its four neighbours, the border ones to grounds. */
    private static Engine membrane(int w, int h, double k) {
        Engine e = new Engine();
        int[][] id = new int[w + 2][h + 2];
        for (int i = 0; i < w + 2; i++) {
            for (int j = 0; j < h + 2; j++) {
                boolean border = i == 0 || j == 0 || i == w + 1 || j == h + 1;
                id[i][j] = border && (i == 0 || i == w + 1) && (j == 0 || j == h + 1) ? -1
                        : e.addMass(border ? MassKind.GROUND3D : MassKind.MASS3D, 1, i, j, 0, 0, 0, 0);
            }
        }
        for (int i = 1; i <= w; i++) {
            for (int j = 1; j <= h; j++) {
                e.addLink(LinkKind.SPRING3D, id[i][j], id[i + 1][j], k, 0, 1);
                e.addLink(LinkKind.SPRING3D, id[i][j], id[i][j + 1], k, 0, 1);
                if (i == 1) {
                    e.addLink(LinkKind.SPRING3D, id[0][j], id[i][j], k, 0, 1);
                }
                if (j == 1) {
                    e.addLink(LinkKind.SPRING3D, id[i][0], id[i][j], k, 0, 1);
                }
            }
        }
        return e;
    }

    private static void assertVerdict(Engine e, double lambda, String what) {
        StabilityReport r = StabilityAnalyzer.analyze(e.plan());
        String msg = what + ": lambda max " + lambda + ", analyser " + r;
        assertEquals(lambda < StabilityReport.LIMIT, r.isStable(), msg);
        assertTrue(r.lambda() >= lambda * (1 - 1e-12), "the estimate is an upper one: " + msg);
        assertTrue(r.lambda() <= r.gershgorinBound(), msg);
        assertTrue(r.lanczosResidual() >= 0 && r.lambda() - r.lanczosResidual() <= lambda * (1 + 1e-12),
                "the Ritz value never exceeds lambda max: " + msg);
    }

    // Was: reported 3.99999, "stable"; the model diverges.
    @Test
    void theReportedChainIsUnstable() {
        int n = 5000;
        double k = 1.000012;
        double lambda = chainLambda(n, k);
        assertEquals(4.0000476, lambda, 1e-7);
        Engine e = chain(n, k);
        assertVerdict(e, lambda, "chain 5000");
        // and it does diverge: displace the middle mass a little (along z, the 1D axis) and let it run; the top
        // mode grows by about 1 + sqrt(lambda - 4) = 1.0069 per step
        e.setPosition(n / 2, n / 2, 0, 1e-3);
        int ran = e.step(50_000);
        assertTrue(ran < 50_000, "the chain diverges");
        assertTrue(e.divergedMass() >= 0);
    }

    @Test
    void chainsWithinOneTenThousandthOfTheBound() {
        for (int n : new int[] {1000, 4000, 10_000}) {
            for (double delta : new double[] {-1e-4, -3e-5, 3e-5, 1e-4}) {
                double target = 4 + delta;
                double k = target / chainLambda(n, 1.0);
                double lambda = chainLambda(n, k);
                assertVerdict(chain(n, k), lambda, "chain " + n + ", lambda - 4 = " + delta);
            }
        }
    }

    @Test
    void membranesWithinOneTenThousandthOfTheBound() {
        int[][] sizes = {{32, 32}, {50, 90}, {100, 100}};
        for (int[] s : sizes) {
            for (double delta : new double[] {-1e-4, -3e-5, 3e-5, 1e-4}) {
                double k = (4 + delta) / membraneLambda(s[0], s[1], 1.0);
                double lambda = membraneLambda(s[0], s[1], k);
                assertVerdict(membrane(s[0], s[1], k), lambda,
                        "membrane " + s[0] + "x" + s[1] + ", lambda - 4 = " + delta);
            }
        }
    }
}
