package tactus.hapticstability;

import java.util.Locale;
import tactus.haptics.emulator.Hand;

/**
 * One scripted scene of the adversarial suite (docs/haptics-stability.md, "The adversarial suite"): a grasp on the
 * emulated 2DIY's handle meets a one-sided wall along y, and the scene may change the wall or the hand while the
 * handle is inside. Times are seconds of simulated time since the run's start, positions metres below the start pose.
 * Immutable; the scene's script and windows follow from its kind, speed and shift.
 */
public final class AdversarialCase {
    /** What the scene does. */
    public enum Kind {
        /** The hand presses in at the case's speed to 3 mm past the surface (2 mm at 5 mm/s), holds 0.4 s, leaves. */
        PRESS,
        /** The hand taps: in at the case's speed to 3 mm past the surface, 30 ms there, out at the same speed. */
        TAP,
        /** The hand rests 3 mm past a wall of stiffness 0, then the wall's stiffness is set to K. */
        SWITCH_ON,
        /** The hand rests 3 mm past where the wall will be; the wall, 6 mm further away, is moved there. */
        MOVE_IN,
        /** The hand presses into a 20 K0 wall and holds; the wall's stiffness is set to K. */
        STIFFEN,
        /** The hand presses into the wall and holds; then it lets go (no hand from then on). */
        RELEASE
    }

    /** A grasp: a name and the hand's lumped mass (kg), stiffness (N/m) and damping (N s/m). */
    public enum Grip {
        /** Fingertips squeezing hard: the range's stiff, damped corner (an assumption). */
        STIFF_PINCH(0.02, 1000, 5),
        /** The pen grip of the sweep. */
        PEN(0.03, 300, 2),
        /** A light, loose hold: the range's lightest, softest, least damped corner (an assumption). */
        LOOSE_HOLD(0.01, 100, 1);

        /** Mass moving with the handle, kg. */
        public final double mass;
        /** Stiffness to the intended motion, N/m. */
        public final double stiffness;
        /** Damping on the velocity relative to the intended motion, N s/m. */
        public final double damping;

        Grip(double mass, double stiffness, double damping) {
            this.mass = mass;
            this.stiffness = stiffness;
            this.damping = damping;
        }
    }

    /** The uncontrolled bound of the 2DIY plant as assumed (theory, one tick of delay), N/m. */
    public static final double K0 = 40.7;
    /** The wall a STIFFEN scene starts from, N/m (20 K0). */
    public static final double STIFFEN_FROM = 20 * K0;
    /** How far past the surface the hand means to go, m. */
    static final double DEPTH = 0.003;

    /** The scene. */
    public final Kind kind;
    /** The grasp. */
    public final Grip grip;
    /** The wall's stiffness (N/m; for STIFFEN, the stiffness it is set to). */
    public final double stiffness;
    /** The hand's speed in and out (m/s; PRESS and TAP). */
    public final double speed;
    /** True if the plant has its (assumed) Coulomb friction, false for the frictionless plant. */
    public final boolean friction;
    /** The hand's script starts this much later (s): moves the contact's phase against the ticks. */
    public final double shift;

    /** A case; see the fields. */
    public AdversarialCase(Kind kind, Grip grip, double stiffness, double speed, boolean friction, double shift) {
        if (kind == null || grip == null) {
            throw new IllegalArgumentException("AdversarialCase: kind and grip must not be null");
        }
        if (!(stiffness >= 0) || !(speed > 0) || !(shift >= 0)) {
            throw new IllegalArgumentException("AdversarialCase: stiffness >= 0, speed > 0 and shift >= 0 needed, got "
                    + stiffness + ", " + speed + ", " + shift);
        }
        this.kind = kind;
        this.grip = grip;
        this.stiffness = stiffness;
        this.speed = speed;
        this.friction = friction;
        this.shift = shift;
    }

    /** The wall's surface below the start, m (where it ends up for MOVE_IN). */
    public double gap() {
        switch (kind) {
            case PRESS:
                return speed < 0.01 ? 0.0005 : 0.001;
            case TAP:
                return 0.002;
            default:
                return 0.002;
        }
    }

    /** Where the wall starts below the start pose, m. */
    public double initialGap() {
        return kind == Kind.MOVE_IN ? gap() + 0.006 : gap();
    }

    /** The wall's stiffness when the run starts, N/m. */
    public double initialStiffness() {
        switch (kind) {
            case SWITCH_ON:
                return 0;
            case STIFFEN:
                return STIFFEN_FROM;
            default:
                return stiffness;
        }
    }

    private double depth() {
        return kind == Kind.PRESS && speed < 0.01 ? 0.002 : DEPTH;
    }

    private double inSpeed() {
        return kind == Kind.PRESS || kind == Kind.TAP ? speed : 0.02;
    }

    /** End of the hand's move in, s. */
    public double inEnd() {
        return 0.05 + shift + (gap() + depth()) / inSpeed();
    }

    /** When the scene changes the wall or the hand, s (NaN: it does not). */
    public double eventTime() {
        switch (kind) {
            case SWITCH_ON:
            case MOVE_IN:
                return inEnd() + 0.1;
            case STIFFEN:
            case RELEASE:
                return inEnd() + 0.2;
            default:
                return Double.NaN;
        }
    }

    /** End of the hold: the hand starts back (PRESS, TAP) or the run ends, s. */
    public double holdEnd() {
        switch (kind) {
            case PRESS:
                return inEnd() + 0.4;
            case TAP:
                return inEnd() + 0.03;
            case RELEASE:
                return eventTime() + 0.3;
            default:
                return eventTime() + 0.5;
        }
    }

    /** The run's length, s. */
    public double duration() {
        switch (kind) {
            case PRESS:
            case TAP:
                return holdEnd() + (gap() + depth()) / Math.max(inSpeed(), 0.02) + (kind == Kind.TAP ? 0.4 : 0.15);
            default:
                return holdEnd();
        }
    }

    /**
     * The window in which the handle must be still (residual oscillation read), s: {from, to}; after a tap or a release
     * only the samples with the handle inside the wall count (the hand's own swing after it left is not the wall's).
     */
    public double[] settledWindow() {
        switch (kind) {
            case PRESS:
                return new double[] {inEnd() + 0.15, holdEnd()};
            case TAP:
                return new double[] {duration() - 0.15, duration()};
            case RELEASE:
                return new double[] {eventTime() + 0.15, holdEnd()};
            default:
                return new double[] {eventTime() + 0.2, holdEnd()};
        }
    }

    /** True if the energy to the hand is counted from 50 ms before the wall changes, not before the first contact. */
    public boolean countsFromEvent() {
        return kind == Kind.SWITCH_ON || kind == Kind.MOVE_IN;
    }

    /** The intended motion (device metres) for a start pose (x0, y0), its time counted from t0 seconds. */
    public Hand.Script script(double x0, double y0, double t0) {
        double v = inSpeed();
        double out = Math.max(v, 0.02);
        double s1 = gap() + depth();
        double start = 0.05 + shift;
        double in = inEnd();
        double hold = holdEnd();
        boolean leaves = kind == Kind.PRESS || kind == Kind.TAP;
        return (t, o) -> {
            double u = t - t0;
            double s;
            if (u < start) {
                s = 0;
            } else if (u < in) {
                s = v * (u - start);
            } else if (!leaves || u < hold) {
                s = s1;
            } else {
                s = Math.max(0, s1 - out * (u - hold));
            }
            o[0] = x0;
            o[1] = y0 - s;
        };
    }

    /** A short label: kind, grip, K / K0, speed, friction, shift. */
    public String label() {
        StringBuilder b = new StringBuilder();
        b.append(kind.name().toLowerCase(Locale.ROOT)).append(' ').append(grip.name().toLowerCase(Locale.ROOT))
                .append(String.format(Locale.ROOT, " %.0f K0", stiffness / K0));
        if (kind == Kind.PRESS || kind == Kind.TAP) {
            b.append(String.format(Locale.ROOT, " %.0f mm/s", speed * 1e3));
        }
        b.append(friction ? "" : " no friction");
        if (shift > 0) {
            b.append(String.format(Locale.ROOT, " +%.2f ms", shift * 1e3));
        }
        return b.toString();
    }

    @Override
    public String toString() {
        return label();
    }
}
