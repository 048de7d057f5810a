package tactus.internal.realtime;

import java.lang.invoke.VarHandle;
import java.util.Arrays;
import tactus.engine.Engine;
import tactus.engine.MassKind;

/**
 * How threads other than the stepping thread read an avatar's accumulated force ({@link
 * PhysicalModel#getHapticForce(String, Vect3D)}) while the model is stepped in realtime, without waiting for it:
 * after each stepping call the owner moves the engine's accumulator of every tapped input module into running sums,
 * under a sequence lock it alone writes; a reader takes the difference between the sums and what it read last time.
 * So the force of every step reaches exactly one read (none is lost or counted twice), as with the locked call,
 * and the reader sees the steps up to the owner's latest stepping call.
 */
public final class ForceTaps {
    /** One tapped input module. */
    public static final class Tap {
        final int id;
        /** Written by the owner only, odd while it writes. */
        volatile long seq;
        double sx, sy, sz;
        /** Written by the owner only: how many steps the sums cover. */
        long sn;
        /** The reader's last consistent copy of the sums; touched under the model's lock only. */
        double rx, ry, rz;
        long rn;

        Tap(int id) {
            this.id = id;
        }
    }

    private volatile Tap[] taps = new Tap[0];
    private final double[] tmp = new double[3];

    /** @return the tap of an input module, or null if no other thread has read its force yet. Any thread. */
    public Tap find(int id) {
        for (Tap t : taps) {
            if (t.id == id) {
                return t;
            }
        }
        return null;
    }

    /** @return the tap of an input module, created on first use. The caller holds the model's lock. */
    public Tap tap(int id) {
        for (Tap t : taps) {
            if (t.id == id) {
                return t;
            }
        }
        Tap t = new Tap(id);
        Tap[] next = Arrays.copyOf(taps, taps.length + 1);
        next[next.length - 1] = t;
        taps = next;
        return t;
    }

    /** Moves the force accumulated on every tapped module into its sums. The owner calls it after each stepping call. */
    public void collect(Engine e) {
        Tap[] ts = taps;
        for (Tap t : ts) {
            if (!e.isMass(t.id)) {
                continue;
            }
            long n = e.takeForce(t.id, tmp);
            long s = t.seq;
            t.seq = s + 1;
            VarHandle.storeStoreFence();
            t.sx += tmp[0];
            t.sy += tmp[1];
            t.sz += tmp[2];
            t.sn += n;
            t.seq = s + 2;
        }
    }

    /**
     * Writes the force (model units, summed over the steps) accumulated since the previous read into {@code out},
     * and returns how many steps it covers, read together with it. Retries while the owner is writing (a few
     * nanoseconds); the caller holds the model's lock, or is the owner.
     */
    public long take(Engine e, Tap t, double[] out) {
        double x, y, z;
        long n;
        while (true) {
            long s1 = t.seq;
            x = t.sx;
            y = t.sy;
            z = t.sz;
            n = t.sn;
            VarHandle.loadLoadFence();
            if ((s1 & 1) == 0 && s1 == t.seq) {
                break;
            }
            Thread.onSpinWait();
        }
        out[0] = x - t.rx;
        out[1] = y - t.ry;
        out[2] = z - t.rz;
        long steps = n - t.rn;
        t.rx = x;
        t.ry = y;
        t.rz = z;
        t.rn = n;
        if (e.massKind(t.id) == MassKind.POS_INPUT3D) {
            out[0] = 0;
            out[1] = 0;
            out[2] = 0;
        }
        return steps;
    }

    public boolean isEmpty() {
        return taps.length == 0;
    }
}
