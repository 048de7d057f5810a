package tactus.engine;

import java.util.Arrays;

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
 * <p>Broad phase: a Verlet neighbour list of the pairs closer than {@code threshold + skin}, built with
 * a uniform grid of cell size {@code threshold + skin} (dense over the members' bounding box when that
 * box holds few enough cells, hashed otherwise), and rebuilt only when some member has moved more than
 * {@code skin / 2} since the last build, so a pair that comes within the threshold is always in the list.
 * Steady-state stepping allocates nothing; the list and the grid only grow when the pile gets denser or
 * wider than ever before.
 */
final class ContactGroupKernel implements Kernel {
    private final StepPlan p;
    private final int[] slot;
    private final int n;
    final double threshold;
    final double k;
    final double z;
    private final double skin;
    private final double reach2;
    private final double halfSkin2;
    private final double cell;
    /** Member positions at the last build of the neighbour list (to detect a move beyond half the skin). */
    private final double[] builtX;
    private final double[] builtY;
    private final double[] builtZ;
    private final int mask;
    private final int[] bucketStart;
    private final int[] bucketItems;
    private final int[] cellOf;
    private final long[] cx;
    private final long[] cy;
    private final long[] cz;
    private int[] cellStart = new int[0];
    private int[] cellCursor = new int[0];
    private int[] candidates = new int[64];
    int[] pairI = new int[256];
    int[] pairJ = new int[256];
    int pairs;
    private boolean built;
    private long rebuilds;
    /**
     * Sequence number of the neighbour list, for readers on other threads: odd while {@link #rebuild()} writes the
     * list, even otherwise, and changed by every rebuild. Written by the stepping thread only, twice per rebuild.
     */
    private volatile long version;

    ContactGroupKernel(StepPlan p, int[] slots, double threshold, double k, double z, double skin) {
        this.p = p;
        this.slot = slots;
        this.n = slots.length;
        this.threshold = threshold;
        this.k = k;
        this.z = z;
        this.skin = skin;
        double reach = threshold + skin;
        this.reach2 = reach * reach;
        this.halfSkin2 = 0.25 * skin * skin;
        this.cell = reach > 0 ? reach : 1.0;
        builtX = new double[n];
        builtY = new double[n];
        builtZ = new double[n];
        int size = Integer.highestOneBit(Math.max(4, 2 * n - 1)) << 1;
        mask = size - 1;
        bucketStart = new int[size + 1];
        bucketItems = new int[n];
        cellOf = new int[n];
        cx = new long[n];
        cy = new long[n];
        cz = new long[n];
    }

    /** @return the member slots, in member order (the caller must not modify the array). */
    int[] members() {
        return slot;
    }

    /**
     * @return the potential energy ½K(d - threshold)² of the pairs closer than the threshold, per-step units,
     *     summed in the same order and with the same operations as {@link EnergyMeter} sums the equivalent
     *     explicit Contact3D links, so both agree exactly. Read-only, so that a reader on another thread never
     *     touches the state the stepping thread uses: the pairs come from this kernel's neighbour list when it is
     *     complete for the current positions and was not being rebuilt meanwhile (checked with {@link #version}),
     *     else from a neighbour search of its own (a fresh list with a skin of a millionth of the threshold,
     *     allocated here, O(members)); the list itself is never rebuilt here.
     */
    double energy() {
        double e = energyFromList();
        if (!Double.isNaN(e)) {
            return e;
        }
        ContactGroupKernel search = new ContactGroupKernel(p, slot, threshold, k, z, 1e-6 * threshold);
        search.rebuild();
        return search.engagedEnergy();
    }

    /**
     * @return the energy summed over this kernel's neighbour list, or NaN when the list cannot be used: never built,
     *     being rebuilt by the stepping thread (a sequence lock: {@link #version} is odd during a rebuild and changes
     *     with each one), or stale (a member moved beyond half the skin since it was built)
     */
    private double energyFromList() {
        long v = version;
        if ((v & 1) != 0 || !built) {
            return Double.NaN;
        }
        double e = movedTooFar() ? Double.NaN : engagedEnergy();
        java.lang.invoke.VarHandle.acquireFence(); // the reads above happen before the second read of the version
        return version == v ? e : Double.NaN;
    }

    /** @return the energy of the engaged pairs in this kernel's own neighbour list, as it is. */
    private double engagedEnergy() {
        double e = 0;
        final int[] pi = pairI, pj = pairJ;
        for (int q = 0, m = Math.min(pairs, Math.min(pi.length, pj.length)); q < m; q++) {
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
        return rebuilds;
    }

    @Override
    public void run() {
        if (!built || movedTooFar()) {
            rebuild();
        }
        final double[] x = p.x, y = p.y, zz = p.z, px = p.px, py = p.py, pz = p.pz;
        final double[] fx = p.fx, fy = p.fy, fz = p.fz;
        final double t = threshold, t2 = t * t, kk = k, zd = z;
        final int[] pi = pairI, pj = pairJ;
        for (int q = 0, m = pairs; q < m; q++) {
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

    private boolean movedTooFar() {
        final double[] x = p.x, y = p.y, zz = p.z;
        final double lim = halfSkin2;
        for (int m = 0; m < n; m++) {
            int s = slot[m];
            double dx = x[s] - builtX[m], dy = y[s] - builtY[m], dz = zz[s] - builtZ[m];
            if (!(dx * dx + dy * dy + dz * dz <= lim)) {
                return true;
            }
        }
        return false;
    }

    private int hash(long cx, long cy, long cz) {
        long h = cx * 0x9E3779B97F4A7C15L ^ cy * 0xC2B2AE3D27D4EB4FL ^ cz * 0x165667B19E3779F9L;
        return (int) (h ^ (h >>> 29)) & mask;
    }

    private long cellIndex(double v) {
        double c = Math.floor(v / cell);
        return c > 1e15 ? (long) 1e15 : c < -1e15 ? (long) -1e15 : (long) c;
    }

    /**
     * Builds the neighbour list: every pair closer than threshold + skin, in lexicographic member order. Only the
     * stepping thread calls it (and a reader on a kernel of its own).
     */
    void rebuild() {
        version++; // odd: readers leave the list alone until the next even value
        java.lang.invoke.VarHandle.storeStoreFence();
        try {
            rebuildList();
        } finally {
            version++;
        }
    }

    private void rebuildList() {
        rebuilds++;
        built = true;
        final double[] x = p.x, y = p.y, zz = p.z;
        long minX = Long.MAX_VALUE, minY = Long.MAX_VALUE, minZ = Long.MAX_VALUE;
        long maxX = Long.MIN_VALUE, maxY = Long.MIN_VALUE, maxZ = Long.MIN_VALUE;
        for (int m = 0; m < n; m++) {
            int s = slot[m];
            builtX[m] = x[s];
            builtY[m] = y[s];
            builtZ[m] = zz[s];
            long a = cellIndex(x[s]), b = cellIndex(y[s]), c = cellIndex(zz[s]);
            cx[m] = a;
            cy[m] = b;
            cz[m] = c;
            minX = Math.min(minX, a);
            minY = Math.min(minY, b);
            minZ = Math.min(minZ, c);
            maxX = Math.max(maxX, a);
            maxY = Math.max(maxY, b);
            maxZ = Math.max(maxZ, c);
        }
        pairs = 0;
        if (n == 0) {
            return;
        }
        long nx = maxX - minX + 1, ny = maxY - minY + 1, nz = maxZ - minZ + 1;
        // the cell count in double: nx * ny * nz can overflow a long (cell indices reach +-1e15)
        if ((double) nx * (double) ny * (double) nz <= Math.max(4096L, 32L * n)) {
            rebuildDense(minX, minY, minZ, (int) nx, (int) ny, (int) nz);
        } else {
            rebuildHashed();
        }
    }

    /** Neighbour search on a dense grid over the members' bounding box: each cell's members, in member order. */
    private void rebuildDense(long minX, long minY, long minZ, int nx, int ny, int nz) {
        int cells = nx * ny * nz;
        if (cellStart.length < cells + 1) {
            cellStart = new int[Math.max(cells + 1, 2 * cellStart.length)];
            cellCursor = new int[cellStart.length];
        }
        Arrays.fill(cellStart, 0, cells + 1, 0);
        for (int m = 0; m < n; m++) {
            int c = (int) (((cx[m] - minX) * ny + (cy[m] - minY)) * nz + (cz[m] - minZ));
            cellOf[m] = c;
            cellStart[c + 1]++;
        }
        for (int c = 0; c < cells; c++) {
            cellStart[c + 1] += cellStart[c];
        }
        System.arraycopy(cellStart, 0, cellCursor, 0, cells);
        for (int m = 0; m < n; m++) {
            bucketItems[cellCursor[cellOf[m]]++] = m;
        }
        for (int m = 0; m < n; m++) {
            int s = slot[m];
            int ix = (int) (cx[m] - minX), iy = (int) (cy[m] - minY), iz = (int) (cz[m] - minZ);
            int found = 0;
            for (int ox = Math.max(0, ix - 1); ox <= Math.min(nx - 1, ix + 1); ox++) {
                for (int oy = Math.max(0, iy - 1); oy <= Math.min(ny - 1, iy + 1); oy++) {
                    int row = (ox * ny + oy) * nz;
                    int from = cellStart[row + Math.max(0, iz - 1)];
                    int to = cellStart[row + Math.min(nz - 1, iz + 1) + 1];
                    found = collect(m, from, to, found);
                }
            }
            append(s, found);
        }
    }

    /** Neighbour search on a hashed grid, for members spread over a large, sparse volume. */
    private void rebuildHashed() {
        Arrays.fill(bucketStart, 0);
        for (int m = 0; m < n; m++) {
            int h = hash(cx[m], cy[m], cz[m]);
            cellOf[m] = h;
            bucketStart[h + 1]++;
        }
        for (int h = 0; h < mask + 1; h++) {
            bucketStart[h + 1] += bucketStart[h];
        }
        if (cellCursor.length < mask + 1) {
            cellCursor = new int[mask + 1];
        }
        System.arraycopy(bucketStart, 0, cellCursor, 0, mask + 1);
        for (int m = 0; m < n; m++) {
            bucketItems[cellCursor[cellOf[m]]++] = m;
        }
        for (int m = 0; m < n; m++) {
            int s = slot[m];
            int found = 0;
            for (int ox = -1; ox <= 1; ox++) {
                for (int oy = -1; oy <= 1; oy++) {
                    for (int oz = -1; oz <= 1; oz++) {
                        int h = hash(cx[m] + ox, cy[m] + oy, cz[m] + oz);
                        found = collect(m, bucketStart[h], bucketStart[h + 1], found);
                    }
                }
            }
            append(s, found);
        }
    }

    /**
     * Adds to member m's sorted candidate list every later member listed in bucketItems[from, to) that lies
     * closer than threshold + skin.
     *
     * @return the new number of candidates
     */
    private int collect(int m, int from, int to, int found) {
        final double[] x = p.x, y = p.y, zz = p.z;
        int s = slot[m];
        for (int q = from; q < to; q++) {
            int other = bucketItems[q];
            if (other <= m) {
                continue;
            }
            int os = slot[other];
            double dx = x[s] - x[os], dy = y[s] - y[os], dz = zz[s] - zz[os];
            if (dx * dx + dy * dy + dz * dz < reach2) {
                found = insertSorted(found, other);
            }
        }
        return found;
    }

    /** Appends the pairs (s, candidate) found for one member, in candidate order. */
    private void append(int s, int found) {
        ensurePairs(pairs + found);
        for (int f = 0; f < found; f++) {
            pairI[pairs] = s;
            pairJ[pairs] = slot[candidates[f]];
            pairs++;
        }
    }

    /** Inserts a member index into the sorted candidate list, skipping duplicates; returns the new count. */
    private int insertSorted(int count, int value) {
        int pos = count;
        while (pos > 0 && candidates[pos - 1] > value) {
            pos--;
        }
        if (pos > 0 && candidates[pos - 1] == value) {
            return count;
        }
        if (count == candidates.length) {
            candidates = Arrays.copyOf(candidates, count * 2);
        }
        System.arraycopy(candidates, pos, candidates, pos + 1, count - pos);
        candidates[pos] = value;
        return count + 1;
    }

    private void ensurePairs(int needed) {
        if (needed > pairI.length) {
            int c = Math.max(needed, pairI.length * 2);
            pairI = Arrays.copyOf(pairI, c);
            pairJ = Arrays.copyOf(pairJ, c);
        }
    }
}
