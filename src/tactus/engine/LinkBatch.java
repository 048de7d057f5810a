package tactus.engine;

/**
 * Flat arrays for all live links of one kind, in insertion order. {@code a} and {@code b}
 * are mass slots in the {@link StepPlan}; {@code dp} is the previous distance used by the
 * damper (a negative value marks a conditional link that was inactive on the previous step).
 */
final class LinkBatch {
    final LinkKind kind;
    final int n;
    final int[] id;
    final int[] a;
    final int[] b;
    final double[] k;
    final double[] z;
    final double[] len;
    final double[] aux;
    final double[] dp;
    /** For plane contacts: links [axisStart[i], axisStart[i+1]) act on axis i. */
    final int[] axisStart = new int[4];

    LinkBatch(LinkKind kind, int n) {
        this.kind = kind;
        this.n = n;
        id = new int[n];
        a = new int[n];
        b = new int[n];
        k = new double[n];
        z = new double[n];
        len = new double[n];
        aux = new double[n];
        dp = new double[n];
    }
}
