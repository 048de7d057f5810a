package tactus.internal.realtime;

import java.util.Arrays;
import tactus.engine.Engine;
import tactus.internal.model.EngineWrites;
import tactus.internal.ModelCore;

/**
 * A prepared parameter or state change: the engine writes a facade call made, already validated and converted to
 * per-step units on the calling thread, recorded as flat arrays. Applying it replays the writes in order: no
 * allocation, no lock, cost proportional to the change.
 */
public final class WriteBatch extends Command implements EngineWrites {
    private static final int MASS = 0, OSC = 1, LINK = 2, PLANE = 3, ATTR = 4, POS = 5, STATE = 6, FORCE = 7,
            TARGET = 8, MEDIUM = 9, VELOCITY = 10, POS_KEEP = 11, AUX = 12;
    private final double[] tmp = new double[3];
    private int[] ops = new int[4];
    private int[] ids = new int[4];
    private double[] v = new double[24];
    private int n;

    /** @return true when the batch changes a parameter or the medium (not only the state). */
    public boolean changesParameters() {
        for (int i = 0; i < n; i++) {
            if (ops[i] <= ATTR || ops[i] == MEDIUM || ops[i] == AUX) {
                return true;
            }
        }
        return false;
    }

    public boolean isEmpty() {
        return n == 0;
    }

    /** @return the number of writes recorded. */
    public int size() {
        return n;
    }

    /**
     * Records an op and returns where its values go in {@link #v}. Callers take the index first and index {@code v}
     * after: {@code v[add(...)] = x} would read the field before the call grows it and write into the old array.
     */
    private int add(int op, int id) {
        if (n == ops.length) {
            ops = Arrays.copyOf(ops, 2 * n);
            ids = Arrays.copyOf(ids, 2 * n);
            v = Arrays.copyOf(v, 12 * n);
        }
        ops[n] = op;
        ids[n] = id;
        return 6 * n++;
    }

    public void setMass(int id, double m) {
        int at = add(MASS, id);
        v[at] = m;
    }

    public void setOscillator(int id, double k, double z) {
        int at = add(OSC, id);
        v[at] = k;
        v[at + 1] = z;
    }

    public void setLinkParams(int id, double k, double z, double len) {
        int at = add(LINK, id);
        v[at] = k;
        v[at + 1] = z;
        v[at + 2] = len;
    }

    public void setPlanePosition(int id, double pos) {
        int at = add(PLANE, id);
        v[at] = pos;
    }

    public void setAttraction(int id, double attr) {
        int at = add(ATTR, id);
        v[at] = attr;
    }

    public void setLinkAux(int id, int index, double value) {
        int at = add(AUX, id);
        v[at] = index;
        v[at + 1] = value;
    }

    public void setPosition(int id, double x, double y, double z) {
        put3(add(POS, id), x, y, z);
    }

    public void setPositionKeepingLinkHistory(int id, double x, double y, double z) {
        put3(add(POS_KEEP, id), x, y, z);
    }

    public void setState(int id, double x, double y, double z, double px, double py, double pz) {
        int at = add(STATE, id);
        put3(at, x, y, z);
        put3(at + 3, px, py, pz);
    }

    public void setVelocity(int id, double dx, double dy, double dz) {
        put3(add(VELOCITY, id), dx, dy, dz);
    }

    public void addForce(int id, double fx, double fy, double fz) {
        put3(add(FORCE, id), fx, fy, fz);
    }

    public void setInputTarget(int id, double x, double y, double z) {
        put3(add(TARGET, id), x, y, z);
    }

    public void setMedium(double gx, double gy, double gz, double friction) {
        int at = add(MEDIUM, -1);
        put3(at, gx, gy, gz);
        v[at + 3] = friction;
    }

    private static double keep(double value, double current) {
        return Double.isNaN(value) ? current : value;
    }

    private void put3(int at, double a, double b, double c) {
        v[at] = a;
        v[at + 1] = b;
        v[at + 2] = c;
    }

    /**
     * Replays the writes in order. A write to a module removed since the call was made is skipped (the module's id is
     * never reused, so nothing else is written in its place).
     *
     * @return true when every write was applied, false when some were skipped
     */
    @Override
    public boolean apply(ModelCore core) {
        Engine e = core.engine;
        boolean full = true;
        for (int i = 0; i < n; i++) {
            int id = ids[i];
            int at = 6 * i;
            int op = ops[i];
            if (op != MEDIUM && !(op == LINK || op == PLANE || op == ATTR || op == AUX ? e.isLink(id) : e.isMass(id))) {
                full = false;
                continue;
            }
            switch (op) {
                case MASS:
                    e.setMass(id, v[at]);
                    break;
                case OSC:
                    e.setOscillator(id, keep(v[at], e.oscStiffness(id)), keep(v[at + 1], e.oscDamping(id)));
                    break;
                case LINK:
                    e.setLinkParams(id, keep(v[at], e.linkStiffness(id)), keep(v[at + 1], e.linkDamping(id)),
                            keep(v[at + 2], e.linkLength(id)));
                    break;
                case VELOCITY:
                    e.position(id, tmp);
                    e.setState(id, tmp[0], tmp[1], tmp[2], tmp[0] - v[at], tmp[1] - v[at + 1], tmp[2] - v[at + 2]);
                    break;
                case PLANE:
                    e.setPlanePosition(id, v[at]);
                    break;
                case AUX:
                    e.setLinkAux(id, (int) v[at], v[at + 1]);
                    break;
                case ATTR:
                    e.setAttraction(id, v[at]);
                    break;
                case POS:
                    e.setPosition(id, v[at], v[at + 1], v[at + 2]);
                    break;
                case POS_KEEP:
                    e.setPositionKeepingLinkHistory(id, v[at], v[at + 1], v[at + 2]);
                    break;
                case STATE:
                    e.setState(id, v[at], v[at + 1], v[at + 2], v[at + 3], v[at + 4], v[at + 5]);
                    break;
                case FORCE:
                    e.addForce(id, v[at], v[at + 1], v[at + 2]);
                    break;
                case TARGET:
                    e.setInputTarget(id, v[at], v[at + 1], v[at + 2]);
                    break;
                default:
                    e.setGravity(v[at], v[at + 1], v[at + 2]);
                    e.setFriction(v[at + 3]);
                    break;
            }
        }
        return full;
    }
}
