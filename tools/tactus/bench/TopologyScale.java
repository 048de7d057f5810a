package tactus.bench;

import tactus.PhysicalModel;
import tactus.Vect3D;

/**
 * Times topology edits at scale: removing k masses one by one from an N-mass chain, then stepping 10 steps; and
 * removing masses from a model with many subsets; 10 steps of the chain on one thread and on two. Prints one line per case, in seconds (the machine's load is the
 * caller's to report). Arguments: {@code [N] [k] [subsets] [removedFromSubsets]}, default 1000000 100 100000 200.
 */
public final class TopologyScale {
    private TopologyScale() {
    }

    /** Runs the cases and prints their times. */
    public static void main(String[] args) {
        int n = args.length > 0 ? Integer.parseInt(args[0]) : 1_000_000;
        int k = args.length > 1 ? Integer.parseInt(args[1]) : 100;
        int subsets = args.length > 2 ? Integer.parseInt(args[2]) : 100_000;
        int removed = args.length > 3 ? Integer.parseInt(args[3]) : 200;
        PhysicalModel pm = chain(n);
        long t0 = System.nanoTime();
        for (int i = 0; i < k; i++) {
            pm.removeMatAndConnectedLinks("m" + (1 + i * (n / (k + 1))));
        }
        pm.computeNSteps(10);
        System.out.printf("removing %d masses one by one from a %d-mass chain, then 10 steps: %.2f s%n", k, n,
                (System.nanoTime() - t0) * 1e-9);
        PhysicalModel ps = chain(subsets);
        for (int s = 0; s < subsets; s++) {
            ps.createMatSubset("s" + s);
            ps.addMatToSubset("m" + s, "s" + s);
        }
        t0 = System.nanoTime();
        for (int i = 0; i < removed; i++) {
            ps.removeMatAndConnectedLinks("m" + (1 + i * (subsets / (removed + 1))));
        }
        ps.computeNSteps(10);
        System.out.printf("%d subsets, removing %d masses one by one, then 10 steps: %.2f s%n", subsets, removed,
                (System.nanoTime() - t0) * 1e-9);
        for (int threads : new int[] {1, 2}) {
            pm.setThreads(threads);
            pm.computeNSteps(2);
            t0 = System.nanoTime();
            pm.computeNSteps(10);
            System.out.printf("10 steps of %d masses on %d thread(s): %.2f s%n", pm.getNumberOfMats(), threads,
                    (System.nanoTime() - t0) * 1e-9);
        }
        pm.setThreads(1);
    }

    /** A chain of n masses on springs, initialised. */
    static PhysicalModel chain(int n) {
        PhysicalModel pm = new PhysicalModel(1000);
        for (int i = 0; i < n; i++) {
            pm.addMass3D("m" + i, 1, new Vect3D(i, 0, 0), new Vect3D());
        }
        for (int i = 1; i < n; i++) {
            pm.addSpringDamper3D("l" + i, 1, 0.01, 0.001, "m" + (i - 1), "m" + i);
        }
        pm.init();
        return pm;
    }
}
