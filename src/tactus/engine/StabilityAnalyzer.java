package tactus.engine;

import java.util.Arrays;

/**
 * Computes the stability margin of the explicit scheme for a compiled scene, before it runs.
 *
 * <p>For a linear network stepped with {@code X(n+1) = 2X(n) - X(n-1) + M⁻¹F} and forces
 * {@code F = -K X(n) - Z (X(n) - X(n-1))}, each mode with per-step stiffness k and damping z is stable
 * iff {@code k > 0} and {@code k + 2z < 4}. With proportional damping the modes of {@code M⁻¹K} and
 * {@code M⁻¹Z} coincide, so the network is stable iff {@code λmax(M⁻¹(K + 2Z)) < 4}; this analyser uses
 * that criterion for every network. See docs/stability.md for the derivation.
 *
 * <ul>
 *   <li>Every coordinate is treated like a scalar network with the link's axial stiffness. Under tension a
 *       3D spring's transverse stiffness {@code K (1 - l0/d)} is at most K, so this bounds the 3D case.</li>
 *   <li>Springs, dampers, ropes, bubbles and 1D spring-dampers are edges; edges to fixed points, input
 *       modules, plane contacts, oscillator springs and air friction are diagonal terms.</li>
 *   <li>An attractor counts with its largest local stiffness {@code 2|A| / dLim^3}.</li>
 *   <li>Contacts are counted as engaged, but a mass can touch only so many neighbours at once (12 in a
 *       close-packed 3D pile by default): their share is bounded by Gershgorin row sums with that many
 *       of the mass's stiffest contacts, and added to the rest (Weyl's inequality keeps this an upper
 *       bound).</li>
 *   <li>{@code λmax} of the permanent network is estimated by Lanczos iteration on the symmetric matrix
 *       {@code A = M^-1/2 (K + 2Z) M^-1/2}, matrix-free on the link list, under a work budget. The estimate
 *       is an upper one: the largest Ritz value theta plus its residual {@code ||A y - theta y||}, which for a
 *       symmetric matrix bounds the distance from theta to an eigenvalue (the largest one, which theta
 *       approaches from below). That residual is the safety margin of the verdict; it is reported
 *       ({@link StabilityReport#lanczosResidual()}). Lanczos runs until it is below 1e-7 relative to theta;
 *       when that takes more than its work budget (clustered spectra of long chains and large meshes), it
 *       stops as soon as the verdict is decided (theta at or above the limit proves instability, since a Ritz
 *       value never exceeds the largest eigenvalue; theta plus the residual below the limit shows stability),
 *       and near the limit it goes on up to a larger budget; a model still undecided then is reported
 *       unstable. Gershgorin row sums give a cheap, guaranteed upper bound alongside, and the estimate
 *       never exceeds it.</li>
 * </ul>
 */
public final class StabilityAnalyzer {
    /** Default number of contacts assumed engaged at once on one mass (close packing in 3D). */
    public static final int DEFAULT_MAX_CONTACTS = 12;

    /** Residual bound at which Lanczos stops, relative to the Ritz value. */
    private static final double TOLERANCE = 1e-7;
    /** Work budget (multiply-adds over masses and links) of a Lanczos run. */
    private static final long WORK_BUDGET = 10_000_000L;
    /** Work budget of a Lanczos run while the verdict is still undecided (theta near the limit). */
    private static final long NEAR_LIMIT_BUDGET = 250_000_000L;
    private static final int MAX_ITERATIONS = 20_000;

    private StabilityAnalyzer() {
    }

    /** Analyses a plan with the default contact count. */
    public static StabilityReport analyze(StepPlan p) {
        return analyze(p, DEFAULT_MAX_CONTACTS);
    }

    /**
     * Analyses a plan.
     *
     * @param p the compiled scene
     * @param maxContacts how many contacts may be engaged at once on one mass
     * @return the report
     */
    public static StabilityReport analyze(StepPlan p, int maxContacts) {
        return analyze(p, maxContacts, null);
    }

    /**
     * Analyses a plan as if one coefficient had another value, without writing it anywhere: the plan is only read,
     * so the analysis may run on any thread (it is how a stiffness limit is found by extrapolation).
     *
     * @param p the compiled scene
     * @param maxContacts how many contacts may be engaged at once on one mass
     * @param assumed the coefficient to take with another value, or null for the plan as it is
     * @return the report
     */
    public static StabilityReport analyze(StepPlan p, int maxContacts, Assumption assumed) {
        Network net = new Network(p, assumed);
        double gersh = net.gershgorin();
        double[] contacts = contactBound(p, maxContacts, assumed);
        double lambda;
        double residual = 0;
        StabilityReport.Method method;
        if (net.edges == 0 && net.maxDiag() == 0) {
            lambda = 0;
            method = StabilityReport.Method.TRIVIAL;
        } else {
            double[] result = net.lanczos(StabilityReport.LIMIT - contacts[0]);
            residual = result[1];
            lambda = Math.min(result[0] + residual, gersh);
            method = result[2] > 0 ? StabilityReport.Method.LANCZOS : StabilityReport.Method.LANCZOS_UNCONVERGED;
        }
        int culpritLink = net.culpritLink;
        int culpritMass = net.culpritMass;
        int culpritGroup = -1;
        if (contacts[0] > lambda) {
            culpritLink = (int) contacts[1];
            culpritMass = (int) contacts[2];
            culpritGroup = (int) contacts[4];
        }
        int negative = net.negativeLink >= 0 ? net.negativeLink : (int) contacts[3];
        return new StabilityReport(lambda, contacts[0], gersh, method, culpritLink, culpritMass, negative,
                net.negativeMass, culpritGroup, Math.min(residual, gersh));
    }

    private static double coefficient(double k, double z) {
        return k + 2 * Math.max(z, 0);
    }

    /**
     * One coefficient an analysis takes with another value than the plan's: the stiffness K of one link, or the
     * internal stiffness of one oscillator (per step). Immutable.
     */
    public static final class Assumption {
        private final int link;
        private final int mass;
        private final double stiffness;

        private Assumption(int link, int mass, double stiffness) {
            this.link = link;
            this.mass = mass;
            this.stiffness = stiffness;
        }

        /** @return the assumption that link {@code linkId} has stiffness {@code k} (per step). */
        public static Assumption linkStiffness(int linkId, double k) {
            return new Assumption(linkId, -1, k);
        }

        /** @return the assumption that oscillator {@code massId} has internal stiffness {@code k} (per step). */
        public static Assumption oscillatorStiffness(int massId, double k) {
            return new Assumption(-1, massId, k);
        }

        /** @return the stiffness of link slot j of a batch, the assumed one for the assumed link. */
        static double linkK(Assumption a, LinkBatch b, int j) {
            return a != null && a.link >= 0 && b.id[j] == a.link ? a.stiffness : b.k[j];
        }

        /** @return the oscillator stiffness per unit mass of a slot, as fillMass writes it, assumed or not. */
        static double oscPerMass(Assumption a, StepPlan p, int slot) {
            return a != null && a.mass >= 0 && p.massId[slot] == a.mass ? a.stiffness * p.invM[slot]
                    : p.oscStiffnessPerMass[slot];
        }
    }

    /**
     * Gershgorin bound of M⁻¹C for contacts, with at most {@code cap} engaged per mass.
     *
     * @return {bound, id of the stiffest contact at the worst mass, id of that mass, first negative-damping
     *     contact id, index of the contact group responsible} (ids are -1 when absent)
     */
    private static double[] contactBound(StepPlan p, int cap, Assumption assumed) {
        LinkBatch b = p.batch(LinkKind.CONTACT3D);
        if ((b == null || b.n == 0) && p.groups.length == 0) {
            return new double[] {0, -1, -1, -1, -1};
        }
        int negative = -1;
        int n = p.nMass;
        double[] cmax = new double[n];
        int[] mobile = new int[n];
        int[] fixed = new int[n];
        int[] stiffest = new int[n];
        int[] stiffestGroup = new int[n];
        java.util.Arrays.fill(stiffestGroup, -1);
        for (int g = 0; g < p.groups.length; g++) {
            ContactGroupKernel grp = p.groups[g];
            double c = coefficient(grp.k, grp.z);
            int[] members = grp.members();
            for (int s : members) {
                mobile[s] += members.length - 1;
                if (c >= cmax[s]) {
                    cmax[s] = c;
                    stiffestGroup[s] = g;
                }
            }
        }
        for (int j = 0, nb = b == null ? 0 : b.n; j < nb; j++) {
            double c = coefficient(Assumption.linkK(assumed, b, j), b.z[j]);
            if (b.z[j] < 0 && negative < 0) {
                negative = b.id[j];
            }
            int a = b.a[j], d = b.b[j];
            if (c >= cmax[a]) {
                stiffest[a] = b.id[j];
                stiffestGroup[a] = -1;
            }
            if (c >= cmax[d]) {
                stiffest[d] = b.id[j];
                stiffestGroup[d] = -1;
            }
            boolean am = p.invM[a] > 0, dm = p.invM[d] > 0;
            cmax[a] = Math.max(cmax[a], c);
            cmax[d] = Math.max(cmax[d], c);
            if (dm) {
                mobile[a]++;
            } else {
                fixed[a]++;
            }
            if (am) {
                mobile[d]++;
            } else {
                fixed[d]++;
            }
        }
        double worst = 0;
        int at = -1;
        for (int i = 0; i < n; i++) {
            if (p.invM[i] == 0) {
                continue;
            }
            int m = Math.min(mobile[i], cap);
            int f = Math.min(fixed[i], cap - m);
            double r = p.invM[i] * cmax[i] * (2 * m + f);
            if (r > worst) {
                worst = r;
                at = i;
            }
        }
        boolean byGroup = at >= 0 && stiffestGroup[at] >= 0;
        return new double[] {worst, at >= 0 && !byGroup ? stiffest[at] : -1, at >= 0 ? p.massId[at] : -1, negative,
            byGroup ? stiffestGroup[at] : -1};
    }

    /** The permanent network as an edge list plus a diagonal, in force units (per step). */
    private static final class Network {
        final StepPlan p;
        final Assumption assumed;
        final int n;
        final double[] diag;
        final double[] sqrtInvM;
        int edges;
        int[] ea = new int[64];
        int[] eb = new int[64];
        double[] ec = new double[64];
        int[] eid = new int[64];
        int culpritLink = -1;
        int culpritMass = -1;
        int negativeLink = -1;
        int negativeMass = -1;

        Network(StepPlan p, Assumption assumed) {
            this.p = p;
            this.assumed = assumed;
            n = p.nMass;
            diag = new double[n];
            sqrtInvM = new double[n];
            for (int i = 0; i < n; i++) {
                double im = p.invM[i];
                sqrtInvM[i] = Math.sqrt(im);
                if (im > 0) {
                    double zf = (1 - p.retention[i]) / im;
                    diag[i] += Assumption.oscPerMass(assumed, p, i) / im + 2 * Math.max(zf, 0);
                    if (zf < 0 && negativeMass < 0) {
                        negativeMass = p.massId[i];
                    }
                }
            }
            for (LinkBatch b : p.batches) {
                if (b == null || b.kind == LinkKind.CONTACT3D) {
                    continue;
                }
                for (int j = 0; j < b.n; j++) {
                    addLink(b, j);
                }
            }
        }

        private void addLink(LinkBatch b, int j) {
            double c;
            if (b.kind == LinkKind.ATTRACTOR3D) {
                double l = b.len[j] > 0 ? b.len[j] : PlanCompiler.distanceOf(b, j, p);
                c = l > 0 ? 2 * Math.abs(b.attraction[j]) / (l * l * l) : 0;
            } else if (b.kind.isNonlinear()) {
                // the descriptor's bound: the largest slope the law reaches, or its linear part where it has none
                double a0 = b.aux0.length > 0 ? b.aux0[j] : 0, a1 = b.aux1.length > 0 ? b.aux1[j] : 0;
                double kk = Assumption.linkK(assumed, b, j);
                double k = b.kind.boundStiffness(kk, a0, a1);
                double z = b.kind.boundDamping(kk, b.z[j], a0, a1);
                if (z < 0 && negativeLink < 0) {
                    negativeLink = b.id[j];
                }
                c = coefficient(k, z);
            } else {
                double k = b.kind.hasStiffness() ? Assumption.linkK(assumed, b, j) : 0;
                double z = b.kind.hasDamping() ? b.z[j] : 0;
                if (z < 0 && negativeLink < 0) {
                    negativeLink = b.id[j];
                }
                c = coefficient(k, z);
            }
            if (c == 0) {
                return;
            }
            int a = b.a[j], d = b.b[j];
            boolean am = p.invM[a] > 0, dm = p.invM[d] > 0;
            if (b.kind == LinkKind.PLANE_CONTACT3D || (am && !dm)) {
                if (am) {
                    addEdge(a, -1, c, b.id[j]);
                }
            } else if (dm && !am) {
                addEdge(d, -1, c, b.id[j]);
            } else if (am) {
                addEdge(a, d, c, b.id[j]);
            }
        }

        private void addEdge(int a, int b, double c, int id) {
            if (edges == ea.length) {
                int cap = edges * 2;
                ea = Arrays.copyOf(ea, cap);
                eb = Arrays.copyOf(eb, cap);
                ec = Arrays.copyOf(ec, cap);
                eid = Arrays.copyOf(eid, cap);
            }
            ea[edges] = a;
            eb[edges] = b;
            ec[edges] = c;
            eid[edges] = id;
            edges++;
        }

        double maxDiag() {
            double m = 0;
            for (int i = 0; i < n; i++) {
                m = Math.max(m, diag[i] * p.invM[i]);
            }
            return m;
        }

        /** Gershgorin bound of M⁻¹C, and the culprit where it is reached. */
        double gershgorin() {
            double[] row = new double[n];
            for (int i = 0; i < n; i++) {
                row[i] = diag[i];
            }
            for (int e = 0; e < edges; e++) {
                if (eb[e] < 0) {
                    row[ea[e]] += ec[e];
                } else {
                    row[ea[e]] += 2 * ec[e];
                    row[eb[e]] += 2 * ec[e];
                }
            }
            double worst = 0;
            int at = -1;
            for (int i = 0; i < n; i++) {
                double r = row[i] * p.invM[i];
                if (r > worst) {
                    worst = r;
                    at = i;
                }
            }
            if (at >= 0) {
                culpritMass = p.massId[at];
                double best = diag[at];
                for (int e = 0; e < edges; e++) {
                    if (ea[e] == at || eb[e] == at) {
                        double share = (eb[e] < 0 ? 1 : 2) * ec[e];
                        if (share > best) {
                            best = share;
                            culpritLink = eid[e];
                        }
                    }
                }
            }
            return worst;
        }

        /** y = M^-1/2 C M^-1/2 v. */
        private void apply(double[] v, double[] u, double[] y) {
            for (int i = 0; i < n; i++) {
                u[i] = v[i] * sqrtInvM[i];
                y[i] = diag[i] * u[i];
            }
            for (int e = 0; e < edges; e++) {
                int a = ea[e], b = eb[e];
                double c = ec[e];
                if (b < 0) {
                    y[a] += c * u[a];
                } else {
                    double t = c * (u[a] - u[b]);
                    y[a] += t;
                    y[b] -= t;
                }
            }
            for (int i = 0; i < n; i++) {
                y[i] *= sqrtInvM[i];
            }
        }

        /**
         * Lanczos iteration with a residual test. At each check the largest Ritz value theta of the tridiagonal
         * T_k is found by bisection, and its residual {@code ||A y - theta y|| = beta_k |s_k|} (s_k the last
         * component of T_k's unit eigenvector) is computed: for a symmetric matrix some eigenvalue lies within
         * that residual of theta, so {@code theta + residual} is an upper estimate of the eigenvalue theta
         * approximates, which is the largest one (the start vector has a component along every mode). Since a
         * Ritz value never exceeds the largest eigenvalue, {@code theta >= limit} proves instability, and
         * {@code theta + residual < limit} shows stability with the residual as safety margin. The iteration
         * stops when the residual is below {@link #TOLERANCE} relative to theta (converged), when the Krylov
         * space is exhausted, or when the work budget {@link #WORK_BUDGET} is spent and the verdict against
         * {@code limit} is decided; while it is undecided (theta just below the limit, residual across it) the
         * iteration goes on up to {@link #NEAR_LIMIT_BUDGET}.
         *
         * @param limit the value of theta + residual that decides the verdict
         * @return {largest Ritz value, its residual bound, 1 if converged else 0}
         */
        double[] lanczos(double limit) {
            double[] q = new double[n];
            double[] qPrev = new double[n];
            double[] w = new double[n];
            double[] u = new double[n];
            long seed = 0x9E3779B97F4A7C15L;
            double norm = 0;
            for (int i = 0; i < n; i++) {
                seed = seed * 6364136223846793005L + 1442695040888963407L;
                q[i] = sqrtInvM[i] > 0 ? 0.5 + ((seed >>> 11) * 0x1.0p-53) : 0;
                norm += q[i] * q[i];
            }
            if (norm == 0) {
                return new double[] {0, 0, 1};
            }
            norm = Math.sqrt(norm);
            for (int i = 0; i < n; i++) {
                q[i] /= norm;
            }
            long perIteration = Math.max(1, 2L * n + 3L * edges);
            int plainIt = (int) Math.max(30, Math.min(MAX_ITERATIONS, WORK_BUDGET / perIteration));
            int maxIt = (int) Math.min(2L * n + 2, Math.max(plainIt, Math.min(MAX_ITERATIONS, NEAR_LIMIT_BUDGET / perIteration)));
            double[] alpha = new double[maxIt];
            double[] beta = new double[maxIt];
            double theta = 0;
            double residual = Double.POSITIVE_INFINITY;
            int k = 0;
            int nextCheck = 5;
            boolean converged = false;
            double betaPrev = 0;
            for (int j = 0; j < maxIt; j++) {
                apply(q, u, w);
                double a = 0;
                for (int i = 0; i < n; i++) {
                    w[i] -= betaPrev * qPrev[i];
                    a += q[i] * w[i];
                }
                double bb = 0;
                for (int i = 0; i < n; i++) {
                    w[i] -= a * q[i];
                    bb += w[i] * w[i];
                }
                double b = Math.sqrt(bb);
                alpha[j] = a;
                beta[j] = b;
                k = j + 1;
                boolean exhausted = b <= 1e-12 * Math.abs(a);
                if (k >= nextCheck || exhausted || k == maxIt) {
                    theta = largestTridiagonal(alpha, beta, k);
                    residual = exhausted ? 0 : b * Math.abs(lastEigenvectorComponent(alpha, beta, k, theta));
                    if (residual <= TOLERANCE * Math.abs(theta)) {
                        converged = true;
                        break;
                    }
                    if (k >= plainIt && (theta >= limit || theta + residual < limit)) {
                        break; // the plain budget is spent and the verdict is decided
                    }
                    nextCheck = Math.max(k + 5, k + k / 8);
                }
                for (int i = 0; i < n; i++) {
                    double t = q[i];
                    q[i] = w[i] / b;
                    qPrev[i] = t;
                }
                betaPrev = b;
            }
            return new double[] {theta, residual, converged ? 1 : 0};
        }
    }

    /**
     * The last component of the unit eigenvector of the symmetric tridiagonal matrix (alpha, beta) for the
     * eigenvalue theta, by two steps of inverse iteration (theta is accurate to a few ulps, so the shifted
     * matrix is nearly singular and one step already gives the eigenvector to working precision).
     */
    static double lastEigenvectorComponent(double[] alpha, double[] beta, int k, double theta) {
        double shift = theta + 1e-13 * Math.max(1, Math.abs(theta));
        double[] x = new double[k];
        java.util.Arrays.fill(x, 1.0 / Math.sqrt(k));
        for (int it = 0; it < 2; it++) {
            solveShifted(alpha, beta, k, shift, x);
            double nn = 0;
            for (int i = 0; i < k; i++) {
                nn += x[i] * x[i];
            }
            nn = Math.sqrt(nn);
            if (!(nn > 0) || Double.isInfinite(nn)) {
                return 1.0; // no usable eigenvector: the most pessimistic residual
            }
            for (int i = 0; i < k; i++) {
                x[i] /= nn;
            }
        }
        return x[k - 1];
    }

    /** Solves (T - shift I) y = x in place for the symmetric tridiagonal T, with partial pivoting (Gaussian elimination). */
    private static void solveShifted(double[] alpha, double[] beta, int k, double shift, double[] x) {
        // LU with partial pivoting of a tridiagonal matrix: U has two superdiagonals
        double[] d = new double[k];    // U diagonal
        double[] e1 = new double[k];   // U first superdiagonal
        double[] e2 = new double[k];   // U second superdiagonal
        double[] l = new double[k];    // multipliers
        boolean[] swapped = new boolean[k];
        double diag = alpha[0] - shift;
        double sup = k > 1 ? beta[0] : 0;
        for (int i = 0; i < k - 1; i++) {
            double sub = beta[i];
            double nextDiag = alpha[i + 1] - shift;
            double nextSup = i + 2 < k ? beta[i + 1] : 0;
            if (Math.abs(sub) > Math.abs(diag)) {
                // swap rows i and i + 1
                swapped[i] = true;
                d[i] = sub;
                e1[i] = nextDiag;
                e2[i] = nextSup;
                double m = diag / sub;
                l[i] = m;
                diag = sup - m * nextDiag;
                sup = -m * nextSup;
            } else {
                swapped[i] = false;
                d[i] = diag == 0 ? 1e-300 : diag;
                e1[i] = sup;
                e2[i] = 0;
                double m = sub / d[i];
                l[i] = m;
                diag = nextDiag - m * sup;
                sup = nextSup;
            }
        }
        d[k - 1] = diag == 0 ? 1e-300 : diag;
        for (int i = 0; i < k - 1; i++) {
            if (swapped[i]) {
                double t = x[i];
                x[i] = x[i + 1];
                x[i + 1] = t;
            }
            x[i + 1] -= l[i] * x[i];
        }
        for (int i = k - 1; i >= 0; i--) {
            double v = x[i];
            if (i + 1 < k) {
                v -= e1[i] * x[i + 1];
            }
            if (i + 2 < k) {
                v -= e2[i] * x[i + 2];
            }
            x[i] = v / d[i];
        }
    }

    /** Largest eigenvalue of the symmetric tridiagonal matrix (alpha, beta off-diagonal), by bisection. */
    static double largestTridiagonal(double[] alpha, double[] beta, int k) {
        double lo = Double.POSITIVE_INFINITY, hi = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < k; i++) {
            double r = (i > 0 ? Math.abs(beta[i - 1]) : 0) + (i < k - 1 ? Math.abs(beta[i]) : 0);
            lo = Math.min(lo, alpha[i] - r);
            hi = Math.max(hi, alpha[i] + r);
        }
        for (int it = 0; it < 200 && hi - lo > 1e-15 * Math.max(1, Math.abs(hi)); it++) {
            double mid = 0.5 * (lo + hi);
            if (countBelow(alpha, beta, k, mid) < k) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        return hi;
    }

    /** Sturm count: the number of eigenvalues of the tridiagonal matrix below x. */
    private static int countBelow(double[] alpha, double[] beta, int k, double x) {
        int count = 0;
        double d = 1;
        for (int i = 0; i < k; i++) {
            double b2 = i > 0 ? beta[i - 1] * beta[i - 1] : 0;
            d = alpha[i] - x - (i > 0 ? b2 / d : 0);
            if (d == 0) {
                d = 1e-300;
            }
            if (d < 0) {
                count++;
            }
        }
        return count;
    }
}
