package tactus.engine;

import java.util.Arrays;

/**
 * Parameters of every mass ever added, indexed by a stable id that is never reused.
 * Positions of masses that are not compiled yet are kept here as pending state; once a
 * mass is compiled its live state is in the {@link StepPlan} slot given by {@link #slot}.
 */
final class MassTable {
    int count;
    MassKind[] kind = new MassKind[16];
    boolean[] alive = new boolean[16];
    int[] slot = new int[16];
    double[] mass = new double[16];
    double[] stiffness = new double[16];
    double[] damping = new double[16];
    double[] weight = new double[16];
    double[] rest = new double[48];
    double[] pending = new double[96];
    /** Forces added to masses that have no plan slot yet (3 per id); the next compile moves them into the plan. */
    double[] pendingForce = new double[48];
    /** Input targets set before a mass has a plan slot (3 per id); NaN when none was set. */
    double[] pendingTarget = new double[48];
    long[] lastTake = new long[16];
    /** The sum that {@code takeForce} last took (3 per id), and over how many steps it was summed (0: none yet). */
    double[] lastTaken = new double[48];
    long[] lastTakenSteps = new long[16];
    /** The user-facing kind of a mass under velocity control (its layout kind is then DRIVEN3D); null otherwise. */
    MassKind[] drivenFrom = new MassKind[16];
    /** The displacement per step imposed on a mass under velocity control (3 per id). */
    double[] drive = new double[48];

    int add(MassKind k, double m) {
        ensure(count + 1);
        int id = count++;
        kind[id] = k;
        alive[id] = true;
        slot[id] = -1;
        mass[id] = m;
        drivenFrom[id] = null;
        int q = 3 * id;
        pendingForce[q] = 0;
        lastTakenSteps[id] = 0;
        pendingForce[q + 1] = 0;
        pendingForce[q + 2] = 0;
        pendingTarget[q] = Double.NaN;
        pendingTarget[q + 1] = Double.NaN;
        pendingTarget[q + 2] = Double.NaN;
        return id;
    }

    void setPending(int id, double x, double y, double z, double px, double py, double pz) {
        int o = 6 * id;
        pending[o] = x;
        pending[o + 1] = y;
        pending[o + 2] = z;
        pending[o + 3] = px;
        pending[o + 4] = py;
        pending[o + 5] = pz;
    }

    void setRest(int id, double x, double y, double z) {
        rest[3 * id] = x;
        rest[3 * id + 1] = y;
        rest[3 * id + 2] = z;
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
        mass = Arrays.copyOf(mass, c);
        stiffness = Arrays.copyOf(stiffness, c);
        damping = Arrays.copyOf(damping, c);
        weight = Arrays.copyOf(weight, c);
        rest = Arrays.copyOf(rest, 3 * c);
        pending = Arrays.copyOf(pending, 6 * c);
        pendingForce = Arrays.copyOf(pendingForce, 3 * c);
        pendingTarget = Arrays.copyOf(pendingTarget, 3 * c);
        lastTake = Arrays.copyOf(lastTake, c);
        lastTaken = Arrays.copyOf(lastTaken, 3 * c);
        lastTakenSteps = Arrays.copyOf(lastTakenSteps, c);
        drivenFrom = Arrays.copyOf(drivenFrom, c);
        drive = Arrays.copyOf(drive, 3 * c);
    }

    /** @return the kind the user sees: the mass's own kind, also while it is under velocity control. */
    MassKind userKind(int id) {
        return drivenFrom[id] != null ? drivenFrom[id] : kind[id];
    }
}
