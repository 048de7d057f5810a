package tactus.engine;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * Engine-level regressions: negative step counts, the haptic-path calls after a topology edit, and the
 * divergence state after the model is cleared or the diverged mass removed.
 */
class EngineLifecycleTest {

    // Was: step(-5) ran no step but added -5 to the step count.
    @Test
    void negativeStepCountsAreRejected() {
        Engine e = new Engine();
        e.addMass(MassKind.MASS3D, 1, 0, 0, 0, 0, 0, 0);
        e.step(3);
        IllegalArgumentException ex = assertThrows(IllegalArgumentException.class, () -> e.step(-5));
        assertTrue(ex.getMessage().contains("-5"), ex.getMessage());
        assertEquals(3, e.stepCount());
        assertEquals(0, e.step(0));
        assertEquals(3, e.stepCount());
    }

    /** A mass on a spring to a ground, stepped a little; returns {mass, ground}. */
    private static int[] springScene(Engine e) {
        int m = e.addMass(MassKind.MASS3D, 2, 0.3, 0, 0, 0, 0, 0);
        int g = e.addMass(MassKind.GROUND3D, 1, 1, 0, 0, 0, 0, 0);
        e.addLink(LinkKind.SPRING3D, m, g, 0.05, 0, 0.5);
        e.step(10);
        return new int[] {m, g};
    }

    // Was: after a topology edit, addForce, setInputTarget and takeForce compiled the whole plan on the calling
    // thread (the haptic thread at 1 kHz). Now they write into the live plan, or into pending buffers for a
    // mass the plan does not hold yet, and the next compile picks those up.
    @Test
    void hapticCallsAfterATopologyEditDoNotCompile() {
        Engine e = new Engine();
        int[] ids = springScene(e);
        double[] before = new double[3];
        e.force(ids[0], before);
        int avatar = e.addMass(MassKind.HAPTIC_INPUT3D, 1, 0, 2, 0, 0, 0, 0);
        int pushed = e.addMass(MassKind.MASS3D, 4, 0, -2, 0, 0, 0, 0);
        assertTrue(e.needsCompile());
        double[] out = new double[3];
        e.addForce(ids[0], 0.01, 0, 0);     // a mass the stale plan holds
        e.addForce(pushed, 0, 0.5, 0);       // a mass the plan does not hold yet
        e.addForce(pushed, 0, 0.25, 0.125);
        e.setInputTarget(avatar, 0, 3, 0);
        e.takeForce(avatar, out);
        assertArrayEquals(new double[] {0, 0, 0}, out, 0.0);
        e.force(ids[0], out);
        assertEquals(before[0] + 0.01, out[0], 0.0, "the force went into the stale plan's buffer");
        e.force(pushed, out);
        assertArrayEquals(new double[] {0, 0.75, 0.125}, out, 0.0, "the pending force is visible");
        assertTrue(e.needsCompile(), "none of these calls compiled the plan");

        e.step(1);
        double[] p = new double[3];
        e.position(pushed, p);
        assertArrayEquals(new double[] {0, -2 + 0.75 / 4, 0.125 / 4}, p, 0.0, "the pending force acted once");
        e.position(avatar, p);
        assertArrayEquals(new double[] {0, 3, 0}, p, 0.0, "the pending target was followed");

        // the same calls made after compiling give the same state, bit for bit
        Engine ref = new Engine();
        int[] r = springScene(ref);
        int refAvatar = ref.addMass(MassKind.HAPTIC_INPUT3D, 1, 0, 2, 0, 0, 0, 0);
        int refPushed = ref.addMass(MassKind.MASS3D, 4, 0, -2, 0, 0, 0, 0);
        ref.compile();
        ref.addForce(r[0], 0.01, 0, 0);
        ref.addForce(refPushed, 0, 0.5, 0);
        ref.addForce(refPushed, 0, 0.25, 0.125);
        ref.setInputTarget(refAvatar, 0, 3, 0);
        ref.step(1);
        double[] a = new double[3];
        double[] b = new double[3];
        for (int i = 0; i < 4; i++) {
            e.position(i, a);
            ref.position(i, b);
            assertArrayEquals(b, a, 0.0, "mass " + i);
        }
    }

    @Test
    void takeForceOnAMassNotYetCompiledReturnsAndClearsItsPendingForce() {
        Engine e = new Engine();
        springScene(e);
        int m = e.addMass(MassKind.MASS3D, 1, 0, 0, 0, 0, 0, 0);
        e.addForce(m, 1, 2, 3);
        double[] out = new double[3];
        e.takeForce(m, out);
        assertArrayEquals(new double[] {1, 2, 3}, out, 0.0);
        e.takeForce(m, out);
        assertArrayEquals(new double[] {0, 0, 0}, out, 0.0);
        assertTrue(e.needsCompile());
        e.step(1);
        e.position(m, out);
        assertArrayEquals(new double[] {0, 0, 0}, out, 0.0, "a taken force no longer acts");
    }

    /** A chain whose middle spring is far too stiff: it diverges within a few hundred steps. */
    private static int[] divergingChain(Engine e) {
        int[] m = new int[4];
        for (int i = 0; i < 4; i++) {
            m[i] = e.addMass(i == 0 ? MassKind.GROUND3D : MassKind.MASS3D, 1, i, 0, 0, 0, 0.01, 0);
        }
        e.addLink(LinkKind.SPRING3D, m[0], m[1], 0.1, 0, 1);
        e.addLink(LinkKind.SPRING3D, m[1], m[2], 9.0, 0, 1);
        e.addLink(LinkKind.SPRING3D, m[2], m[3], 0.1, 0, 1);
        assertTrue(e.step(100_000) < 100_000, "the chain should diverge");
        assertTrue(e.divergedMass() >= 0);
        return m;
    }

    private static void assertRunsCleanly(Engine e) {
        int a = e.addMass(MassKind.MASS3D, 1, 0, 0, 0, 0.001, 0, 0);
        int g = e.addMass(MassKind.GROUND3D, 1, 1, 0, 0, 0, 0, 0);
        e.addLink(LinkKind.SPRING_DAMPER3D, a, g, 0.1, 0.01, 1);
        assertEquals(1000, e.step(1000));
        assertEquals(-1, e.divergedMass());
        assertEquals(-1, e.divergedAt());
        double[] p = new double[3];
        e.position(a, p);
        assertTrue(Double.isFinite(p[0]) && Math.abs(p[0]) < 1, "x = " + p[0]);
    }

    // Was: clear() kept the diverged mass's id: the engine ran no further step, and the facade's message for the
    // dead id threw "no live mass with id 1" on every later step.
    @Test
    void clearAfterADivergenceLeavesAUsableEngine() {
        Engine e = new Engine();
        divergingChain(e);
        e.clear();
        assertEquals(-1, e.divergedMass());
        assertEquals(-1, e.divergedAt());
        assertRunsCleanly(e);
    }

    @Test
    void removingTheDivergedMassForgetsTheDivergence() {
        Engine e = new Engine();
        int[] m = divergingChain(e);
        int bad = e.divergedMass();
        e.removeMass(bad);
        assertEquals(-1, e.divergedMass(), "no dead id may stay recorded");
        assertEquals(-1, e.divergedAt());
        for (int id : m) {
            if (e.isMass(id)) {
                e.removeMass(id);
            }
        }
        assertRunsCleanly(e);
    }

    @Test
    void removingAnotherMassKeepsTheDivergence() {
        Engine e = new Engine();
        int[] m = divergingChain(e);
        int bad = e.divergedMass();
        int other = m[3] == bad ? m[1] : m[3];
        e.removeMass(other);
        assertEquals(bad, e.divergedMass());
        assertTrue(e.isMass(e.divergedMass()));
        assertFalse(e.divergedAt() < 0);
    }
}
