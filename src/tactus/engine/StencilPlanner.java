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
     * Largest model (in masses) stepped with stencil runs. Runs trade extra memory traffic (scratch arrays,
     * per-slot parameters) for vectorised arithmetic: a win while the model sits in the core's caches, a loss
     * once it streams from memory (measured: a 100x100 sheet is 1.3x faster with runs, a 150x150 sheet 1.15x
     * slower).
     */
    static final int MAX_MASSES = 16_384;
    /** Smallest share of real links among the run's slots. */
    static final double MIN_DENSITY = 0.7;

    private StencilPlanner() {
    }

    static boolean eligible(LinkKind k) {
        return k == LinkKind.SPRING3D || k == LinkKind.DAMPER3D || k == LinkKind.SPRING_DAMPER3D;
    }

    /** Returns a batch with the same links, reordered as irregular links then runs. */
    static LinkBatch organize(LinkBatch in) {
        int n = in.n;
        long[] keys = new long[n];
        for (int j = 0; j < n; j++) {
            int lo = Math.min(in.a[j], in.b[j]);
            int o = Math.abs(in.b[j] - in.a[j]);
            keys[j] = ((long) o << 42) | ((long) lo << 21) | j;
        }
        if (n < MIN_RUN || n >= (1 << 21)) {
            return in;
        }
        Arrays.sort(keys);
        boolean[] inRun = new boolean[n];
        int[] runStart = new int[16];
        int[] runEnd = new int[16];
        int runs = 0;
        int q = 0;
        while (q < n) {
            int o = (int) (keys[q] >>> 42);
            int r = q + 1;
            int last = lo(keys[q]);
            while (r < n && (int) (keys[r] >>> 42) == o && lo(keys[r]) - last <= MAX_GAP && lo(keys[r]) != last) {
                last = lo(keys[r]);
                r++;
            }
            int count = r - q;
            int span = last - lo(keys[q]) + 1;
            if (o > 0 && count >= MIN_RUN && count >= MIN_DENSITY * span) {
                if (runs == runStart.length) {
                    runStart = Arrays.copyOf(runStart, runs * 2);
                    runEnd = Arrays.copyOf(runEnd, runs * 2);
                }
                runStart[runs] = q;
                runEnd[runs] = r;
                runs++;
                for (int t = q; t < r; t++) {
                    inRun[(int) (keys[t] & 0x1FFFFF)] = true;
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
            int first = lo(keys[runStart[r]]);
            int lastLo = lo(keys[runEnd[r] - 1]);
            int o = (int) (keys[runStart[r]] >>> 42);
            StencilRun run = new StencilRun(first, lastLo + 1, o);
            out.runs[r] = run;
            for (int t = runStart[r]; t < runEnd[r]; t++) {
                int j = (int) (keys[t] & 0x1FFFFF);
                int lo = lo(keys[t]);
                copy(in, j, out, w);
                out.a[w] = lo;
                out.b[w] = lo + o;
                out.runOf[w] = r;
                w++;
            }
        }
        return out;
    }

    private static int lo(long key) {
        return (int) ((key >>> 21) & 0x1FFFFF);
    }

    private static void copy(LinkBatch in, int j, LinkBatch out, int w) {
        out.id[w] = in.id[j];
        out.a[w] = in.a[j];
        out.b[w] = in.b[j];
    }
}
