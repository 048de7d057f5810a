package tactus.engine;

/**
 * A structured block of spring-damper links: for every mass slot {@code i} in {@code [s, e)} there is
 * (at most) one link between slot {@code i} and slot {@code i + o}. Chains (o = 1) and the rows, columns
 * and diagonals of meshes (o = 1, W, W + 1) are stencil runs. Missing links inside the range are
 * placeholders with K = Z = 0, which exchange exactly zero force.
 *
 * <p>Parameters and the damper's previous distance are stored by mass slot, so that the run's kernel
 * indexes every array with the same loop index; that is the form HotSpot's C2 compiler vectorises on
 * JDK 17 (loads at two different run-time offsets of one array are not vectorised there).
 */
final class StencilRun {
    final int s;
    final int e;
    final int o;
    final double[] k;
    final double[] z;
    final double[] l0;
    final double[] dp;

    StencilRun(int s, int e, int o) {
        this.s = s;
        this.e = e;
        this.o = o;
        k = new double[e];
        z = new double[e];
        l0 = new double[e];
        dp = new double[e];
    }
}
