package tactus.haptics.loop;

import java.lang.invoke.VarHandle;
import java.util.concurrent.locks.LockSupport;
import tactus.haptics.AvatarLink;
import tactus.haptics.HapticLoop;
import tactus.haptics.PhysicalModelAvatar;

/**
 * An {@link AvatarLink} that never makes the haptic thread wait for the model: a helper thread does the
 * (possibly blocking) calls on the wrapped link, and the two threads meet through lock-free single-writer
 * channels. For {@link HapticLoop.Mode#AUDIO}, where the audio thread holds the model for a whole buffer
 * of steps at a time.
 *
 * <p>{@link #setTarget} publishes the target and wakes the helper, which passes it on and takes the force;
 * {@link #takeForce} returns everything the helper has collected since the previous call (forces are never
 * lost, at worst they arrive one tick later). {@link #step} calls the wrapped link directly. If the wrapped
 * link throws, the helper stops and every later {@link #takeForce} throws an {@link IllegalStateException}
 * that carries the model's exception (the haptic loop then sends zero torque and stops, naming it). Call
 * {@link #close()} to stop the helper thread. {@link HapticLoop} wraps its avatar in one by itself in
 * {@link HapticLoop.Mode#AUDIO}.
 */
public final class DecoupledAvatar implements AvatarLink, AutoCloseable {
    private final AvatarLink inner;
    private final Thread helper;
    private volatile boolean running = true;

    // target: written by the haptic thread, read by the helper (seqlock)
    private volatile long targetSeq;
    private double tx;
    private double ty;
    private double tz;

    // cumulative force: written by the helper, read by the haptic thread (seqlock)
    private volatile long forceSeq;
    private double cx;
    private double cy;
    private double cz;
    private long cs;                        // steps covered by the sums
    private volatile boolean stepsUnknown;  // the wrapped link cannot count its steps

    // haptic thread only: the totals already handed out
    private double takenX;
    private double takenY;
    private double takenZ;
    private long takenS;

    private volatile long exchanges;
    private volatile long busyReads;
    private static final int MAX_TRIES = 64;
    private volatile RuntimeException failure;

    /** Wraps a link (typically a {@link PhysicalModelAvatar}) and starts the helper thread. */
    public DecoupledAvatar(AvatarLink inner) {
        if (inner == null) {
            throw new IllegalArgumentException("DecoupledAvatar: inner link must not be null");
        }
        this.inner = inner;
        this.helper = new Thread(this::serve, "tactus-avatar-exchange");
        helper.setDaemon(true);
        helper.start();
    }

    @Override
    public void setTarget(double x, double y, double z) {
        long s = targetSeq;
        targetSeq = s + 1;          // odd: writing
        VarHandle.storeStoreFence();
        tx = x;
        ty = y;
        tz = z;
        targetSeq = s + 2;          // even: done
        LockSupport.unpark(helper);
    }

    @Override
    public void takeForce(double[] out) {
        takeForceCounted(out);
    }

    /** Everything collected since the previous call, and the model steps it covers (-1 if the link cannot tell). */
    @Override
    public long takeForceCounted(double[] out) {
        RuntimeException failed = failure;
        if (failed != null) {
            throw new IllegalStateException("the model failed on the avatar exchange thread: " + failed, failed);
        }
        double x;
        double y;
        double z;
        long steps;
        int tries = 0;
        while (true) {
            long s1 = forceSeq;
            if ((s1 & 1) == 0) {
                x = cx;
                y = cy;
                z = cz;
                steps = cs;
                VarHandle.loadLoadFence();
                if (forceSeq == s1) {
                    break;
                }
            }
            if (++tries == MAX_TRIES) {
                // The helper was preempted while writing (it runs at normal priority, this thread perhaps
                // not): never wait for it. Nothing new this time; the running sums lose nothing, the next
                // call takes it all.
                busyReads++;
                out[0] = 0;
                out[1] = 0;
                out[2] = 0;
                return stepsUnknown ? -1 : 0;
            }
            Thread.onSpinWait();
        }
        out[0] = x - takenX;
        out[1] = y - takenY;
        out[2] = z - takenZ;
        takenX = x;
        takenY = y;
        takenZ = z;
        long n = steps - takenS;
        takenS = steps;
        return stepsUnknown ? -1 : n;
    }

    @Override
    public void step(int n) {
        inner.step(n);
    }

    /**
     * Number of {@link #takeForceCounted} calls that found the helper in the middle of publishing and returned
     * nothing new rather than wait for it.
     */
    public long busyReads() {
        return busyReads;
    }

    /** Number of target/force exchanges the helper has made with the wrapped link. */
    public long exchanges() {
        return exchanges;
    }

    /** Stops the helper thread. */
    @Override
    public void close() {
        running = false;
        LockSupport.unpark(helper);
        try {
            helper.join(1000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    private void serve() {
        double[] f = new double[3];
        long seen = 0;
        long steps = 0;
        while (running) {
            long s = targetSeq;
            if (s == seen || (s & 1) != 0) {
                LockSupport.parkNanos(1_000_000);
                continue;
            }
            double x = tx;
            double y = ty;
            double z = tz;
            VarHandle.loadLoadFence();
            if (targetSeq != s) {
                continue;           // torn: read again
            }
            seen = s;
            try {
                inner.setTarget(x, y, z);
                long n = inner.takeForceCounted(f);
                if (n < 0) {
                    stepsUnknown = true;
                    n = 0;
                }
                steps = n;
            } catch (RuntimeException e) {
                failure = e;        // the next takeForce throws: the loop sends zero torque and stops
                exchanges++;
                return;
            }
            long fs = forceSeq;
            forceSeq = fs + 1;
            VarHandle.storeStoreFence();
            cx += f[0];
            cy += f[1];
            cz += f[2];
            cs += steps;
            forceSeq = fs + 2;
            exchanges++;
        }
    }
}
