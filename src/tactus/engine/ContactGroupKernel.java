package tactus.engine;

/**
 * Contact between every pair of a group of masses, found by a broad phase instead of N² explicit links.
 *
 * <p>Semantics: for every unordered pair (i, j) of members, i before j in member order, exactly a
 * {@link LinkKind#CONTACT3D} link between i and j: while {@code d < threshold} it adds
 * {@code f = -K (d - threshold) - Z (d(n) - d(n-1))} along the line between them, with the previous
 * distance taken from the masses' previous positions (which is what an explicit contact stores). Pairs
 * are visited in lexicographic order, so the force sums equal those of explicit contacts added in that
 * order, bit for bit (the two share {@link LinkKernels#springDamperOverDistance}; after a change of step
 * duration, {@link Engine#rescaleTime}, they agree to round-off only, the explicit links rescaling their
 * stored previous distance and the group its members' previous positions).
 *
 * <p>Broad phase: a {@link NeighbourList} of the pairs closer than {@code threshold + skin}, rebuilt only when
 * some member has moved more than {@code skin / 2} since the last build, so a pair that comes within the
 * threshold is always in the list. Steady-state stepping allocates nothing.
 */
final class ContactGroupKernel implements Kernel {
    private final StepPlan p;
    private final NeighbourList list;
    final double threshold;
    final double k;
    final double z;

    ContactGroupKernel(StepPlan p, int[] slots, double threshold, double k, double z, double skin) {
        this.p = p;
        this.threshold = threshold;
        this.k = k;
        this.z = z;
        this.list = new NeighbourList(p, slots, threshold, skin);
    }

    /** @return the member slots, in member order (the caller must not modify the array). */
    int[] members() {
        return list.members();
    }

    /**
     * @return the potential energy ½K(d - threshold)² of the pairs closer than the threshold, per-step units,
     *     summed in the same order and with the same operations as {@link EnergyMeter} sums the equivalent
     *     explicit Contact3D links, so both agree exactly. Read-only, so that a reader on another thread never
     *     touches the state the stepping thread uses: the pairs come from this kernel's neighbour list when it is
     *     complete for the current positions and was not being rebuilt meanwhile (checked with the list's
     *     version), else from a neighbour search of its own (a fresh list with a skin of a millionth of the
     *     threshold, allocated here, O(members)); the list itself is never rebuilt here.
     */
    double energy() {
        double e = energyFromList();
        if (!Double.isNaN(e)) {
            return e;
        }
        NeighbourList search = new NeighbourList(p, list.members(), threshold, 1e-6 * threshold);
        search.rebuild();
        return engagedEnergy(search);
    }

    /**
     * @return the energy summed over this kernel's neighbour list, or NaN when the list cannot be used: never built,
     *     being rebuilt by the stepping thread (a sequence lock: the list's version is odd during a rebuild and
     *     changes with each one), or stale (a member moved beyond half the skin since it was built)
     */
    private double energyFromList() {
        long v = list.version;
        if ((v & 1) != 0 || !list.isBuilt()) {
            return Double.NaN;
        }
        double e = list.movedTooFar() ? Double.NaN : engagedEnergy(list);
        java.lang.invoke.VarHandle.acquireFence(); // the reads above happen before the second read of the version
        return list.version == v ? e : Double.NaN;
    }

    /** @return the energy of the engaged pairs in a neighbour list, as it is. */
    private double engagedEnergy(NeighbourList l) {
        double e = 0;
        final int[] pi = l.pairI, pj = l.pairJ;
        for (int q = 0, m = Math.min(l.pairs, Math.min(pi.length, pj.length)); q < m; q++) {
            int a = pi[q], c = pj[q];
            double dx = p.x[a] - p.x[c], dy = p.y[a] - p.y[c], dz = p.z[a] - p.z[c];
            double d = Math.sqrt(dx * dx + dy * dy + dz * dz);
            if (d < threshold) {
                double stretch = d - threshold;
                e += 0.5 * k * stretch * stretch;
            }
        }
        return e;
    }

    /** @return how many times the neighbour list has been rebuilt (for tests of the rebuild rate). */
    long rebuilds() {
        return list.rebuilds();
    }

    @Override
    public void run() {
        list.refresh();
        final double[] x = p.x, y = p.y, zz = p.z, px = p.px, py = p.py, pz = p.pz;
        final double[] fx = p.fx, fy = p.fy, fz = p.fz;
        final double t = threshold, t2 = t * t, kk = k, zd = z;
        final int[] pi = list.pairI, pj = list.pairJ;
        for (int q = 0, m = list.pairs; q < m; q++) {
            int a = pi[q], c = pj[q];
            double dx = x[a] - x[c], dy = y[a] - y[c], dz = zz[a] - zz[c];
            double d2 = dx * dx + dy * dy + dz * dz;
            if (d2 >= t2) {
                continue;
            }
            double d = Math.sqrt(d2);
            double ex = px[a] - px[c], ey = py[a] - py[c], ez = pz[a] - pz[c];
            double prev = Math.sqrt(ex * ex + ey * ey + ez * ez);
            if (d > 0) {
                LinkKernels.push(fx, fy, fz, a, c, LinkKernels.springDamperOverDistance(kk, zd, t, d, prev), dx, dy, dz);
            }
        }
    }
}
