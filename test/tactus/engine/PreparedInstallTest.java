package tactus.engine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.junit.jupiter.api.Test;

/**
 * A topology change compiled in two halves ({@link Engine#prepareCompile()} on one thread while the old plan keeps
 * stepping under {@link Engine#holdTopology()}, then {@link Engine#install} between two steps) gives the same model,
 * bit for bit, as the same change compiled at once at the step of the install, whatever happened in between: steps
 * of the old plan, parameter changes, forces on a mass the old plan does not have yet, a mass moved by hand.
 */
class PreparedInstallTest {

    /** A chain of Mass3D between two grounds, long enough for stencil runs, with an oscillator and a contact. */
    private static Engine scene() {
        Engine e = new Engine();
        e.setGravity(0, -1e-7, 0);
        e.setFriction(1e-5);
        int prev = e.addMass(MassKind.GROUND3D, 1, 0, 0, 0, 0, 0, 0);
        for (int i = 1; i <= 40; i++) {
            int m = e.addMass(MassKind.MASS3D, 1, i, i == 7 ? 0.2 : 0, 0, 0, 0, 0);
            e.addLink(LinkKind.SPRING_DAMPER3D, prev, m, 0.1, 0.001, 1);
            prev = m;
        }
        int g = e.addMass(MassKind.GROUND3D, 1, 41, 0, 0, 0, 0, 0);
        e.addLink(LinkKind.SPRING_DAMPER3D, prev, g, 0.1, 0.001, 1);
        int o = e.addMass(MassKind.OSC3D, 1, 20, 1, 0, 0, 0.01, 0);
        e.setOscillator(o, 0.05, 0.0001);
        e.addLink(LinkKind.CONTACT3D, o, 20, 0.05, 0.001, 1.1);
        e.addLink(LinkKind.ROPE3D, o, 25, 0.05, 0.001, 1.5);
        e.compile();
        return e;
    }

    /** Ids of the scene (they are the same in every scene built by {@link #scene()}). */
    private static final int OSC = 42;
    private static final int FIRST_SPRING = 0;

    /**
     * The change under test, made identically on both engines: a new mass linked to the chain, a removed spring, a
     * new contact group. Returns the new mass's id.
     */
    private static int change(Engine e) {
        int x = e.addMass(MassKind.MASS3D, 1, 12, 2, 0, 0, -0.001, 0);
        e.addLink(LinkKind.SPRING_DAMPER3D, x, 12, 0.08, 0.002, 1.8);
        e.removeLink(FIRST_SPRING + 30);
        e.addContactGroup(new int[] {5, 6, 7, 8, x}, 0.5, 0.05, 0.001);
        return x;
    }

    /** What happens between the preparation and the install (on the reference: just before its compile). */
    private static void meanwhile(Engine e, int x) {
        e.setOscillator(OSC, 0.07, 0.0002);
        e.addForce(x, 0.001, 0, 0);
        e.addForce(9, 0, 0.002, 0);
        e.setPosition(15, 15, 0.05, 0);
        e.setLinkParams(FIRST_SPRING + 3, 0.12, 0.001, 1);
    }

    private static void assertSameModel(Engine ref, Engine e, String what) {
        StepPlan a = ref.plan();
        StepPlan b = e.plan();
        assertEquals(a.nMass, b.nMass, what + ": masses");
        for (int s = 0; s < a.nMass; s++) {
            assertEquals(a.massId[s], b.massId[s], what + ": slot " + s);
            double[][] fa = {a.x, a.y, a.z, a.px, a.py, a.pz, a.fx, a.fy, a.fz, a.tx, a.ty, a.tz, a.invM, a.retention};
            double[][] fb = {b.x, b.y, b.z, b.px, b.py, b.pz, b.fx, b.fy, b.fz, b.tx, b.ty, b.tz, b.invM, b.retention};
            for (int f = 0; f < fa.length; f++) {
                assertEquals(fa[f][s], fb[f][s], 0.0, what + ": mass " + a.massId[s] + " field " + f);
            }
        }
    }

    @ParameterizedTest
    @ValueSource(ints = {0, 1, 37, 500})
    void preparedInstallMatchesACompileAtTheInstallStep(int stepsBetween) {
        Engine ref = scene();
        Engine e = scene();
        ref.step(300);
        e.step(300);

        e.holdTopology();
        int x = change(e);
        StepPlan old = e.plan();
        Engine.PreparedPlan prepared = e.prepareCompile();
        assertNotNull(prepared);
        assertSame(old, e.plan(), "held: the old plan stays in place");
        e.step(stepsBetween); // the old plan goes on stepping while the new one waits
        assertSame(old, e.plan(), "held: stepping does not compile");
        meanwhile(e, x);
        assertTrue(e.install(prepared), "the prepared plan is installed, not recompiled");
        assertNotSame(old, e.plan());

        ref.step(stepsBetween);
        int xr = change(ref);
        assertEquals(x, xr);
        meanwhile(ref, xr);
        ref.compile();

        assertSameModel(ref, e, "at the install");
        ref.step(3000);
        e.step(3000);
        assertSameModel(ref, e, "3000 steps later");
        assertTrue(ref.contactGroupRebuilds() > 0);
    }

    @Test
    void aTopologyChangeAfterThePreparationFallsBackToAFullCompile() {
        Engine ref = scene();
        Engine e = scene();
        e.holdTopology();
        int x = change(e);
        Engine.PreparedPlan prepared = e.prepareCompile();
        e.step(10);
        e.removeLink(FIRST_SPRING + 20); // after the preparation: the prepared plan is outdated
        assertFalse(e.install(prepared));
        ref.step(10);
        change(ref);
        ref.removeLink(FIRST_SPRING + 20);
        ref.compile();
        assertSameModel(ref, e, "after the fallback");
        e.step(1000);
        ref.step(1000);
        assertSameModel(ref, e, "1000 steps later");
        assertTrue(e.plan().nMass > x);
    }

    @Test
    void nothingToPrepareWithoutATopologyChange() {
        Engine e = scene();
        e.holdTopology();
        e.setOscillator(OSC, 0.06, 0.0001);
        assertNull(e.prepareCompile());
        StepPlan p = e.plan();
        assertFalse(e.install(null));
        assertSame(p, e.plan());
    }
}
