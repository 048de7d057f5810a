package tactus.engine;

import java.util.Arrays;

/**
 * A Verlet neighbour list over a set of masses: every pair of members closer than a reach
 * ({@code threshold + skin}), found by testing every pair in groups of at most {@link #ALL_PAIRS_MAX} members and
 * with a uniform grid of cell size reach in larger ones (dense over the members' bounding box when that box holds
 * at most {@code max(4,096, 32 n)} cells, hashed otherwise), so that a rebuild costs in proportion to the members
 * (at most 64 grid cells per member), never to the volume they span; rebuilt only when some member has moved more
 * than {@code skin / 2} since the last build. Between two builds, every pair closer than the threshold is in the
 * list: each of its two masses moved at most half the skin, so the pair was closer than threshold + skin at the
 * build. Pairs are listed in lexicographic member order ({@link #pairI} before {@link #pairJ}, as mass slots).
 * Steady-state use allocates nothing; the list and the grid only grow when the members get denser or spread
 * wider than ever before, and a group searched pair by pair has room for all its pairs from construction on.
 *
 * <p>Used by contact groups ({@link ContactGroupKernel}) and by the broad phase of explicit contacts
 * ({@link ContactIndex}).
 */
final class NeighbourList {
    /**
     * Groups of at most this many members test every pair ({@code n (n - 1) / 2} distance tests, 2,016 at 64) rather
     * than build a grid: measured on this project's 2-core Xeon, every pair costs 0.4 µs per rebuild at 24 members and
     * 2.7 µs at 64, the dense grid 1.2 and 3.4 µs (the hashed grid more), and the grid wins from about 96 members on.
     */
    static final int ALL_PAIRS_MAX = 64;
    /**
     * The dense grid is used when the members' bounding box holds at most {@code max(4,096, 32 n)} cells for n members
     * (at most 64 per member, since only groups of more than {@link #ALL_PAIRS_MAX} use a grid), so that clearing and
     * summing its cell counts costs a few dozen operations per member; sparser groups use the hashed grid (a table of
     * 8 to 16 buckets per member, {@link #HASH_BUCKETS_PER_MEMBER}). Measured: the strung-out 200- and 2,000-member
     * groups of {@code tactus.bench.GroupScenes} stepped 1.6 times slower on the hashed grid (then with 2 to 4 buckets
     * per member) than on the dense one (docs/audio.md, "The contact group's rebuild").
     */
    static final int DENSE_CELLS_PER_MEMBER = 32;
    /** The dense grid is used up to this many cells whatever the member count (see {@link #DENSE_CELLS_PER_MEMBER}). */
    static final int DENSE_CELLS_MIN = 4096;
    /** The hashed grid's table has between this many and twice as many buckets per member. */
    static final int HASH_BUCKETS_PER_MEMBER = 8;
    /** {@link #lastSearch}: every pair tested. */
    static final int ALL_PAIRS = 0;
    /** {@link #lastSearch}: the dense grid. */
    static final int DENSE = 1;
    /** {@link #lastSearch}: the hashed grid. */
    static final int HASHED = 2;
    private final StepPlan p;
    private final int[] slot;
    private final int n;
    private double reach2;
    private double halfSkin2;
    private double cell;
    /** Member positions at the last build of the list (to detect a move beyond half the skin). */
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
    /** First mass slot of each listed pair. */
    int[] pairI = new int[256];
    /** Second mass slot of each listed pair. */
    int[] pairJ = new int[256];
    /** Number of listed pairs. */
    int pairs;
    private boolean built;
    private long rebuilds;
    /** The search the last rebuild used (for tests): {@link #ALL_PAIRS}, {@link #DENSE} or {@link #HASHED}. */
    int lastSearch;
    /**
     * Sequence number of the list, for readers on other threads: odd while {@link #rebuild()} writes the list,
     * even otherwise, and changed by every rebuild. Written by the stepping thread only, twice per rebuild.
     */
    volatile long version;

    /**
     * @param p the plan whose positions are read
     * @param slots the member mass slots, in member order
     * @param threshold the distance below which every pair must be listed (model units)
     * @param skin the margin added to the threshold (model units, &gt;= 0)
     */
    NeighbourList(StepPlan p, int[] slots, double threshold, double skin) {
        this.p = p;
        this.slot = slots;
        this.n = slots.length;
        builtX = new double[n];
        builtY = new double[n];
        builtZ = new double[n];
        // 8 to 16 buckets per member: with 2 to 4, a member's 27 neighbour cells held some 14 members of other cells
        // (hash collisions) to test, and the strung-out 2,000-member group rebuilt in 710 µs instead of 360 µs
        int size = Integer.highestOneBit(Math.max(4, HASH_BUCKETS_PER_MEMBER * n - 1)) << 1;
        mask = size - 1;
        bucketStart = new int[size + 1];
        bucketItems = new int[n];
        cellOf = new int[n];
        cx = new long[n];
        cy = new long[n];
        cz = new long[n];
        // a group searched pair by pair gets room for all its pairs now, so that no rebuild (on the stepping thread)
        // ever allocates
        ensurePairs(n <= ALL_PAIRS_MAX ? n * (n - 1) / 2 : 0);
        setReach(threshold, skin);
    }

    /**
     * Sets the threshold and skin; the next {@link #refresh()} rebuilds the list. Allocates nothing.
     *
     * @param threshold the distance below which every pair must be listed (model units)
     * @param skin the margin added to the threshold (model units, &gt;= 0)
     */
    void setReach(double threshold, double skin) {
        double reach = threshold + skin;
        this.reach2 = reach * reach;
        this.halfSkin2 = 0.25 * skin * skin;
        this.cell = reach > 0 ? reach : 1.0;
        built = false;
    }

    /** @return the member slots, in member order (the caller must not modify the array). */
    int[] members() {
        return slot;
    }

    /** @return whether the list was ever built */
    boolean isBuilt() {
        return built;
    }

    /** @return how many times the list has been rebuilt (for tests of the rebuild rate). */
    long rebuilds() {
        return rebuilds;
    }

    /**
     * Makes the list complete for the current positions: rebuilds it when it was never built or when some
     * member has moved more than half the skin since the last build.
     *
     * @return true when the list was rebuilt
     */
    boolean refresh() {
        if (!built || movedTooFar()) {
            rebuild();
            return true;
        }
        return false;
    }

    /** @return whether some member has moved more than half the skin since the last build (NaN counts as moved) */
    boolean movedTooFar() {
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
     * Builds the list now: every pair closer than the reach, in lexicographic member order. Only the stepping
     * thread calls it (and a reader on a list of its own).
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
        for (int m = 0; m < n; m++) {
            int s = slot[m];
            builtX[m] = x[s];
            builtY[m] = y[s];
            builtZ[m] = zz[s];
        }
        pairs = 0;
        if (n <= ALL_PAIRS_MAX) {
            lastSearch = ALL_PAIRS;
            rebuildAllPairs();
            return;
        }
        long minX = Long.MAX_VALUE, minY = Long.MAX_VALUE, minZ = Long.MAX_VALUE;
        long maxX = Long.MIN_VALUE, maxY = Long.MIN_VALUE, maxZ = Long.MIN_VALUE;
        for (int m = 0; m < n; m++) {
            int s = slot[m];
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
        long nx = maxX - minX + 1, ny = maxY - minY + 1, nz = maxZ - minZ + 1;
        // the cell count in double: nx * ny * nz can overflow a long (cell indices reach +-1e15)
        if ((double) nx * (double) ny * (double) nz <= Math.max(DENSE_CELLS_MIN, (double) DENSE_CELLS_PER_MEMBER * n)) {
            lastSearch = DENSE;
            rebuildDense(minX, minY, minZ, (int) nx, (int) ny, (int) nz);
        } else {
            lastSearch = HASHED;
            rebuildHashed();
        }
    }

    /**
     * Neighbour search of a small group: every pair tested, in lexicographic member order (the order the grids
     * produce), with the same distance test as {@link #collect}.
     */
    private void rebuildAllPairs() {
        final double[] x = p.x, y = p.y, zz = p.z;
        final double r2 = reach2;
        int count = 0;
        for (int m = 0; m < n - 1; m++) {
            int s = slot[m];
            double sx = x[s], sy = y[s], sz = zz[s];
            for (int other = m + 1; other < n; other++) {
                int os = slot[other];
                double dx = sx - x[os], dy = sy - y[os], dz = sz - zz[os];
                if (dx * dx + dy * dy + dz * dz < r2) {
                    pairI[count] = s;
                    pairJ[count] = os;
                    count++;
                }
            }
        }
        pairs = count;
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
     * closer than the reach.
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
