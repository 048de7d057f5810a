package tactus.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.HashMap;
import java.util.Map;
import java.util.Set;
import org.junit.jupiter.api.Test;
import tactus.PhysicalModel;
import tactus.Vect3D;

/**
 * Topology changes in the middle of a run. A model A runs, then loses a link, loses a mass with its links,
 * turns a mass into a fixed point, or gains a module. A model B is BUILT without the removed part (or with the
 * added one, or with a Ground3D in place of the frozen mass) from A's state at that instant: same positions,
 * same velocities, and the same pending forces (the force buffer filled by A's last interaction phase, loaded
 * into B with triggerForceImpulse). From then on the scheme is deterministic, so A and B must move
 * bit-identically (assertEquals with 0 tolerance) for thousands of steps: any slot mix-up, stale link, stale
 * damper history or lost state in A's recompilation would show.
 *
 * <p>Exact state transfer through the public API: fs = 1024 and every coordinate stays in [16, 32), so
 * x - x_prev is exact (Sterbenz), the velocity (x - x_prev) * 1024 and its conversion back are exact, and B's
 * previous position x - v/1024 is bit-equal to A's. B's spring-dampers take their previous length from the
 * current positions, which equals what A's links stored in their last interaction phase; conditional links
 * re-derive theirs from the previous positions.
 */
class TopologyChangeTest {
    private static final int FS = 1024;
    private static final int BEFORE = 3000;
    private static final int AFTER = 4000;

    /** What to leave out of (or change in) a build. */
    private static final class Spec {
        Set<String> skipLinks = Set.of();
        Set<String> skipMasses = Set.of();
        String groundMass;
        boolean withNewModule;
        Map<String, Vect3D[]> state;   // name -> {position, velocity}; null for the initial state
    }

    private static Vect3D[] st(Spec s, String name, Vect3D pos, Vect3D vel) {
        if (s.state != null && s.state.containsKey(name)) {
            return s.state.get(name);
        }
        return new Vect3D[] {pos, vel};
    }

    private static void mass(PhysicalModel pm, Spec s, String name, double m, Vect3D pos, Vect3D vel) {
        if (s.skipMasses.contains(name)) {
            return;
        }
        Vect3D[] x = st(s, name, pos, vel);
        if (name.equals(s.groundMass)) {
            pm.addGround3D(name, x[0]);
        } else {
            pm.addMass3D(name, m, x[0], x[1]);
        }
    }

    private static boolean keep(Spec s, String link, String a, String b) {
        return !s.skipLinks.contains(link) && !s.skipMasses.contains(a) && !s.skipMasses.contains(b);
    }

    /** A chain g0 - m1..m8 - g9 along x with a two-mass branch, a rope and a contact, friction and gravity. */
    private static PhysicalModel build(Spec s) {
        PhysicalModel pm = new PhysicalModel(FS, 30);
        pm.setFriction(0.0005);
        pm.setGravity(1e-7);
        pm.addGround3D("g0", new Vect3D(17, 20, 20));
        for (int i = 1; i <= 8; i++) {
            mass(pm, s, "m" + i, 1 + 0.1 * i, new Vect3D(17 + i, 20 + 0.05 * (i % 3), 20),
                    new Vect3D(0, 10 * (i % 2 == 0 ? 1 : -1), 5 * i - 20));
        }
        pm.addGround3D("g9", new Vect3D(26, 20, 20));
        mass(pm, s, "b1", 0.8, new Vect3D(21, 21, 20), new Vect3D(15, 0, 0));
        mass(pm, s, "b2", 0.9, new Vect3D(21, 22, 20.2), new Vect3D(0, 0, -10));
        for (int i = 0; i <= 8; i++) {
            String a = i == 0 ? "g0" : "m" + i;
            String b = i == 8 ? "g9" : "m" + (i + 1);
            if (keep(s, "s" + i, a, b)) {
                pm.addSpringDamper3D("s" + i, 1.0, 0.05, 0.002, a, b);
            }
        }
        if (keep(s, "sb1", "m4", "b1")) {
            pm.addSpringDamper3D("sb1", 1.0, 0.04, 0.001, "m4", "b1");
        }
        if (keep(s, "sb12", "b1", "b2")) {
            pm.addSpringDamper3D("sb12", 1.0, 0.03, 0.001, "b1", "b2");
        }
        if (keep(s, "sb2", "m6", "b2")) {
            pm.addSpring3D("sb2", 1.5, 0.02, "m6", "b2");
        }
        if (keep(s, "r", "m2", "b1")) {
            pm.addRope3D("r", 3.0, 0.05, 0.01, "m2", "b1");
        }
        if (keep(s, "c", "m5", "b2")) {
            pm.addContact3D("c", 1.6, 0.05, 0.01, "m5", "b2");
        }
        if (s.withNewModule) {
            Vect3D[] x = st(s, "n1", new Vect3D(24, 21.5, 20), new Vect3D(0, -20, 0));
            pm.addMass3D("n1", 0.7, x[0], x[1]);
            pm.addSpringDamper3D("sn1", 1.2, 0.03, 0.002, "n1", "m7");
        }
        pm.init();
        return pm;
    }

    private static Map<String, Vect3D[]> stateOf(PhysicalModel pm) {
        Map<String, Vect3D[]> m = new HashMap<>();
        for (int i = 0; i < pm.getNumberOfMats(); i++) {
            String n = pm.getMatNameAt(i);
            Vect3D p = pm.getMatPosition(n);
            Vect3D prev = new Vect3D(p).sub(new Vect3D(pm.getMatVelocity(n)).div(FS));
            for (Vect3D q : new Vect3D[] {p, prev}) {
                assertTrue(q.x >= 16 && q.x < 32 && q.y >= 16 && q.y < 32 && q.z >= 16 && q.z < 32,
                        "the exact-transfer argument needs coordinates in [16, 32): " + n + " " + q);
            }
            m.put(n, new Vect3D[] {p, pm.getMatVelocity(n)});
        }
        return m;
    }

    /** Loads A's pending forces into B's (empty) force buffers: the next step of both uses the same forces. */
    private static void copyPendingForces(PhysicalModel a, PhysicalModel b) {
        for (int i = 0; i < b.getNumberOfMats(); i++) {
            String n = b.getMatNameAt(i);
            Vect3D f = a.getMatForce(n);
            b.triggerForceImpulse(n, f.x, f.y, f.z);
        }
    }

    private static void assertLockstep(PhysicalModel a, PhysicalModel b, String what) {
        assertEquals(a.getNumberOfMats(), b.getNumberOfMats());
        Vect3D pa = new Vect3D();
        Vect3D pb = new Vect3D();
        for (int n = 1; n <= AFTER; n++) {
            a.computeStep();
            b.computeStep();
            for (int i = 0; i < b.getNumberOfMats(); i++) {
                String name = b.getMatNameAt(i);
                a.getMatPosition(name, pa);
                b.getMatPosition(name, pb);
                assertEquals(pb.x, pa.x, 0.0, what + ": " + name + " x, step " + n);
                assertEquals(pb.y, pa.y, 0.0, what + ": " + name + " y, step " + n);
                assertEquals(pb.z, pa.z, 0.0, what + ": " + name + " z, step " + n);
            }
        }
    }

    private static PhysicalModel runFull() {
        PhysicalModel a = build(new Spec());
        a.computeNSteps(BEFORE);
        return a;
    }

    @Test
    void removeLinkMidRun() {
        PhysicalModel a = runFull();
        a.removeLink("sb1");
        Spec s = new Spec();
        s.skipLinks = Set.of("sb1");
        s.state = stateOf(a);
        PhysicalModel b = build(s);
        copyPendingForces(a, b);
        assertLockstep(a, b, "removeLink(sb1)");
    }

    @Test
    void removeConditionalLinksMidRun() {
        PhysicalModel a = runFull();
        a.removeLink("r");
        a.removeLink("s3");
        Spec s = new Spec();
        s.skipLinks = Set.of("r", "s3");
        s.state = stateOf(a);
        PhysicalModel b = build(s);
        copyPendingForces(a, b);
        assertLockstep(a, b, "removeLink(r, s3)");
    }

    @Test
    void removeMassWithItsLinksMidRun() {
        PhysicalModel a = runFull();
        a.removeMatAndConnectedLinks("b2");
        assertEquals(false, a.linkExists("sb12"));
        assertEquals(false, a.linkExists("c"));
        Spec s = new Spec();
        s.skipMasses = Set.of("b2");
        s.state = stateOf(a);
        PhysicalModel b = build(s);
        copyPendingForces(a, b);
        assertLockstep(a, b, "removeMatAndConnectedLinks(b2)");
    }

    @Test
    void changeToFixedPointMidRun() {
        PhysicalModel a = runFull();
        Vect3D frozen = a.getMatPosition("m5");
        a.changeToFixedPoint("m5");
        assertEquals("Ground3D", a.getMass("m5").getType());
        Spec s = new Spec();
        s.groundMass = "m5";
        s.state = stateOf(a);
        PhysicalModel b = build(s);
        copyPendingForces(a, b);
        assertLockstep(a, b, "changeToFixedPoint(m5)");
        assertEquals(frozen.x, a.getMatPosition("m5").x, 0.0);
        assertEquals(frozen.z, a.getMatPosition("m5").z, 0.0);
    }

    @Test
    void addModuleMidRun() {
        PhysicalModel a = runFull();
        a.addMass3D("n1", 0.7, new Vect3D(24, 21.5, 20), new Vect3D(0, -20, 0));
        a.addSpringDamper3D("sn1", 1.2, 0.03, 0.002, "n1", "m7");
        Spec s = new Spec();
        s.withNewModule = true;
        s.state = stateOf(a);
        PhysicalModel b = build(s);
        copyPendingForces(a, b);
        assertLockstep(a, b, "add n1 + sn1");
    }

    // Control: without the transfer of pending forces the lockstep fails, so the comparison is sensitive.
    @Test
    void theComparisonDetectsAOneStepForceDifference() {
        PhysicalModel a = runFull();
        a.removeLink("sb1");
        Spec s = new Spec();
        s.skipLinks = Set.of("sb1");
        s.state = stateOf(a);
        PhysicalModel b = build(s);
        a.computeStep();
        b.computeStep();
        assertTrue(a.getMatPosition("m4").y != b.getMatPosition("m4").y);
    }
}
