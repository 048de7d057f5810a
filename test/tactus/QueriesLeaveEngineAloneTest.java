package tactus;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.reflect.InvocationTargetException;
import java.lang.reflect.Method;
import java.lang.reflect.Modifier;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * Readers never mutate engine state: on a model with every module kind (every mass kind, every interaction kind,
 * a contact group, subsets, a controller), every public query of {@link PhysicalModel} and of the module handles,
 * called with every argument that makes sense, leaves every value reachable from the engine (positions, forces,
 * coefficients, the compiled plan, the contact group's neighbour list and rebuild count) bitwise unchanged. Queries
 * are found by reflection (public methods named get..., is..., has..., describe..., ...Exists), so a query added
 * later is checked too; the few that consume what they read by design are listed in {@link #TAKES}.
 */
class QueriesLeaveEngineAloneTest {
    /** Reads that consume what they return (the avatar force accumulator is read once per haptic tick). */
    private static final Set<String> TAKES = Set.of("getHapticForce", "getHapticForceCounted", "takeForce");

    private static final String[] PARAMS = {"stiffness", "damping", "mass", "dist", "distX"};

    @Test
    @Timeout(60)
    void everyQueryOfALockedModelLeavesTheEngineBitwiseUnchanged() throws Exception {
        PhysicalModel m = everyKind();
        m.computeNSteps(200);
        m.setMatPosition("b3", new Vect3D(40, 40, 40)); // the group's neighbour list is now stale: a reader must not rebuild it
        checkEveryQuery(m);
    }

    @Test
    @Timeout(60)
    void everyQueryOfARealtimeSteppedModelLeavesTheEngineBitwiseUnchanged() throws Exception {
        PhysicalModel m = everyKind();
        m.beginRealtimeStepping();
        m.computeNSteps(200); // this thread becomes the owner
        m.setMatPosition("b3", new Vect3D(40, 40, 40));
        m.computeStep(); // applies the queued change, then a step: the list may be rebuilt by the owner only
        m.setMatPosition("b3", new Vect3D(-40, 40, 40));
        m.computeNSteps(0);
        List<Throwable> errors = new ArrayList<>();
        Thread reader = new Thread(() -> {
            try {
                checkEveryQuery(m);
            } catch (Throwable t) {
                errors.add(t);
            }
        }, "reader");
        reader.start();
        reader.join();
        if (!errors.isEmpty()) {
            throw new AssertionError(errors.get(0));
        }
        m.endRealtimeStepping();
    }

    /** Calls every query with every candidate argument, checking the fingerprint after each call. */
    private static void checkEveryQuery(PhysicalModel m) throws Exception {
        List<String> before = EngineFingerprint.of(m);
        Set<String> answered = new TreeSet<>();
        Set<String> queries = new TreeSet<>();
        List<Object> targets = new ArrayList<>();
        targets.add(m);
        for (int i = 0; i < m.getNumberOfMats(); i++) {
            targets.add(m.getMass(m.getMatNameAt(i)));
        }
        for (int i = 0; i < m.getNumberOfLinks(); i++) {
            targets.add(m.getInteraction(m.getLinkNameAt(i)));
        }
        targets.add(m.getParamController("k"));
        List<String> before0 = before;
        for (Object target : targets) {
            for (Method q : queriesOf(target.getClass())) {
                String label = q.getDeclaringClass().getSimpleName() + "." + q.getName()
                        + Arrays.toString(q.getParameterTypes());
                queries.add(label);
                for (Object[] args : argumentsFor(m, q)) {
                    try {
                        q.invoke(target, args);
                        answered.add(label);
                    } catch (InvocationTargetException e) {
                        if (!(e.getCause() instanceof IllegalArgumentException
                                || e.getCause() instanceof IllegalStateException
                                || e.getCause() instanceof UnsupportedOperationException)) {
                            throw new AssertionError(label + Arrays.toString(args) + " threw", e.getCause());
                        }
                    }
                    List<String> after = EngineFingerprint.of(m);
                    String diff = EngineFingerprint.firstDifference(before0, after);
                    assertNull(diff, () -> label + " with " + Arrays.toString(args) + " changed the engine: " + diff);
                }
            }
        }
        Set<String> silent = new TreeSet<>(queries);
        silent.removeAll(answered);
        assertTrue(silent.isEmpty(), "queries never answered with the candidate arguments (extend them): " + silent);
        assertTrue(queries.size() > 80, "only " + queries.size() + " queries found");
        assertTrue(queries.contains("PhysicalModel.getTotalEnergy[]"));
        assertTrue(queries.contains("PhysicalModel.describeStability[]"));
    }

    private static List<Method> queriesOf(Class<?> c) {
        List<Method> out = new ArrayList<>();
        for (Method q : c.getMethods()) {
            String n = q.getName();
            boolean query = n.startsWith("get") || n.startsWith("is") || n.startsWith("has") || n.startsWith("describe")
                    || n.endsWith("Exists") || n.equals("updatePosSpeedArraysForModType");
            if (!query || Modifier.isStatic(q.getModifiers()) || q.getDeclaringClass() == Object.class
                    || TAKES.contains(n) || n.equals("getLock") || n.equals("getClass")) {
                continue;
            }
            out.add(q);
        }
        out.sort(Comparator.comparing(Method::toString));
        return out;
    }

    /** @return the argument lists to try: the cartesian product of each parameter's candidates. */
    private static List<Object[]> argumentsFor(PhysicalModel m, Method q) {
        List<Object[]> out = new ArrayList<>();
        out.add(new Object[q.getParameterCount()]);
        Class<?>[] types = q.getParameterTypes();
        for (int p = 0; p < types.length; p++) {
            List<Object> cands = candidates(m, types[p], p);
            List<Object[]> next = new ArrayList<>();
            for (Object[] prefix : out) {
                for (Object c : cands) {
                    Object[] a = prefix.clone();
                    a[p] = c;
                    next.add(a);
                }
            }
            out = next;
        }
        return out;
    }

    private static List<Object> candidates(PhysicalModel m, Class<?> t, int position) {
        List<Object> c = new ArrayList<>();
        if (t == String.class) {
            if (position == 1) {
                c.addAll(Arrays.asList(PARAMS));
            }
            for (int i = 0; i < m.getNumberOfMats(); i++) {
                c.add(m.getMatNameAt(i));
            }
            for (int i = 0; i < m.getNumberOfLinks(); i++) {
                c.add(m.getLinkNameAt(i));
            }
            c.addAll(Arrays.asList("balls", "chain", "k"));
            c.addAll(Arrays.asList("Q", "C", "Kmax", "scale", "profile")); // the nonlinear kinds' extra parameters
        } else if (t == int.class) {
            for (int i = 0; i < Math.max(m.getNumberOfMats(), m.getNumberOfLinks()); i++) {
                c.add(i);
            }
        } else if (t == Vect3D.class) {
            c.add(new Vect3D());
        } else if (t == processing.core.PVector.class) {
            c.add(new processing.core.PVector());
        } else if (t == ArrayList.class) {
            c.add(new ArrayList<>());
        } else if (t.isEnum()) {
            c.addAll(Arrays.asList(t.getEnumConstants()));
        } else if (t == boolean.class) {
            c.add(true);
            c.add(false);
        } else {
            throw new AssertionError("no candidate argument of type " + t.getName() + " (extend the test)");
        }
        return c;
    }

    /** A model with every mass kind, every interaction kind, a contact group, subsets and a controller. */
    static PhysicalModel everyKind() {
        PhysicalModel m = new PhysicalModel(1000, 60);
        m.setStabilityPolicy(StabilityPolicy.WARN);
        m.setGravity(0.001);
        m.setFriction(0.0001);
        m.addMass3D("m3", 1, new Vect3D(0, 0, 0), new Vect3D(1, 0, 0));
        m.addMass3DSimple("ms", 1, new Vect3D(1, 0, 0), new Vect3D(0, 1, 0));
        m.addMass2DPlane("mp", 1, new Vect3D(2, 0, 0), new Vect3D(0, 0, 1));
        m.addMass1D("m1", 1, new Vect3D(3, 0, 0), new Vect3D(0, 0, 1));
        m.addGround3D("g3", new Vect3D(-1, 0, 0));
        m.addGround1D("g1", new Vect3D(4, 0, 0));
        m.addOsc3D("o3", 1, 0.01, 0.001, new Vect3D(0, 2, 0), new Vect3D(1, 1, 0));
        m.addOsc1D("o1", 1, 0.01, 0.001, new Vect3D(0, 3, 0), new Vect3D(0, 0, 2));
        m.addHapticInput3D("h", new Vect3D(0, -1, 0), 2);
        m.addPosInput3D("pi", new Vect3D(0, -2, 0), 2);
        m.addSpring3D("s", 1, 0.01, "g3", "m3");
        m.addDamper3D("d", 0.001, "m3", "ms");
        m.addSpringDamper3D("sd", 1, 0.01, 0.001, "ms", "mp");
        m.addSpringDamper1D("s1", 1, 0.01, 0.001, "m1", "g1");
        m.addRope3D("r", 1.5, 0.01, 0.001, "mp", "o3");
        m.addContact3D("c", 0.5, 0.01, 0.001, "m3", "o3");
        m.addBubble3D("bu", 5, 0.01, 0.001, "o3", "g3");
        m.addPlaneContact("pl", 0, 0.01, 0.001, 2, -0.5, "m3");
        m.addAttractor3D("a", 0.5, 0.0001, "h", "m3");
        m.addSpring3D("hs", 0.5, 0.01, "h", "pi");
        // one of each of mi.lib's nonlinear laws
        m.addQuadraticSpringDamper3D("nq", 1, 0.01, 0.001, 0.1, "m3", "mp");
        m.addCubicSpringDamper1D("nc", 1, 0.01, 0.001, 0.1, "m1", "g1");
        m.addClippedSpringDamper3D("nk", 1, 0.01, 0.001, 0.5, 0.04, "ms", "o3");
        m.addPluck3D("np", 0.5, 0.01, 0.001, 0.2, "h", "ms");
        m.addBow1D("nb", 0.1, 0.01, 0, "m1", "o1");
        m.addClippedContact3D("nx", 0.5, 0.01, 0.001, 0.5, 0.04, "m3", "ms");
        m.createMatSubset("balls");
        for (int i = 0; i < 8; i++) {
            m.addMass3D("b" + i, 1, new Vect3D(0.3 * (i % 2), 0.3 * ((i / 2) % 2), 5 + 0.3 * (i / 4)),
                    new Vect3D(0.1 * i, -0.05 * i, 0.02));
            m.addMatToSubset("b" + i, "balls");
        }
        m.addContactGroup("balls", 0.35, 0.01, 0.0001);
        m.createLinkSubset("chain");
        m.addLinkToSubset("s", "chain");
        m.addLinkToSubset("sd", "chain");
        m.addParamController("k", "chain", "stiffness", 0.01f);
        m.init();
        assertEquals(18, m.getNumberOfMats());
        return m;
    }
}
