package tactus.engine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.HashMap;
import java.util.Map;
import org.junit.jupiter.api.Test;

/**
 * A topology change rebuilds the step plan (slots move: masses are grouped by kind, links by kind). The live
 * state must survive that bit for bit, addressed by stable id: positions, previous positions, pending forces,
 * input targets and each link's damper history (its previous distance, or the "inactive" mark of a conditional
 * link). Otherwise a model would jump whenever a module is added or removed.
 */
class PlanRecompileTest {

    /** Every mass kind and every link kind, in a scene that moves. */
    private static int ropeId;
    private static int bubbleId;

    private static Engine scene(int[] ids) {
        Engine e = new Engine();
        e.setGravity(0, 0, -1e-7);
        e.setFriction(1e-4);
        ids[0] = e.addMass(MassKind.GROUND3D, 1, 0, 0, 0, 0, 0, 0);
        ids[1] = e.addMass(MassKind.MASS3D, 1, 1, 0, 0, 0.001, 0.002, 0);
        ids[2] = e.addMass(MassKind.MASS3D, 1.5, 2, 0.1, 0, 0, -0.001, 0.001);
        ids[3] = e.addMass(MassKind.OSC3D, 1, 2, 1, 0, 0.003, 0, 0);
        e.setOscillator(ids[3], 0.05, 0.001);
        ids[4] = e.addMass(MassKind.MASS2D_PLANE, 1, 3, 0, 0, 0, 0.002, 0);
        ids[5] = e.addMass(MassKind.MASS1D, 1, 0, 0, 1, 0, 0, 0.001);
        ids[6] = e.addMass(MassKind.GROUND1D, 1, 0, 0, 0, 0, 0, 0);
        ids[7] = e.addMass(MassKind.HAPTIC_INPUT3D, 1, 3, 1, 0, 0, 0, 0);
        e.setInputWeight(ids[7], 0.25);
        ids[8] = e.addMass(MassKind.OSC1D, 1, 5, 5, 2, 0, 0, 0.002);
        e.setOscillator(ids[8], 0.02, 0);
        e.addLink(LinkKind.SPRING_DAMPER3D, ids[0], ids[1], 0.05, 0.002, 1);
        e.addLink(LinkKind.SPRING3D, ids[1], ids[2], 0.05, 0, 1);
        e.addLink(LinkKind.DAMPER3D, ids[2], ids[3], 0, 0.002, 0);
        ropeId = e.addLink(LinkKind.ROPE3D, ids[1], ids[3], 0.05, 0.002, 1.2);
        e.addLink(LinkKind.CONTACT3D, ids[2], ids[4], 0.05, 0.002, 1.3);
        bubbleId = e.addLink(LinkKind.BUBBLE3D, ids[3], ids[0], 0.05, 0.002, 2.0);
        e.addLink(LinkKind.SPRING_DAMPER1D, ids[5], ids[6], 0.05, 0.002, 1);
        e.addPlaneContact(ids[2], 2, -0.001, 0, 0.05, 0.002);
        e.addAttractor(ids[4], ids[7], 0.1, 1e-5);
        e.addLink(LinkKind.SPRING_DAMPER3D, ids[4], ids[7], 0.05, 0.002, 1);
        e.setInputTarget(ids[7], 3.2, 1.1, 0.1);
        return e;
    }

    /** id -> {x, y, z, px, py, pz, fx, fy, fz, tx, ty, tz} of every live mass. */
    private static Map<Integer, double[]> massState(StepPlan p) {
        Map<Integer, double[]> m = new HashMap<>();
        for (int s = 0; s < p.nMass; s++) {
            m.put(p.massId[s], new double[] {p.x[s], p.y[s], p.z[s], p.px[s], p.py[s], p.pz[s], p.fx[s], p.fy[s],
                                             p.fz[s], p.tx[s], p.ty[s], p.tz[s]});
        }
        return m;
    }

    private static void assertSameMassState(Map<Integer, double[]> expected, StepPlan after, String what) {
        Map<Integer, double[]> m = massState(after);
        for (Map.Entry<Integer, double[]> en : expected.entrySet()) {
            if (m.containsKey(en.getKey())) {
                double[] a = en.getValue();
                double[] b = m.get(en.getKey());
                for (int i = 0; i < a.length; i++) {
                    assertEquals(a[i], b[i], 0.0, what + ": mass " + en.getKey() + " state[" + i + "]");
                }
            }
        }
    }

    // The recompiled plan holds the same per-id state, and then evolves exactly like a plan never recompiled
    // (so the links' damper histories, not read directly here, survived too).
    @Test
    void stateSurvivesAddingAModule() {
        int[] ids = new int[9];
        Engine e = scene(ids);
        Engine ref = scene(new int[9]);
        e.step(777);
        ref.step(777);
        StepPlan p0 = e.plan();
        Map<Integer, double[]> m0 = massState(p0);
        // adding Mass3Ds (the first kind group: every later slot shifts) and a link between them, far away from
        // the rest, in one recompilation
        int x1 = e.addMass(MassKind.MASS3D, 1, 9, 9, 9, 0, 0, 0);
        int x2 = e.addMass(MassKind.MASS3D, 1, 9, 9, 10.5, 0, 0, 0);
        e.addLink(LinkKind.SPRING_DAMPER3D, x1, x2, 0.05, 0.002, 1);
        StepPlan p1 = e.plan();
        assertNotSame(p0, p1);
        assertSameMassState(m0, p1, "after adding");
        assertEquals(10.5, p1.z[slotOf(p1, x2)], 0.0);
        e.step(2000);
        ref.step(2000);
        assertSameMassState(massState(ref.plan()), e.plan(), "2000 steps after adding");
    }

    // Removing masses (and their links) keeps every survivor's state; the scene tests check that the survivors
    // then move exactly like a model built without the removed part.
    @Test
    void stateSurvivesRemovingModules() {
        int[] ids = new int[9];
        Engine e = scene(ids);
        e.step(900);
        // one conditional link engaged and one slack at the change, so both history marks are carried
        assertTrue(e.linkDistance(bubbleId) > 2.0, "bubble engaged at the change");
        assertTrue(e.linkDistance(ropeId) <= 1.2, "rope slack at the change");
        Map<Integer, double[]> m0 = massState(e.plan());
        e.removeMass(ids[5]);          // the Mass1D and its SpringDamper1D
        e.removeMass(ids[1]);          // a Mass3D with a spring-damper, a spring and the rope
        StepPlan p1 = e.plan();
        assertSameMassState(m0, p1, "after removing masses");
        assertEquals(false, massState(p1).containsKey(ids[5]));
        assertEquals(false, massState(p1).containsKey(ids[1]));
        assertEquals(false, e.isLink(ropeId));
    }

    // makeFixed: same position, no velocity, never moves again whatever the forces.
    @Test
    void makeFixedFreezesTheMassWhereItIs() {
        int[] ids = new int[9];
        Engine e = scene(ids);
        e.step(500);
        double[] pos = new double[3];
        e.position(ids[2], pos);
        e.makeFixed(ids[2]);
        e.step(500);
        double[] now = new double[3];
        e.position(ids[2], now);
        assertEquals(pos[0], now[0], 0.0);
        assertEquals(pos[1], now[1], 0.0);
        assertEquals(pos[2], now[2], 0.0);
        e.displacement(ids[2], now);
        assertEquals(0.0, now[0] * now[0] + now[1] * now[1] + now[2] * now[2], 0.0);
    }

    private static int slotOf(StepPlan p, int id) {
        for (int s = 0; s < p.nMass; s++) {
            if (p.massId[s] == id) {
                return s;
            }
        }
        return -1;
    }
}
