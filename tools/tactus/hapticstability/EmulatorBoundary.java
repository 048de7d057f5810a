package tactus.hapticstability;

/**
 * Finds the largest stable wall stiffness in the emulator by bisection on K, each probe one {@link WallRig} run
 * judged by {@link Touch}: a two-sided spring without a hand (growth of the oscillation after a step) or a
 * one-sided wall pressed by the configured hand (residual oscillation during the hold).
 */
public final class EmulatorBoundary {
    /** End of the press scenario's slow press-in (seconds of simulated time), where the felt stiffness is read. */
    public static final double PRESS_END = 0.35;
    /** The press scenario's hold window (seconds of simulated time) in which the residual is read. */
    public static final double HOLD_FROM = 0.85;
    /** End of the hold window. */
    public static final double HOLD_TO = 1.35;

    private EmulatorBoundary() {
    }

    /** True if this configuration's run is stable. */
    public static boolean stable(WallRig.Config c) {
        WallRig.Trace t = WallRig.run(c);
        return judge(c, t).stable;
    }

    /** Judges a run of this configuration. */
    public static Touch judge(WallRig.Config c, WallRig.Trace t) {
        return c.wall == WallRig.Wall.SPRING ? Touch.ofSpring(c, t) : Touch.ofPress(c, t, PRESS_END, HOLD_FROM, HOLD_TO);
    }

    /**
     * The boundary K (N/m) between lo and hi by bisection to a relative tolerance; lo is widened down and hi up
     * (by factors of 2, at most 8 times) until lo is stable and hi is not. NaN if no bracket was found.
     */
    public static double find(WallRig.Config base, double lo, double hi, double tol) {
        WallRig.Config c = base.copy();
        for (int i = 0; i < 8; i++) {
            c.stiffness = lo;
            if (stable(c)) {
                break;
            }
            lo /= 2;
            if (i == 7) {
                return Double.NaN;
            }
        }
        for (int i = 0; i < 8; i++) {
            c.stiffness = hi;
            if (!stable(c)) {
                break;
            }
            hi *= 2;
            if (i == 7) {
                return Double.POSITIVE_INFINITY;
            }
        }
        while (hi - lo > tol * hi) {
            c.stiffness = 0.5 * (lo + hi);
            if (stable(c)) {
                lo = c.stiffness;
            } else {
                hi = c.stiffness;
            }
        }
        return 0.5 * (lo + hi);
    }

    /**
     * The largest K = multiple * unit of an increasing list that is stable with every smaller one stable too; 0 if the
     * first is unstable, and the last multiple's K (a lower bound) if none is.
     */
    public static double lastStable(WallRig.Config base, double[] multiples, double unit) {
        WallRig.Config c = base.copy();
        double last = 0;
        for (double m : multiples) {
            c.stiffness = m * unit;
            if (!stable(c)) {
                return last;
            }
            last = c.stiffness;
        }
        return last;
    }
}
