package tactus.engine;

import java.util.Arrays;

/**
 * Reorders a batch of Spring3D, Damper3D or SpringDamper3D links into an irregular part (kept in
 * insertion order, stepped with index arrays) followed by {@link StencilRun}s. Links are grouped by their
 * slot offset {@code o = b - a} (endpoints are swapped so that o &gt; 0; a spring's force is symmetric);
 * a group's links whose lower slots form a dense range become a run. The result is deterministic: it
 * depends only on the set of links and their insertion order.
 */
final class StencilPlanner {
    /** Fewest links for a run: below this the index-array loop is as fast. */
    static final int MIN_RUN = 32;
    /** Largest gap between consecutive lower slots inside a run (filled with placeholders). */
    static final int MAX_GAP = 4;
    /**
     * Largest model (in masses) stepped with stencil runs in their two-pass form ({@link Engine#setStencilSweeps}
     * off). Two-pass runs trade extra memory traffic (scratch arrays, per-slot parameters, a second pass over the
     * forces) for vectorised arithmetic: a win while the model sits in the core's caches, a loss once it streams
     * from memory (measured: a 100x100 sheet is 1.3x faster with runs, a 150x150 sheet 1.15x slower). Runs
     * stepped in one sweep have no such limit.
     */
    static final int MAX_MASSES = 16_384;
    /** Smallest share of real links among the run's slots. */
    static final double MIN_DENSITY = 0.7;

    private StencilPlanner() {
    }

    static boolean eligible(LinkKind k) {
        return k == LinkKind.SPRING3D || k == LinkKind.DAMPER3D || k == LinkKind.SPRING_DAMPER3D;
    }

    /**
     * Returns a batch with the same links, reordered as irregular links then runs. Links are ordered by
     * (offset, lower slot, insertion index) with two stable counting sorts, so any slot and link count that
     * fits an int is handled (no bit packing, hence no limit at 2^21 masses).
     */
    static LinkBatch organize(LinkBatch in) {
        int n = in.n;
        if (n < MIN_RUN) {
            return in;
        }
        int[] offset = new int[n];
        int[] low = new int[n];
        int slots = 0;
        for (int j = 0; j < n; j++) {
            low[j] = Math.min(in.a[j], in.b[j]);
            offset[j] = Math.abs(in.b[j] - in.a[j]);
            slots = Math.max(slots, Math.max(in.a[j], in.b[j]) + 1);
        }
        int[] order = new int[n];
        for (int j = 0; j < n; j++) {
            order[j] = j;
        }
        order = stableSortBy(stableSortBy(order, low, slots), offset, slots);
        boolean[] inRun = new boolean[n];
        int[] runStart = new int[16];
        int[] runEnd = new int[16];
        int runs = 0;
        int q = 0;
        while (q < n) {
            int o = offset[order[q]];
            int r = q + 1;
            int last = low[order[q]];
            while (r < n && offset[order[r]] == o && low[order[r]] - last <= MAX_GAP && low[order[r]] != last) {
                last = low[order[r]];
                r++;
            }
            int count = r - q;
            int span = last - low[order[q]] + 1;
            if (o > 0 && count >= MIN_RUN && count >= MIN_DENSITY * span) {
                if (runs == runStart.length) {
                    runStart = Arrays.copyOf(runStart, runs * 2);
                    runEnd = Arrays.copyOf(runEnd, runs * 2);
                }
                runStart[runs] = q;
                runEnd[runs] = r;
                runs++;
                for (int t = q; t < r; t++) {
                    inRun[order[t]] = true;
                }
            }
            q = r;
        }
        if (runs == 0) {
            return in;
        }
        LinkBatch out = new LinkBatch(in.kind, n);
        int w = 0;
        for (int j = 0; j < n; j++) {
            if (!inRun[j]) {
                copy(in, j, out, w++);
            }
        }
        out.nIrregular = w;
        out.runs = new StencilRun[runs];
        for (int r = 0; r < runs; r++) {
            int first = low[order[runStart[r]]];
            int lastLo = low[order[runEnd[r] - 1]];
            int o = offset[order[runStart[r]]];
            StencilRun run = new StencilRun(first, lastLo + 1, o);
            out.runs[r] = run;
            for (int t = runStart[r]; t < runEnd[r]; t++) {
                int j = order[t];
                int lo = low[j];
                copy(in, j, out, w);
                out.a[w] = lo;
                out.b[w] = lo + o;
                out.runOf[w] = r;
                w++;
            }
        }
        return out;
    }

    /** @return the indices of {@code order} stably sorted by {@code key[index]}, each key in [0, range). */
    private static int[] stableSortBy(int[] order, int[] key, int range) {
        int[] start = new int[range + 1];
        for (int j : order) {
            start[key[j] + 1]++;
        }
        for (int k = 0; k < range; k++) {
            start[k + 1] += start[k];
        }
        int[] out = new int[order.length];
        for (int j : order) {
            out[start[key[j]]++] = j;
        }
        return out;
    }

    private static void copy(LinkBatch in, int j, LinkBatch out, int w) {
        out.id[w] = in.id[j];
        out.a[w] = in.a[j];
        out.b[w] = in.b[j];
    }
}
