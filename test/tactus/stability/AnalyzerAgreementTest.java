package tactus.stability;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.SplittableRandom;
import org.junit.jupiter.api.DisplayName;
import org.junit.jupiter.api.Test;
import tactus.engine.Engine;
import tactus.engine.LinkKind;
import tactus.engine.MassKind;
import tactus.engine.StabilityAnalyzer;
import tactus.engine.StabilityReport;
import tactus.engine.PlanAccess;
import tactus.engine.StepPlan;

/**
 * The analyser's verdict against what the scheme actually does, on a seeded random sweep of 10,000 small
 * mass-spring-damper networks (2 to 40 masses) plus 500 pre-tensioned 3D membranes reported apart.
 *
 * <h2>Networks</h2>
 * Five families the analyser models exactly (its per-coordinate scalar network is the linearised dynamics):
 * <ul>
 *   <li>chain1D: Mass1D chains of SpringDamper1D, fixed at one or both ends;</li>
 *   <li>mesh2D: a x b grids of Mass1D (one degree of freedom each, like a membrane), most border masses tied to
 *       ground;</li>
 *   <li>graph1D: random connected graphs of Mass1D and Osc1D (30%), 1 to n/3 ground links, air friction in a
 *       quarter of the cases;</li>
 *   <li>graph3D: random graphs of Mass3D and Osc3D with zero-length Spring3D (exactly linear in 3D), oscillator
 *       damping and friction;</li>
 *   <li>string3D: strings of Mass3D on SpringDamper3D under tension (rest length half the spacing), radial
 *       damping, perturbed by 1e-9 around their exact equilibrium (linearised dynamics).</li>
 * </ul>
 * Masses are equal, mildly mixed (0.3..3) or widely mixed (0.01..100, a 10^4 ratio); damping is absent,
 * proportional (Z = zeta K), independent per link (non-proportional), or heavy (zeta 0.5..5). Stiffness and
 * damping are then scaled together (the analyser's lambda is homogeneous in them) to a target lambda drawn
 * uniformly in [2, 6] for 80% of the cases and in [3.96, 4.04] (within 1% of the bound) for 20%.
 * A sixth family, membrane3D (pre-tensioned 2D meshes of Mass2DPlane on SpringDamper3D), is one where the
 * analyser is only an upper bound by design: it counts a 3D spring's full K in every coordinate, while the
 * transverse stiffness under tension is K (1 - l0/d) = K/2 here. It is reported apart and only checked to be
 * on the safe side.
 *
 * <h2>Ground truth</h2>
 * From a random perturbation (every mass displaced and moving, oscillators moving), the compiled plan is
 * stepped without the divergence guard and the mass-weighted norm sqrt(sum M (|x - x_eq|² + |x - x_prev|²)) is
 * sampled every 3 steps. The network is unstable when that norm exceeds 1e6 times its initial value within
 * 8192 steps. When it has not, the growth rate is estimated by a least-squares fit of log(max norm) over the
 * last 16 windows of 256 steps; if it is above 1e-5 per step (a slow grower, or a slowly decaying mode close to
 * the bound), the run is extended to 65,536 steps and the same 1e6 criterion decides. A linear scheme whose
 * spectral radius is 1 + g exceeds 1e6 within 65,536 steps iff g > 2e-4 (roughly), which undamped networks
 * reach for lambda > 4 (1 + 1e-8) and damped ones for lambda > 4 (1 + 5e-5 zeta); closer to the bound the ground
 * truth itself is "stable for all practical purposes".
 */
class AnalyzerAgreementTest {
    private static final String[] FAMILIES = {"chain1D", "mesh2D", "graph1D", "graph3D", "string3D", "membrane3D"};
    private static final int LINEAR_FAMILIES = 5;
    private static final int CASES = 10_000;
    private static final int MEMBRANES = 500;
    private static final long SEED = 20240603L;

    /** One generated network, before scaling. */
    private static final class Net {
        int family;
        int n;
        MassKind[] kind;
        double[] m;
        double[] oscK;
        double[] oscZ;
        List<int[]> edges = new ArrayList<>();     // {a, b}; b = -1: to ground (or to the far ground, see ground2)
        List<Double> k = new ArrayList<>();
        List<Double> z = new ArrayList<>();
        boolean threeD;
        boolean tension;
        boolean plane;
        double friction;
        double[][] eq;        // equilibrium positions
        double[][] ground;    // per edge: ground position when b = -1
        double restLength;
        LinkKind linkKind;
    }

    private static double logUniform(SplittableRandom r, double a, double b) {
        return a * Math.exp(r.nextDouble() * Math.log(b / a));
    }

    private static Net generate(int family, SplittableRandom r) {
        Net net = new Net();
        net.family = family;
        int massMode = r.nextInt(3);
        int dampMode = r.nextInt(4);
        boolean osc = false;
        int n;
        List<int[]> e = net.edges;
        switch (family) {
            case 0: {
                n = 2 + r.nextInt(39);
                for (int i = 0; i + 1 < n; i++) {
                    e.add(new int[] {i, i + 1});
                }
                e.add(new int[] {0, -1});
                if (r.nextDouble() < 0.7) {
                    e.add(new int[] {n - 1, -1});
                }
                break;
            }
            case 1: {
                int a = 2 + r.nextInt(5);
                int b = 2 + r.nextInt(40 / a - 1);
                n = a * b;
                for (int i = 0; i < a; i++) {
                    for (int j = 0; j < b; j++) {
                        int id = i * b + j;
                        if (j + 1 < b) {
                            e.add(new int[] {id, id + 1});
                        }
                        if (i + 1 < a) {
                            e.add(new int[] {id, id + b});
                        }
                        boolean border = i == 0 || j == 0 || i == a - 1 || j == b - 1;
                        if (border && r.nextDouble() < 0.8) {
                            e.add(new int[] {id, -1});
                        }
                    }
                }
                if (e.stream().noneMatch(x -> x[1] < 0)) {
                    e.add(new int[] {0, -1});
                }
                break;
            }
            case 2:
            case 3: {
                n = family == 2 ? 2 + r.nextInt(39) : 2 + r.nextInt(19);
                for (int i = 1; i < n; i++) {
                    e.add(new int[] {r.nextInt(i), i});
                }
                int extra = r.nextInt(n + 1);
                for (int x = 0; x < extra; x++) {
                    int a = r.nextInt(n), b = r.nextInt(n);
                    if (a != b) {
                        e.add(new int[] {a, b});
                    }
                }
                int grounds = family == 2 ? 1 + r.nextInt(Math.max(1, n / 3)) : 1;
                for (int x = 0; x < grounds; x++) {
                    e.add(new int[] {r.nextInt(n), -1});
                }
                osc = true;
                net.threeD = family == 3;
                break;
            }
            case 4: {
                n = 2 + r.nextInt(29);
                for (int i = 0; i + 1 < n; i++) {
                    e.add(new int[] {i, i + 1});
                }
                e.add(new int[] {0, -1});
                e.add(new int[] {n - 1, -2});
                net.threeD = true;
                net.tension = true;
                break;
            }
            default: {
                int a = 2 + r.nextInt(4);
                int b = 2 + r.nextInt(4);
                n = a * b;
                net.plane = true;
                net.threeD = true;
                net.tension = true;
                // grid masses at (i+1, j+1); ground ring at 0 and a+1 / b+1
                net.ground = new double[0][];
                List<double[]> g = new ArrayList<>();
                for (int i = 0; i < a; i++) {
                    for (int j = 0; j < b; j++) {
                        int id = i * b + j;
                        if (j + 1 < b) {
                            e.add(new int[] {id, id + 1});
                        }
                        if (i + 1 < a) {
                            e.add(new int[] {id, id + b});
                        }
                    }
                }
                for (int i = 0; i < a; i++) {
                    e.add(new int[] {i * b, -1});
                    g.add(new double[] {i + 1, 0, 0});
                    e.add(new int[] {i * b + b - 1, -1});
                    g.add(new double[] {i + 1, b + 1, 0});
                }
                for (int j = 0; j < b; j++) {
                    e.add(new int[] {j, -1});
                    g.add(new double[] {0, j + 1, 0});
                    e.add(new int[] {(a - 1) * b + j, -1});
                    g.add(new double[] {a + 1, j + 1, 0});
                }
                net.ground = g.toArray(new double[0][]);
                net.eq = new double[n][];
                for (int i = 0; i < a; i++) {
                    for (int j = 0; j < b; j++) {
                        net.eq[i * b + j] = new double[] {i + 1, j + 1, 0};
                    }
                }
                break;
            }
        }
        net.n = n;
        net.kind = new MassKind[n];
        net.m = new double[n];
        net.oscK = new double[n];
        net.oscZ = new double[n];
        double zeta = dampMode == 1 ? logUniform(r, 0.01, 1) : dampMode == 3 ? logUniform(r, 0.5, 5) : 0;
        for (int i = 0; i < n; i++) {
            net.m[i] = massMode == 0 ? 1 : massMode == 1 ? logUniform(r, 0.3, 3) : logUniform(r, 0.01, 100);
            boolean isOsc = osc && r.nextDouble() < 0.3;
            net.kind[i] = net.plane ? MassKind.MASS2D_PLANE : net.threeD
                    ? (isOsc ? MassKind.OSC3D : MassKind.MASS3D) : (isOsc ? MassKind.OSC1D : MassKind.MASS1D);
            if (isOsc) {
                net.oscK[i] = logUniform(r, 0.1, 1) * net.m[i];
                net.oscZ[i] = dampMode == 0 ? 0 : dampMode == 2 ? logUniform(r, 0.001, 1) * net.m[i]
                        : zeta * net.oscK[i];
            }
        }
        boolean uniformK = net.tension || r.nextBoolean();
        for (int[] edge : e) {
            double mRef = edge[1] >= 0 ? Math.sqrt(net.m[edge[0]] * net.m[edge[1]]) : net.m[edge[0]];
            double kk = net.plane ? 1 : (uniformK ? 1 : logUniform(r, 0.2, 1)) * mRef;
            double zz = dampMode == 0 ? 0 : dampMode == 2 ? (r.nextDouble() < 0.5 ? logUniform(r, 0.001, 1) * mRef : 0)
                    : zeta * kk;
            net.k.add(kk);
            net.z.add(family == 3 ? 0 : zz); // zero-length Spring3D has no damper: graph3D damps through Osc3D
        }
        net.friction = r.nextDouble() < 0.25 ? logUniform(r, 1e-4, 0.1) : 0;
        net.linkKind = net.threeD ? (family == 3 ? LinkKind.SPRING3D : LinkKind.SPRING_DAMPER3D) : LinkKind.SPRING_DAMPER1D;
        net.restLength = net.tension ? 0.5 : 0;
        if (family == 4) {
            // series string between grounds at x = 0 and x = n + 1: equal tension T, spring j stretched to l0 + T/K_j
            double inv = 0;
            for (double kk : net.k) {
                inv += 1 / kk;
            }
            double tension = (n + 1) * (1 - net.restLength) / inv;
            net.eq = new double[n][];
            double x = net.restLength + tension / net.k.get(n - 1); // edge n-1 is the ground link of mass 0
            for (int i = 0; i < n; i++) {
                if (i > 0) {
                    x += net.restLength + tension / net.k.get(i - 1);
                }
                net.eq[i] = new double[] {x, 0, 0};
            }
        }
        if (net.eq == null) {
            net.eq = new double[n][3];
        }
        return net;
    }

    /** Builds the network with every stiffness and damping scaled by s, perturbed from equilibrium. */
    private static Engine build(Net net, double s, long seed, int[] ids) {
        SplittableRandom r = new SplittableRandom(seed);
        Engine e = new Engine();
        if (net.friction > 0) {
            e.setFriction(net.friction * s);
        }
        double amp = net.tension ? 1e-9 : 1;
        for (int i = 0; i < net.n; i++) {
            double[] q = net.eq[i];
            boolean isOsc = net.kind[i].isOscillator();
            double dx = isOsc ? 0 : amp * (2 * r.nextDouble() - 1);
            double dy = isOsc ? 0 : amp * (2 * r.nextDouble() - 1);
            double dz = isOsc || net.plane ? 0 : amp * (2 * r.nextDouble() - 1);
            ids[i] = e.addMass(net.kind[i], net.m[i], q[0] + dx, q[1] + dy, q[2] + dz, amp * (2 * r.nextDouble() - 1),
                    amp * (2 * r.nextDouble() - 1), amp * (2 * r.nextDouble() - 1));
            if (isOsc) {
                e.setOscillator(ids[i], net.oscK[i] * s, net.oscZ[i] * s);
            }
        }
        MassKind groundKind = net.threeD ? MassKind.GROUND3D : MassKind.GROUND1D;
        int origin = e.addMass(groundKind, 1, 0, 0, 0, 0, 0, 0);
        int far = net.family == 4 ? e.addMass(groundKind, 1, net.n + 1, 0, 0, 0, 0, 0) : origin;
        int groundIndex = 0;
        for (int j = 0; j < net.edges.size(); j++) {
            int[] edge = net.edges.get(j);
            int a = ids[edge[0]];
            int b;
            if (edge[1] >= 0) {
                b = ids[edge[1]];
            } else if (edge[1] == -2) {
                b = far;
            } else if (net.plane) {
                double[] g = net.ground[groundIndex++];
                b = e.addMass(groundKind, 1, g[0], g[1], g[2], 0, 0, 0);
            } else {
                b = origin;
            }
            e.addLink(net.linkKind, a, b, net.k.get(j) * s, net.z.get(j) * s, net.restLength);
        }
        return e;
    }

    private static double norm(Engine e, Net net, int[] ids, double[] t) {
        double s = 0;
        for (int i = 0; i < net.n; i++) {
            e.position(ids[i], t);
            double dx = t[0] - net.eq[i][0], dy = t[1] - net.eq[i][1], dz = t[2] - net.eq[i][2];
            e.displacement(ids[i], t);
            s += net.m[i] * (dx * dx + dy * dy + dz * dz + t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
        }
        return Math.sqrt(s);
    }

    /** Outcome of one simulated network. */
    private static final class Truth {
        boolean unstable;
        boolean extended;
        double growth;   // per-step log growth estimate
        long steps;
    }

    /** Steps the plan (no guard) until the norm exceeds 1e6 x its start, following the rules of the class comment. */
    private static Truth simulate(Engine e, Net net, int[] ids) {
        StepPlan p = e.plan();
        double[] t = new double[3];
        double start = norm(e, net, ids, t);
        double limit = 1e6 * start;
        Truth out = new Truth();
        int window = 256;
        double[] maxima = new double[32];
        for (int w = 0; w < 32; w++) {
            double mx = 0;
            for (int k = 1; k <= window; k++) {
                PlanAccess.stepWithoutGuard(p);
                if (k % 3 == 0) {
                    double v = norm(e, net, ids, t);
                    if (!(v <= limit)) {
                        out.unstable = true;
                        out.steps = (long) w * window + k;
                        out.growth = Math.log(v / start) / out.steps;
                        return out;
                    }
                    mx = Math.max(mx, v);
                }
            }
            maxima[w] = mx;
        }
        double sx = 0, sy = 0, sxx = 0, sxy = 0;
        for (int w = 16; w < 32; w++) {
            double x = w * (double) window;
            double y = Math.log(Math.max(maxima[w], Double.MIN_NORMAL));
            sx += x;
            sy += y;
            sxx += x * x;
            sxy += x * y;
        }
        out.growth = (16 * sxy - sx * sy) / (16 * sxx - sx * sx);
        out.steps = 32L * window;
        if (out.growth > 1e-5) {
            out.extended = true;
            for (long k = out.steps + 1; k <= 65_536; k++) {
                PlanAccess.stepWithoutGuard(p);
                if (k % 3 == 0) {
                    double v = norm(e, net, ids, t);
                    if (!(v <= limit)) {
                        out.unstable = true;
                        out.steps = k;
                        out.growth = Math.log(v / start) / k;
                        return out;
                    }
                }
            }
            out.steps = 65_536;
        }
        return out;
    }

    @Test
    @DisplayName("analyser verdict vs simulation on 10,000 random networks: >= 99% agreement, misses only within 1% of the bound")
    void analyserAgreesWithSimulation() {
        int families = FAMILIES.length;
        int[] cases = new int[families];
        int[] agree = new int[families];
        int[] nearCases = new int[families];
        int[] unsafe = new int[families];   // analyser stable, simulation unstable
        int[] safe = new int[families];     // analyser unstable, simulation stable
        int[] missNear = new int[families]; // disagreements within 1% of the bound
        int[] extended = new int[families];
        int[] unconverged = new int[families];
        double[] worstMissDistance = new double[families];
        List<String> misses = new ArrayList<>();
        long t0 = System.nanoTime();
        int total = CASES + MEMBRANES;
        for (int c = 0; c < total; c++) {
            SplittableRandom r = new SplittableRandom(SEED * 1_000_003L + c);
            int family = c < CASES ? c % LINEAR_FAMILIES : LINEAR_FAMILIES;
            Net net = generate(family, r);
            int[] ids = new int[net.n];
            long stateSeed = r.nextLong();
            double unitLambda = StabilityAnalyzer.analyze(build(net, 1, stateSeed, ids).plan()).lambda();
            double target = r.nextDouble() < 0.2 ? 3.96 + 0.08 * r.nextDouble() : 2 + 4 * r.nextDouble();
            Engine e = build(net, target / unitLambda, stateSeed, ids);
            StabilityReport rep = StabilityAnalyzer.analyze(e.plan());
            Truth truth = simulate(e, net, ids);
            double lambda = rep.lambda();
            boolean near = Math.abs(lambda - 4) <= 0.04;
            cases[family]++;
            nearCases[family] += near ? 1 : 0;
            extended[family] += truth.extended ? 1 : 0;
            unconverged[family] += rep.method() == StabilityReport.Method.LANCZOS_UNCONVERGED ? 1 : 0;
            if (rep.isStable() == !truth.unstable) {
                agree[family]++;
            } else {
                if (rep.isStable()) {
                    unsafe[family]++;
                } else {
                    safe[family]++;
                }
                missNear[family] += near ? 1 : 0;
                worstMissDistance[family] = Math.max(worstMissDistance[family], Math.abs(lambda / 4 - 1));
                if (family < LINEAR_FAMILIES || misses.size() < 40) {
                    misses.add(String.format(Locale.ROOT, "  case %d %s n=%d lambda=%.6f (%+.4f%%) analyser %s, "
                            + "simulation %s (growth %.3g/step over %d steps)", c, FAMILIES[family], net.n, lambda,
                            100 * (lambda / 4 - 1), rep.isStable() ? "stable" : "unstable",
                            truth.unstable ? "unstable" : "stable", truth.growth, truth.steps));
                }
            }
        }
        double seconds = (System.nanoTime() - t0) / 1e9;

        int linCases = 0, linAgree = 0, linMiss = 0, linMissNear = 0, linUnsafe = 0;
        StringBuilder table = new StringBuilder();
        table.append(String.format(Locale.ROOT, "[stability] analyser vs simulation, seed %d, %.1f s%n", SEED, seconds));
        table.append(String.format(Locale.ROOT, "  %-11s %6s %9s %10s %8s %8s %8s %9s %10s%n", "family", "cases",
                "agree", "rate", "near 1%", "misses", "in 1%", "unsafe", "extended"));
        for (int f = 0; f < families; f++) {
            int miss = cases[f] - agree[f];
            table.append(String.format(Locale.ROOT, "  %-11s %6d %9d %9.3f%% %8d %8d %8d %9d %10d%n", FAMILIES[f],
                    cases[f], agree[f], 100.0 * agree[f] / cases[f], nearCases[f], miss, missNear[f], unsafe[f],
                    extended[f]));
            if (f < LINEAR_FAMILIES) {
                linCases += cases[f];
                linAgree += agree[f];
                linMiss += miss;
                linMissNear += missNear[f];
                linUnsafe += unsafe[f];
            }
        }
        double rate = 100.0 * linAgree / linCases;
        table.append(String.format(Locale.ROOT, "  %-11s %6d %9d %9.3f%% %8s %8d %8d %9d%n", "all linear", linCases,
                linAgree, rate, "", linMiss, linMissNear, linUnsafe));
        table.append(String.format(Locale.ROOT, "  membrane3D (analyser an upper bound by design): %d misses, all "
                + "on the safe side: %b, farthest %.1f%% above the bound%n", cases[LINEAR_FAMILIES] - agree[LINEAR_FAMILIES],
                unsafe[LINEAR_FAMILIES] == 0, 100 * worstMissDistance[LINEAR_FAMILIES]));
        for (String s : misses) {
            table.append(s).append('\n');
        }
        System.out.print(table);

        assertEquals(CASES, linCases);
        assertTrue(rate >= 99.0, "agreement " + rate + "%");
        assertEquals(linMiss, linMissNear, "every disagreement on the linear families is within 1% of the bound");
        assertEquals(0, unsafe[LINEAR_FAMILIES], "membrane3D: the analyser must never call an unstable mesh stable");
        for (int f = 0; f < families; f++) {
            assertEquals(0, unconverged[f], FAMILIES[f] + ": Lanczos did not converge");
        }
    }
}
