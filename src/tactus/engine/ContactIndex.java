package tactus.engine;

/**
 * The broad phase of a large batch of explicit {@link LinkKind#CONTACT3D} links: the contacts that may act this
 * step, found with a {@link NeighbourList} over the batch's masses instead of testing every contact every step.
 * It pays when the batch holds many contacts per mass, as in the paper's EnclosedMarbles (one contact per pair of
 * marbles: 200 marbles, 19,900 contacts, of which a few hundred touch).
 *
 * <p>The candidates are the contacts whose two masses are closer than {@code maxThreshold + skin}, listed in
 * batch order (insertion order), so that the kernel adds forces in the same order as a test of every contact and
 * gives the same sums, bit for bit. The list stays valid until some mass moves more than half the skin; it is then
 * rebuilt: the neighbour pairs are mapped to their contacts with an open-addressing table keyed by the pair, the
 * contacts are marked in a bit set, and the set is read back in order. Nothing is allocated after construction.
 *
 * <p>{@link #refresh()} answers false, and the kernel tests every contact, whenever the candidates cannot be
 * trusted: a mass position that is not finite, or a threshold that is not a positive finite number.
 */
final class ContactIndex {
    /** The skin, as a fraction of the largest threshold of the batch. */
    static final double SKIN = 0.5;
    /** A batch needs at least this many contacts for the index to be built. */
    static final int MIN_LINKS = 1024;
    /** A batch needs at least this many contacts per distinct mass for the index to be built. */
    static final int MIN_LINKS_PER_MASS = 8;

    private final LinkBatch b;
    private final StepPlan p;
    private final int[] members;
    private final NeighbourList list;
    /** Open-addressing table: pair key (lower slot, higher slot) to the first contact of that pair. */
    private final long[] keys;
    private final int[] first;
    private final int keyMask;
    /** The next contact of the same pair, in batch order, or -1. */
    private final int[] nextSame;
    private final long[] marked;
    /** The candidate contacts, ascending, in [0, candidates). */
    final int[] candidate;
    int candidates;
    private int seenParams = Integer.MIN_VALUE;
    private boolean usable;
    private long rebuilds;

    private ContactIndex(LinkBatch b, StepPlan p, int[] members) {
        this.b = b;
        this.p = p;
        this.members = members;
        this.list = new NeighbourList(p, members, 0.0, 0.0);
        int size = Integer.highestOneBit(Math.max(4, 2 * b.n - 1)) << 1;
        keys = new long[size];
        first = new int[size];
        keyMask = size - 1;
        java.util.Arrays.fill(first, -1);
        nextSame = new int[b.n];
        int[] last = new int[size];
        for (int j = 0; j < b.n; j++) {
            long key = key(b.a[j], b.b[j]);
            int h = find(key);
            nextSame[j] = -1;
            if (first[h] < 0) {
                keys[h] = key;
                first[h] = j;
            } else {
                nextSame[last[h]] = j;
            }
            last[h] = j;
        }
        marked = new long[(b.n + 63) >>> 6];
        candidate = new int[b.n];
    }

    /**
     * @return an index for a Contact3D batch when it holds enough contacts per mass to pay (and none from a mass
     *     to itself), else null
     */
    static ContactIndex forBatch(LinkBatch b, StepPlan p) {
        if (b.kind != LinkKind.CONTACT3D || b.n < MIN_LINKS || b.runs.length > 0) {
            return null;
        }
        boolean[] seen = new boolean[p.nMass];
        int distinct = 0;
        for (int j = 0; j < b.n; j++) {
            if (b.a[j] == b.b[j]) {
                return null;
            }
            distinct += see(seen, b.a[j]) + see(seen, b.b[j]);
        }
        if ((long) b.n < (long) MIN_LINKS_PER_MASS * distinct) {
            return null;
        }
        int[] members = new int[distinct];
        for (int s = 0, m = 0; s < seen.length; s++) {
            if (seen[s]) {
                members[m++] = s;
            }
        }
        return new ContactIndex(b, p, members);
    }

    /** Marks a slot as seen; returns 1 the first time, 0 after. */
    private static int see(boolean[] seen, int s) {
        if (seen[s]) {
            return 0;
        }
        seen[s] = true;
        return 1;
    }

    /** @return the plan this index reads positions from */
    StepPlan plan() {
        return p;
    }

    /** @return how many times the candidate list has been rebuilt (for tests) */
    long rebuilds() {
        return rebuilds;
    }

    /**
     * Makes the candidate list complete for the current positions and thresholds. Allocates nothing.
     *
     * @return true when {@link #candidate} holds every contact that may act this step; false when every contact
     *     must be tested (a position or a threshold that the broad phase cannot handle)
     */
    boolean refresh() {
        if (b.paramsVersion != seenParams) {
            seenParams = b.paramsVersion;
            double reach = 0;
            for (int j = 0; j < b.n; j++) {
                // the kernel compares d² with t², so a negative threshold acts by its magnitude
                reach = Math.max(reach, Math.abs(b.len[j]));
            }
            usable = reach > 0 && reach < Double.MAX_VALUE;
            if (usable) {
                list.setReach(reach, SKIN * reach);
            }
        }
        if (!usable) {
            return false;
        }
        if (list.refresh()) {
            if (!allFinite()) {
                return false;
            }
            collect();
        }
        return true;
    }

    /** @return whether every member's position is finite (the grid cannot place the others) */
    private boolean allFinite() {
        final double[] x = p.x, y = p.y, z = p.z;
        for (int s : members) {
            if (!Double.isFinite(x[s]) || !Double.isFinite(y[s]) || !Double.isFinite(z[s])) {
                return false;
            }
        }
        return true;
    }

    /** Maps the neighbour pairs to their contacts, in batch order. */
    private void collect() {
        rebuilds++;
        final int[] pi = list.pairI, pj = list.pairJ;
        final long[] bits = marked;
        for (int q = 0, m = list.pairs; q < m; q++) {
            int h = lookup(key(pi[q], pj[q]));
            if (h < 0) {
                continue;
            }
            for (int j = first[h]; j >= 0; j = nextSame[j]) {
                bits[j >>> 6] |= 1L << j;
            }
        }
        int c = 0;
        for (int w = 0; w < bits.length; w++) {
            long word = bits[w];
            bits[w] = 0;
            while (word != 0) {
                candidate[c++] = (w << 6) + Long.numberOfTrailingZeros(word);
                word &= word - 1;
            }
        }
        candidates = c;
    }

    private static long key(int s1, int s2) {
        return s1 < s2 ? ((long) s1 << 32) | (s2 & 0xFFFFFFFFL) : ((long) s2 << 32) | (s1 & 0xFFFFFFFFL);
    }

    private static int hash(long key) {
        long h = key * 0x9E3779B97F4A7C15L;
        return (int) (h ^ (h >>> 32));
    }

    /** @return the table slot holding key, or the empty slot where it would go */
    private int find(long key) {
        int h = hash(key) & keyMask;
        while (first[h] >= 0 && keys[h] != key) {
            h = (h + 1) & keyMask;
        }
        return h;
    }

    /** @return the table slot holding key, or -1 when no contact joins that pair */
    private int lookup(long key) {
        int h = find(key);
        return first[h] >= 0 ? h : -1;
    }
}
