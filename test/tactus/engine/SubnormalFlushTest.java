package tactus.engine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** The divergence guard's subnormal flush must remove only values that are themselves tiny, never real forces. */
class SubnormalFlushTest {
    private static final double K = 0.05;
    private static final double L0 = 1.1;

    /** A haptic avatar at the origin on a spring to a ground at x = 1; optionally an unrelated mass at x = tiny. */
    private static Engine avatarOnSpring(double tinyX, int[] ids) {
        Engine e = new Engine();
        ids[0] = e.addMass(MassKind.HAPTIC_INPUT3D, 1, 0, 0, 0, 0, 0, 0);
        ids[1] = e.addMass(MassKind.GROUND3D, 1, 1, 0, 0, 0, 0, 0);
        e.addLink(LinkKind.SPRING3D, ids[0], ids[1], K, 0, L0);
        if (tinyX != 0) {
            ids[2] = e.addMass(MassKind.MASS3D, 1, tinyX, 0, 0, 0, 0, 0);
        }
        return e;
    }

    // Was: when some coordinate of an axis was below 1e-150 on a busy axis, the guard zeroed the position and
    // the force accumulator of every mass whose coordinates were below 1e-150, including exactly zero: the
    // avatar at the origin lost the 0.32 of force its spring had accumulated over 64 steps (it read 0.0).
    @Test
    void anAvatarAtTheOriginKeepsItsForceWhenAnotherMassHasATinyCoordinate() {
        int steps = 64;
        // the spring is compressed by L0 - 1: it pushes the avatar towards -x with K (L0 - 1) per step
        double perStep = K * (L0 - 1.0);
        double expected = -steps * perStep;
        double[] f = new double[3];
        int[] ids = new int[3];

        Engine reference = avatarOnSpring(0, ids);
        reference.step(steps);
        reference.takeForce(ids[0], f);
        assertEquals(expected, f[0], 1e-12, "without the tiny mass");

        Engine withTiny = avatarOnSpring(1e-200, ids);
        withTiny.step(steps);
        double[] x = new double[3];
        withTiny.position(ids[2], x);
        assertEquals(0.0, x[0], 0.0, "the tiny coordinate itself is flushed at the scan of step 64");
        assertTrue(withTiny.guard().flushedValues() > 0, "the flush is counted");
        withTiny.takeForce(ids[0], f);
        assertEquals(expected, f[0], 1e-12, "the avatar's accumulated force survives the flush");
    }

    @Test
    void anAvatarWithATinyCoordinateIsFlushedButKeepsItsForce() {
        Engine e = new Engine();
        int avatar = e.addMass(MassKind.HAPTIC_INPUT3D, 1, 1e-200, 0, 0, 0, 0, 0);
        int ground = e.addMass(MassKind.GROUND3D, 1, 1, 0, 0, 0, 0, 0);
        e.addLink(LinkKind.SPRING3D, avatar, ground, K, 0, L0);
        e.step(64);
        assertTrue(e.guard().flushedValues() > 0, "the avatar's tiny x coordinate was flushed");
        double[] f = new double[3];
        e.takeForce(avatar, f);
        assertEquals(-64 * K * (L0 - 1.0), f[0], 1e-12, "the force along the flushed axis is a real force and is kept");
    }

    @Test
    void aModelBelowTheResolutionIsReportedByTheFlushCount() {
        Engine e = new Engine();
        int a = e.addMass(MassKind.MASS3D, 1, 0, 0, 3e-157, 0, 0, 0);
        int g = e.addMass(MassKind.GROUND3D, 1, 0, 0, 0, 0, 0, 0);
        e.addLink(LinkKind.SPRING_DAMPER3D, a, g, 0.1, 0.001, 0);
        e.step(63);
        assertEquals(0, e.guard().flushedValues());
        e.step(1);
        assertTrue(e.guard().flushedValues() > 0);
    }
}
