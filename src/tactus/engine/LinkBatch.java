package tactus.engine;

/**
 * Flat arrays for all live links of one kind. {@code a} and {@code b} are mass slots in the {@link StepPlan}.
 * Order: insertion order, except that plane contacts are grouped by axis ({@link #axisStart}) and that a
 * spring-family batch organised by the {@link StencilPlanner} holds its irregular links first (indices
 * [0, {@link #nIrregular}), in insertion order) and then the links of its {@link StencilRun}s (by offset and
 * slot, with {@code a < b}). The damper's previous distance of an irregular link is {@code dp[j]}; that of a
 * run link lives in its run, indexed by slot: read and write it with {@link #prev} and {@link #setPrev}. A
 * negative previous distance marks a conditional link that was inactive on the previous step.
 *
 * <p>Contact3D batches mark activity by step instead, so that a step touches only the contacts that act:
 * {@code dp[j]} holds the previous distance only while {@code engagedAt[j]} equals {@link #contactSteps} (the
 * contact acted on the last step); any other stamp reads as inactive. {@link #prev} and {@link #setPrev} hide
 * the difference.
 */
final class LinkBatch {
    private static final double[] NONE = new double[0];
    final LinkKind kind;
    final int n;
    final int[] id;
    final int[] a;
    final int[] b;
    final double[] k;
    final double[] z;
    final double[] len;
    /** Plane coordinate of each plane contact (an empty array in other batches). */
    final double[] planePosition;
    /** Attraction factor A of each attractor (an empty array in other batches). */
    final double[] attraction;
    /** The parameters beyond K, Z and the length ({@link LinkKind#auxNames()}); empty arrays for kinds without. */
    final double[] aux0;
    final double[] aux1;
    final double[] dp;
    /** For plane contacts: links [axisStart[i], axisStart[i+1]) act on axis i. */
    final int[] axisStart = new int[4];
    /** Links [0, nIrregular) are stepped with index arrays; the rest belong to {@link #runs}. */
    int nIrregular;
    /** Structured blocks of this batch (see {@link StencilRun}); empty for most kinds. */
    StencilRun[] runs = new StencilRun[0];
    /** For each link, the index of its run, or -1 when it is irregular. */
    final int[] runOf;
    /** Contact3D only (else null): the step count at which each contact last acted; see the class comment. */
    final long[] engagedAt;
    /** Contact3D only: the number of steps the batch's kernel has run. */
    long contactSteps;
    /** Changed by every {@link #setParams} call, so that kernels can notice new parameters. */
    int paramsVersion;
    /** Contact3D only: the broad phase of the batch's kernel, built with its first kernel, or null. */
    ContactIndex contactIndex;

    LinkBatch(LinkKind kind, int n) {
        this.kind = kind;
        this.n = n;
        id = new int[n];
        a = new int[n];
        b = new int[n];
        k = new double[n];
        z = new double[n];
        len = new double[n];
        planePosition = kind == LinkKind.PLANE_CONTACT3D ? new double[n] : NONE;
        attraction = kind == LinkKind.ATTRACTOR3D ? new double[n] : NONE;
        aux0 = kind.auxCount() > 0 ? new double[n] : NONE;
        aux1 = kind.auxCount() > 1 ? new double[n] : NONE;
        dp = new double[n];
        runOf = new int[n];
        java.util.Arrays.fill(runOf, -1);
        nIrregular = n;
        if (kind == LinkKind.CONTACT3D) {
            engagedAt = new long[n];
            java.util.Arrays.fill(engagedAt, -1L);
        } else {
            engagedAt = null;
        }
    }

    /** @return the damper's previous distance of link j (a negative value marks an inactive conditional link). */
    double prev(int j) {
        if (engagedAt != null) {
            return engagedAt[j] == contactSteps ? dp[j] : -1.0;
        }
        int r = runOf[j];
        return r < 0 ? dp[j] : runs[r].dp[a[j]];
    }

    /** Sets the damper's previous distance of link j. */
    void setPrev(int j, double v) {
        if (engagedAt != null) {
            dp[j] = v;
            engagedAt[j] = v < 0 ? contactSteps - 1 : contactSteps;
            return;
        }
        int r = runOf[j];
        if (r < 0) {
            dp[j] = v;
        } else {
            runs[r].dp[a[j]] = v;
        }
    }

    /** Sets the parameters of link j, in the batch and in its run if it has one. */
    void setParams(int j, double kk, double zz, double length, double plane, double attract, double a0, double a1) {
        paramsVersion++;
        k[j] = kk;
        z[j] = zz;
        len[j] = length;
        if (kind == LinkKind.PLANE_CONTACT3D) {
            planePosition[j] = plane;
        } else if (kind == LinkKind.ATTRACTOR3D) {
            attraction[j] = attract;
        }
        if (aux0.length > 0) {
            aux0[j] = a0;
        }
        if (aux1.length > 0) {
            aux1[j] = a1;
        }
        int r = runOf[j];
        if (r >= 0) {
            StencilRun run = runs[r];
            run.k[a[j]] = kk;
            run.z[a[j]] = zz;
            run.l0[a[j]] = length;
        }
    }
}
