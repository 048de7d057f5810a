package tactus.engine;

import java.util.Arrays;

/**
 * Parameters of every interaction ever added, indexed by a stable id that is never reused.
 * {@code length} is the rest length, contact threshold, bubble radius, plane offset or
 * attractor limit distance depending on the kind; {@code planePosition} is the plane coordinate of a
 * plane contact, {@code attraction} the attraction factor A of an attractor (0 for other kinds);
 * {@code axis} is the plane axis (0 = x, 1 = y, 2 = z).
 */
final class LinkTable {
    int count;
    LinkKind[] kind = new LinkKind[16];
    boolean[] alive = new boolean[16];
    int[] slot = new int[16];
    int[] a = new int[16];
    int[] b = new int[16];
    double[] stiffness = new double[16];
    double[] damping = new double[16];
    double[] length = new double[16];
    double[] planePosition = new double[16];
    double[] attraction = new double[16];
    int[] axis = new int[16];
    /** The parameters beyond K, Z and the length of the kinds that have them ({@link LinkKind#auxNames()}). */
    double[] aux0 = new double[16];
    double[] aux1 = new double[16];

    int add(LinkKind k, int massA, int massB, double kk, double zz, double len) {
        ensure(count + 1);
        int id = count++;
        kind[id] = k;
        alive[id] = true;
        slot[id] = -1;
        a[id] = massA;
        b[id] = massB;
        stiffness[id] = kk;
        damping[id] = zz;
        length[id] = len;
        aux0[id] = 0;
        aux1[id] = 0;
        return id;
    }

    boolean isLive(int id) {
        return id >= 0 && id < count && alive[id];
    }

    private void ensure(int n) {
        if (n <= kind.length) {
            return;
        }
        int c = Math.max(n, kind.length * 2);
        kind = Arrays.copyOf(kind, c);
        alive = Arrays.copyOf(alive, c);
        slot = Arrays.copyOf(slot, c);
        a = Arrays.copyOf(a, c);
        b = Arrays.copyOf(b, c);
        stiffness = Arrays.copyOf(stiffness, c);
        damping = Arrays.copyOf(damping, c);
        length = Arrays.copyOf(length, c);
        planePosition = Arrays.copyOf(planePosition, c);
        attraction = Arrays.copyOf(attraction, c);
        axis = Arrays.copyOf(axis, c);
        aux0 = Arrays.copyOf(aux0, c);
        aux1 = Arrays.copyOf(aux1, c);
    }
}
