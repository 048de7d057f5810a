package tactus.audio;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import tactus.PhysicalModel;
import tactus.Vect3D;

/**
 * No clicks when the avatar touches or leaves the string. A haptic thread, simulated in step with the
 * audio (a 1 kHz staircase through the AvatarExchange), drives the avatar down through the string next to
 * mass 10, so it touches the string, drags it, slips past (the pluck) and leaves. The PhyUGen listens to
 * mass 10's y displacement u with gain g and the DC blocker off (a fixed linear filter, tested elsewhere),
 * so the output is y = g u.
 *
 * <p>The bound. The scheme is x(n+1) = 2 x(n) - x(n-1) + F(n) / M, so the third difference of the output is
 * g (F(n-1) - F(n-2)) / M: a click is a force that jumps. On mass 10 act two tensioned springs (rest L0 &lt;
 * distance d, no damping), whose force is K-Lipschitz in the positions while d &gt; L0 / 2, and the contact
 * with the avatar, f = K_c (r - d) - Z_c (d(n) - d(n-1)) along the line of centres while d &lt; r. The contact
 * force is continuous where it switches on or off: on the step it engages, d(n-1) &ge; r &gt; d(n), so
 * r - d(n) &le; |d(n) - d(n-1)|. From the measured velocities v (per step) of the masses and the avatar:
 * <pre>
 * |dF_springs| &le; K sum over the two neighbours j of (|v_10| + |v_j|)
 * |dF_contact| &le; (K_c + Z_c) |dd(n)| + Z_c |dd(n-1)| + |f(n-1)| (|v_10| + |v_avatar|) / d(n)   (direction change)
 * </pre>
 * with |dd| &le; |v_10| + |v_avatar|. The test checks |third difference of y| &le; g (that sum) / M at every
 * sample: an impulsive force at touch or release (a contact picking up a spurious velocity, an avatar that
 * jumps without its EWMA reaching the force) or a glitch in the audio path breaks it. A control run with a
 * sudden gain change (a real click) shows the check catches it.
 */
class ContactClickTest {
    static final int RATE = 44100;
    static final double GAIN = 10;
    static final double R = 0.05;
    static final double KC = 0.01;
    static final double ZC = 0.001;

    private static final class Run {
        int n;
        float[] y;
        double[][] p9;
        double[][] p10;
        double[][] p11;
        double[][] avatar;
        double[] d;
        int touches;
        int releases;
    }

    private static Run pluckThrough(Double gainStepAt) {
        PhysicalModel pm = new PhysicalModel(RATE);
        StringModel.build(pm, 7, 0);
        pm.addHapticInput3D("avatar", new Vect3D(1.03, 0.15, 0), 30);
        for (int i = 1; i <= StringModel.N; i++) {
            pm.addContact3D("c" + i, R, KC, ZC, "avatar", StringModel.mass(i));
        }
        pm.init();
        PhyUGen u = new PhyUGen(pm);
        u.setBlockSize(1);   // the test reads the model after each sample: the per-sample path
        u.setDcBlockerEnabled(false);
        ListeningPoint point = u.listenToMass(StringModel.mass(10), SteppedModel.Y, GAIN, 0);
        AvatarExchange ex = new AvatarExchange();
        u.attachAvatar("avatar", ex);
        u.setSampleRate(RATE);
        u.setChannelCount(1);
        Run run = new Run();
        run.n = (int) (0.5 * RATE);
        run.y = new float[run.n];
        run.p9 = new double[run.n][];
        run.p10 = new double[run.n][];
        run.p11 = new double[run.n][];
        run.avatar = new double[run.n][];
        run.d = new double[run.n];
        float[] frame = new float[1];
        double[] force = new double[3];
        double hapticClock = 0;
        Vect3D v = new Vect3D();
        for (int i = 0; i < run.n; i++) {
            double t = i / (double) RATE;
            if (t >= hapticClock) {
                // the device goes from y = 0.15 to y = -0.15 in 0.3 s, then rests there
                double y = 0.15 - 0.3 * Math.min(1, t / 0.3);
                ex.publishPosition(1.03, y, 0);
                ex.takeForce(force);
                hapticClock += 0.001;
            }
            if (gainStepAt != null && i == (int) (gainStepAt * RATE)) {
                point.setGain(3 * GAIN);
            }
            u.tick(frame);
            run.y[i] = frame[0];
            run.p9[i] = xyz(pm.getMatPosition(StringModel.mass(9), v));
            run.p10[i] = xyz(pm.getMatPosition(StringModel.mass(10), v));
            run.p11[i] = xyz(pm.getMatPosition(StringModel.mass(11), v));
            run.avatar[i] = xyz(pm.getMatPosition("avatar", v));
            run.d[i] = pm.getLinkDistance("c10");
            if (i > 0 && run.d[i] < R && run.d[i - 1] >= R) {
                run.touches++;
            }
            if (i > 0 && run.d[i] >= R && run.d[i - 1] < R) {
                run.releases++;
            }
        }
        return run;
    }

    private static double[] xyz(Vect3D v) {
        return new double[] {v.x, v.y, v.z};
    }

    private static double speed(double[][] p, int k) {
        double dx = p[k][0] - p[k - 1][0];
        double dy = p[k][1] - p[k - 1][1];
        double dz = p[k][2] - p[k - 1][2];
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }

    /** Upper bound on |F(k) - F(k-1)| on mass 10, from measured motion only. */
    private static double forceChangeBound(Run r, int k) {
        double v10 = speed(r.p10, k);
        double springs = StringModel.K * (2 * v10 + speed(r.p9, k) + speed(r.p11, k));
        double rel = v10 + speed(r.avatar, k);
        double relBefore = v10 + speed(r.avatar, k - 1) + speed(r.p10, k - 1);
        boolean activeNow = r.d[k] < R;
        boolean activeBefore = r.d[k - 1] < R;
        double contact = 0;
        if (activeNow || activeBefore) {
            double fBefore = activeBefore ? KC * (R - r.d[k - 1]) + ZC * Math.abs(r.d[k - 1] - r.d[k - 2]) : 0;
            contact = (KC + ZC) * rel + ZC * relBefore + fBefore * rel / Math.min(r.d[k], r.d[k - 1]);
        }
        return springs + contact;
    }

    /** @return the first sample whose output jerk exceeds the bound, or -1. */
    private static int firstClick(Run r) {
        for (int i = 4; i < r.n; i++) {
            double jerk = Math.abs(r.y[i] - 3.0 * r.y[i - 1] + 3.0 * r.y[i - 2] - r.y[i - 3]);
            double bound = GAIN * forceChangeBound(r, i - 1) / StringModel.M;
            // float output: allow a few ulps of |y|
            double slack = 1e-6 * (Math.abs(r.y[i]) + Math.abs(r.y[i - 1]) + Math.abs(r.y[i - 2]) + Math.abs(r.y[i - 3]))
                    + 1e-9;
            if (jerk > bound * (1 + 1e-9) + slack) {
                return i;
            }
        }
        return -1;
    }

    @Test
    void touchingAndLeavingTheStringDoesNotClick() {
        Run run = pluckThrough(null);
        assertTrue(run.touches >= 1 && run.releases >= 1, "the avatar touched (" + run.touches + ") and left ("
                + run.releases + ") the string");
        double peak = 0;
        for (float y : run.y) {
            peak = Math.max(peak, Math.abs(y));
        }
        assertTrue(peak > 0.01, "the string was dragged and plucked: peak " + peak);
        assertEquals(-1, firstClick(run));
    }

    /** The check has teeth: a sudden gain change (a real click) is caught where it happens. */
    @Test
    void aGainStepIsCaughtAsAClick() {
        Run run = pluckThrough(0.4);
        int click = firstClick(run);
        assertTrue(click >= (int) (0.4 * RATE) && click <= (int) (0.4 * RATE) + 3, "the gain step at sample "
                + (int) (0.4 * RATE) + " is caught (first click found at " + click + ")");
    }
}
