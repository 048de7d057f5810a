package tactus;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.PrintStream;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.SplittableRandom;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicReference;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * Randomised, seeded sequences of calls over the public {@link PhysicalModel} API and its handles. Names are
 * drawn from small fixed pools ("m0".."m7", "l0".."l7", "s0".."s2"), so a sequence does not depend on the state
 * it runs in: it can be replayed, and shortened to a minimal reproduction (delta debugging) when it breaks an
 * invariant. After every call:
 * <ul>
 * <li>the call returned normally, or threw one of the documented exceptions ({@link IllegalArgumentException},
 *     {@link IllegalStateException}, {@link UnstableModelException}, {@link DivergenceException}) with a
 *     non-empty message; an {@link IllegalArgumentException} names the element (or index) it was given, and
 *     a call that takes no argument that could be wrong (stepping, energies, reads of existing state) never
 *     throws one;</li>
 * <li>a rejected call ({@link IllegalArgumentException}, {@link IllegalStateException} other than divergence,
 *     {@link UnstableModelException}) left the whole observable state identical: rates, units, medium, every
 *     mass and link with positions, velocities, forces and parameters, names, indices and counts, subsets and
 *     their members, contact groups, policy, threads, divergence flag, energies and the stability line;</li>
 * <li>every reader still works, and no parameter or state becomes NaN or infinite without the model being
 *     flagged as diverged (state is given the longest divergence-check interval the sequence can set to be
 *     caught).</li>
 * </ul>
 * The first test runs the budget of seeds (about 20 s on the 2-core build machine), shrinks the first failure of
 * every distinct kind and reports them all; FacadeRegressionTest holds the minimal reproductions found so far.
 */
class ApiSequenceFuzzTest {
    static final int SEEDS = Integer.getInteger("tactus.fuzz.seeds", 200);
    static final int CALLS = Integer.getInteger("tactus.fuzz.calls", 250);
    static final String[] MASSES = {"m0", "m1", "m2", "m3", "m4", "m5", "m6", "m7"};
    static final String[] LINKS = {"l0", "l1", "l2", "l3", "l4", "l5", "l6", "l7"};
    static final String[] SUBSETS = {"s0", "s1", "s2"};
    /** The longest divergence-check interval a sequence can set (see {@link #generate}). */
    static final int MAX_INTERVAL = 1000;

    /** One call: a readable text, the names and indices it passes, and what it does. */
    static final class Call {
        final String text;
        final String[] names;
        /** True when no argument of the call can be wrong, so it must never throw IllegalArgumentException. */
        final boolean argless;
        final Op op;

        Call(String text, boolean argless, Op op, String... names) {
            this.text = text;
            this.names = names;
            this.argless = argless;
            this.op = op;
        }

        @Override
        public String toString() {
            return text;
        }
    }

    /** The action of a call, with the handles and listener state of the run. */
    interface Op {
        void apply(PhysicalModel m, Run run);
    }

    /** The per-run context: the model, the handles the calls obtained, and the listener's events. */
    static final class Run {
        PhysicalModel model;
        final Map<String, Mass> massHandles = new HashMap<>();
        final Map<String, Interaction> linkHandles = new HashMap<>();
        int divergenceEvents;
        /** True once the model has diverged in this run (an exception or a listener event). */
        boolean diverged;
        long nonFiniteSince = -1;
    }

    /** A broken invariant: its kind (for grouping and shrinking) and details. */
    static final class Violation {
        final String kind;
        final String detail;
        final int at;

        Violation(String kind, String detail, int at) {
            this.kind = kind;
            this.detail = detail;
            this.at = at;
        }
    }

    // ------------------------------------------------------------------ generation

    static double pick(SplittableRandom r, double... values) {
        return values[r.nextInt(values.length)];
    }

    /** A value that is usually valid (in [lo, hi]) and sometimes not (NaN, infinities, negative, zero, huge). */
    static double value(SplittableRandom r, double lo, double hi) {
        if (r.nextInt(10) == 0) {
            return pick(r, Double.NaN, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY, -1, 0, -0.0, 1e300,
                    Double.MIN_VALUE);
        }
        return lo + (hi - lo) * r.nextDouble();
    }

    static Vect3D vec(SplittableRandom r) {
        int c = r.nextInt(20);
        if (c == 0) {
            return new Vect3D(Double.NaN, 0, 0);
        }
        if (c == 1) {
            return null;
        }
        if (c < 5) {
            return new Vect3D(0, 0, 0);   // coincident masses happen often
        }
        return new Vect3D(2 * r.nextDouble() - 1, 2 * r.nextDouble() - 1, 2 * r.nextDouble() - 1);
    }

    static String fmt(Vect3D v) {
        return v == null ? "null" : "new Vect3D(" + v.x + ", " + v.y + ", " + v.z + ")";
    }

    static String massName(SplittableRandom r) {
        return r.nextInt(30) == 0 ? (r.nextBoolean() ? "" : "nope") : MASSES[r.nextInt(MASSES.length)];
    }

    /** An index call may name the element by its index or by the name found there. */
    static String[] indexNames(int idx) {
        return withPools("(" + idx + ")", "\"" + idx + "\"");
    }

    /** The given names plus every pool name: for calls that may name a member rather than the argument. */
    static String[] withPools(String... names) {
        List<String> all = new ArrayList<>(List.of(names));
        all.add("\"nope\"");
        for (String n : MASSES) {
            all.add("\"" + n + "\"");
        }
        for (String n : LINKS) {
            all.add("\"" + n + "\"");
        }
        return all.toArray(new String[0]);
    }

    static String linkName(SplittableRandom r) {
        return r.nextInt(30) == 0 ? "nope" : LINKS[r.nextInt(LINKS.length)];
    }

    static String subsetName(SplittableRandom r) {
        return r.nextInt(30) == 0 ? "nope" : SUBSETS[r.nextInt(SUBSETS.length)];
    }

    /** Generates {@code n} calls; the first creates the model (rate, display rate and units). */
    static List<Call> generate(long seed, int n) {
        SplittableRandom r = new SplittableRandom(seed);
        List<Call> calls = new ArrayList<>();
        int fs = (int) pick(r, 1000, 44100, 300, 8000);
        boolean real = r.nextBoolean();
        paramSystem sys = real ? paramSystem.REAL_UNITS : paramSystem.ALGO_UNITS;
        calls.add(new Call("PhysicalModel m = new PhysicalModel(" + fs + ", 60, paramSystem." + sys + ")", true,
                (m, run) -> run.model = new PhysicalModel(fs, 60, sys)));
        // scales from per-step (algorithmic) values to the model's units
        double kScale = real ? (double) fs * fs : 1;
        double zScale = real ? fs : 1;
        for (int i = 1; i < n; i++) {
            calls.add(oneCall(r, kScale, zScale, fs));
        }
        return calls;
    }

    static Call oneCall(SplittableRandom r, double ks, double zs, int fs) {
        int c = r.nextInt(100);
        String a = massName(r);
        String b = massName(r);
        String l = linkName(r);
        String s = subsetName(r);
        int idx = r.nextInt(12) - 1;
        double mass = value(r, 0.5, 5);
        double k = value(r, 0, 0.3) * ks;
        double z = value(r, 0, 0.02) * zs;
        double d = value(r, 0, 1.5);
        Vect3D p = vec(r);
        Vect3D v = vec(r);
        switch (c) {
            case 0: case 1: case 2:
                return new Call("m.addMass3D(\"" + a + "\", " + mass + ", " + fmt(p) + ", " + fmt(v) + ")", false,
                        (m, run) -> run.massHandles.put(a, m.addMass3D(a, mass, p, v)), a);
            case 3:
                return new Call("m.addMass2DPlane(\"" + a + "\", " + mass + ", " + fmt(p) + ", " + fmt(v) + ")", false,
                        (m, run) -> run.massHandles.put(a, m.addMass2DPlane(a, mass, p, v)), a);
            case 4:
                return new Call("m.addMass1D(\"" + a + "\", " + mass + ", " + fmt(p) + ", " + fmt(v) + ")", false,
                        (m, run) -> run.massHandles.put(a, m.addMass1D(a, mass, p, v)), a);
            case 5:
                return new Call("m.addGround3D(\"" + a + "\", " + fmt(p) + ")", false,
                        (m, run) -> run.massHandles.put(a, m.addGround3D(a, p)), a);
            case 6:
                return new Call("m.addGround1D(\"" + a + "\", " + fmt(p) + ")", false,
                        (m, run) -> run.massHandles.put(a, m.addGround1D(a, p)), a);
            case 7: case 8:
                return new Call("m.addOsc3D(\"" + a + "\", " + mass + ", " + k + ", " + z + ", " + fmt(p) + ", "
                        + fmt(v) + ")", false, (m, run) -> run.massHandles.put(a, m.addOsc3D(a, mass, k, z, p, v)), a);
            case 9:
                return new Call("m.addOsc1D(\"" + a + "\", " + mass + ", " + k + ", " + z + ", " + fmt(p) + ", "
                        + fmt(v) + ")", false, (m, run) -> run.massHandles.put(a, m.addOsc1D(a, mass, k, z, p, v)), a);
            case 10: {
                double f = value(r, 20, fs / 3.0);
                double t = value(r, 0.05, 2);
                return new Call("m.addOsc3DTuned(\"" + a + "\", " + mass + ", " + f + ", " + t + ", " + fmt(p) + ", "
                        + fmt(v) + ")", false, (m, run) -> run.massHandles.put(a, m.addOsc3DTuned(a, mass, f, t, p, v)),
                        a);
            }
            case 11: {
                int sm = r.nextInt(5) - 1;
                boolean haptic = r.nextBoolean();
                return new Call("m.add" + (haptic ? "HapticInput3D" : "PosInput3D") + "(\"" + a + "\", " + fmt(p)
                        + ", " + sm + ")", false, (m, run) -> run.massHandles.put(a, haptic
                        ? m.addHapticInput3D(a, p, sm) : m.addPosInput3D(a, p, sm)), a);
            }
            case 12: case 13: case 14:
                return new Call("m.addSpringDamper3D(\"" + l + "\", " + d + ", " + k + ", " + z + ", \"" + a + "\", \""
                        + b + "\")", false, (m, run) -> run.linkHandles.put(l, m.addSpringDamper3D(l, d, k, z, a, b)),
                        l, a, b);
            case 15:
                return new Call("m.addSpring3D(\"" + l + "\", " + d + ", " + k + ", \"" + a + "\", \"" + b + "\")",
                        false, (m, run) -> run.linkHandles.put(l, m.addSpring3D(l, d, k, a, b)), l, a, b);
            case 16:
                return new Call("m.addDamper3D(\"" + l + "\", " + z + ", \"" + a + "\", \"" + b + "\")", false,
                        (m, run) -> run.linkHandles.put(l, m.addDamper3D(l, z, a, b)), l, a, b);
            case 17:
                return new Call("m.addSpringDamper1D(\"" + l + "\", " + d + ", " + k + ", " + z + ", \"" + a + "\", \""
                        + b + "\")", false, (m, run) -> run.linkHandles.put(l, m.addSpringDamper1D(l, d, k, z, a, b)),
                        l, a, b);
            case 18:
                return new Call("m.addRope3D(\"" + l + "\", " + d + ", " + k + ", " + z + ", \"" + a + "\", \"" + b
                        + "\")", false, (m, run) -> run.linkHandles.put(l, m.addRope3D(l, d, k, z, a, b)), l, a, b);
            case 19: case 20:
                return new Call("m.addContact3D(\"" + l + "\", " + d + ", " + k + ", " + z + ", \"" + a + "\", \"" + b
                        + "\")", false, (m, run) -> run.linkHandles.put(l, m.addContact3D(l, d, k, z, a, b)), l, a, b);
            case 21:
                return new Call("m.addBubble3D(\"" + l + "\", " + d + ", " + k + ", " + z + ", \"" + a + "\", \"" + b
                        + "\")", false, (m, run) -> run.linkHandles.put(l, m.addBubble3D(l, d, k, z, a, b)), l, a, b);
            case 22: {
                int axis = r.nextInt(4);
                double pos = value(r, -1, 1);
                return new Call("m.addPlaneContact(\"" + l + "\", " + d + ", " + k + ", " + z + ", " + axis + ", "
                        + pos + ", \"" + a + "\")", false,
                        (m, run) -> run.linkHandles.put(l, m.addPlaneContact(l, d, k, z, axis, pos, a)), l, a);
            }
            case 23: {
                double att = value(r, -1e-4, 1e-4) * ks;
                return new Call("m.addAttractor3D(\"" + l + "\", " + d + ", " + att + ", \"" + a + "\", \"" + b
                        + "\")", false, (m, run) -> run.linkHandles.put(l, m.addAttractor3D(l, d, att, a, b)), l, a, b);
            }
            case 24:
                return new Call("m.addSpringDamper3D(\"" + l + "\", " + d + ", " + k + ", " + z + ", handle(\"" + a
                        + "\"), handle(\"" + b + "\"))", false, (m, run) -> {
                            Mass ha = run.massHandles.get(a);
                            Mass hb = run.massHandles.get(b);
                            if (ha != null && hb != null) {
                                run.linkHandles.put(l, m.addSpringDamper3D(l, d, k, z, ha, hb));
                            }
                        }, l, a, b);
            case 25:
                return new Call("m.setMatPosition(\"" + a + "\", " + fmt(p) + ")", false,
                        (m, run) -> m.setMatPosition(a, p), a);
            case 26:
                return new Call("m.setMatVelocity(\"" + a + "\", " + fmt(v) + ")", false,
                        (m, run) -> m.setMatVelocity(a, v), a);
            case 27:
                return new Call("m.setMatMass(\"" + a + "\", " + mass + ")", false, (m, run) -> m.setMatMass(a, mass), a);
            case 28:
                return new Call("m.setMatStiffness(\"" + a + "\", " + k + ")", false,
                        (m, run) -> m.setMatStiffness(a, k), a);
            case 29:
                return new Call("m.setMatDamping(\"" + a + "\", " + z + ")", false, (m, run) -> m.setMatDamping(a, z), a);
            case 30: {
                double f = value(r, 20, fs / 3.0);
                double t = value(r, 0.05, 2);
                return new Call("m.tuneOsc(\"" + a + "\", " + f + ", " + t + ")", false, (m, run) -> m.tuneOsc(a, f, t),
                        a);
            }
            case 31: {
                double f = value(r, -1e-3, 1e-3) * ks;
                return new Call("m.triggerForceImpulse(\"" + a + "\", " + f + ", 0, " + f + ")", false,
                        (m, run) -> m.triggerForceImpulse(a, f, 0, f), a);
            }
            case 32:
                return new Call("m.setLinkStiffness(\"" + l + "\", " + k + ")", false,
                        (m, run) -> m.setLinkStiffness(l, k), l);
            case 33:
                return new Call("m.setLinkDamping(\"" + l + "\", " + z + ")", false, (m, run) -> m.setLinkDamping(l, z), l);
            case 34:
                return new Call("m.setLinkDRest(\"" + l + "\", " + d + ")", false, (m, run) -> m.setLinkDRest(l, d), l);
            case 35:
                return new Call("m.setLinkParams(\"" + l + "\", " + k + ", " + z + ", " + d + ")", false,
                        (m, run) -> m.setLinkParams(l, k, z, d), l);
            case 36:
                return new Call("m.setLinkStiffnessAt(" + idx + ", " + k + ")", false,
                        (m, run) -> m.setLinkStiffnessAt(idx, k), indexNames(idx));
            case 37:
                return new Call("m.setMatMassAt(" + idx + ", " + mass + ")", false, (m, run) -> m.setMatMassAt(idx, mass),
                        indexNames(idx));
            case 38:
                return new Call("m.setMatPosAt(" + idx + ", " + fmt(p) + ")", false, (m, run) -> m.setMatPosAt(idx, p),
                        indexNames(idx));
            case 39:
                return new Call("m.setHapticPosition(\"" + a + "\", " + fmt(p) + ")", false,
                        (m, run) -> m.setHapticPosition(a, p), a);
            case 40:
                return new Call("m.getHapticForce(\"" + a + "\")", false, (m, run) -> m.getHapticForce(a), a);
            case 41:
                return new Call("m.removeLink(\"" + l + "\")", false, (m, run) -> m.removeLink(l), l);
            case 42:
                return new Call("m.removeLink(" + idx + ")", false, (m, run) -> m.removeLink(idx), indexNames(idx));
            case 43: case 44:
                return new Call("m.removeMatAndConnectedLinks(\"" + a + "\")", false,
                        (m, run) -> m.removeMatAndConnectedLinks(a), a);
            case 45:
                return new Call("m.removeMatAndConnectedLinks(" + idx + ")", false,
                        (m, run) -> m.removeMatAndConnectedLinks(idx), indexNames(idx));
            case 46:
                return new Call("m.changeToFixedPoint(\"" + a + "\")", false,
                        (m, run) -> run.massHandles.put(a, m.changeToFixedPoint(a)), a);
            case 47:
                return new Call("m.clearModel()", true, (m, run) -> m.clearModel());
            case 48: case 49:
                return new Call("m.createMatSubset(\"" + s + "\")", false, (m, run) -> m.createMatSubset(s), s);
            case 50:
                return new Call("m.createLinkSubset(\"" + s + "\")", false, (m, run) -> m.createLinkSubset(s), s);
            case 51: case 52: case 53:
                return new Call("m.addMatToSubset(\"" + a + "\", \"" + s + "\")", false,
                        (m, run) -> m.addMatToSubset(a, s), a, s);
            case 54:
                return new Call("m.addLinkToSubset(\"" + l + "\", \"" + s + "\")", false,
                        (m, run) -> m.addLinkToSubset(l, s), l, s);
            case 55:
                return new Call("m.removeMatFromSubset(\"" + a + "\", \"" + s + "\")", false,
                        (m, run) -> m.removeMatFromSubset(a, s), a, s);
            case 56:
                return new Call("m.removeLinkFromSubset(\"" + l + "\", \"" + s + "\")", false,
                        (m, run) -> m.removeLinkFromSubset(l, s), l, s);
            case 57: {
                String param = r.nextInt(8) == 0 ? "colour" : new String[] {"mass", "stiffness", "damping", "dist"}
                        [r.nextInt(4)];
                double val = param.equals("stiffness") ? k : param.equals("damping") ? z
                        : param.equals("mass") ? mass : d;
                return new Call("m.changeParamOfSubset(" + val + ", \"" + s + "\", \"" + param + "\")", false,
                        (m, run) -> m.changeParamOfSubset(val, s, param), withPools(s, param));
            }
            case 58:
                return new Call("m.getParamValueOfSubset(\"" + s + "\", \"stiffness\")", false,
                        (m, run) -> m.getParamValueOfSubset(s, "stiffness"), withPools(s));
            case 59:
                return new Call("m.getBarycenterOfSubset(\"" + s + "\")", false, (m, run) -> m.getBarycenterOfSubset(s), s);
            case 60: case 61: {
                double thr = value(r, 0.05, 0.6);
                return new Call("m.addContactGroup(\"" + s + "\", " + thr + ", " + k + ", " + z + ")", false,
                        (m, run) -> m.addContactGroup(s, thr, k, z), s);
            }
            case 62: {
                double thr = value(r, 0.05, 0.6);
                return new Call("m.setContactGroupParams(\"" + s + "\", " + thr + ", " + k + ", " + z + ")", false,
                        (m, run) -> m.setContactGroupParams(s, thr, k, z), s);
            }
            case 63:
                return new Call("m.removeContactGroup(\"" + s + "\")", false, (m, run) -> m.removeContactGroup(s), s);
            case 64: {
                int rate = (int) pick(r, 1000, 2000, 4000, 44100, 300, 0, -5);
                return new Call("m.setSimRate(" + rate + ")", rate > 0, (m, run) -> m.setSimRate(rate),
                        String.valueOf(rate));
            }
            case 65: {
                int t = r.nextInt(40) == 0 ? Integer.MAX_VALUE : r.nextInt(5) - 1;
                return new Call("m.setThreads(" + t + ")", t >= 1 && t <= 64, (m, run) -> m.setThreads(t), String.valueOf(t));
            }
            case 66: {
                double g = value(r, 0, 1e-4) * ks;
                return new Call("m.setGravity(" + g + ")", false, (m, run) -> m.setGravity(g), String.valueOf(g));
            }
            case 67: {
                double f = value(r, 0, 0.01) * zs;
                return new Call("m.setFriction(" + f + ")", false, (m, run) -> m.setFriction(f), String.valueOf(f));
            }
            case 68: {
                StabilityPolicy pol = StabilityPolicy.values()[r.nextInt(StabilityPolicy.values().length)];
                return new Call("m.setStabilityPolicy(StabilityPolicy." + pol + ")", true,
                        (m, run) -> m.setStabilityPolicy(pol));
            }
            case 69: case 70:
                return new Call("m.init()", true, (m, run) -> m.init());
            case 71: case 72: case 73: case 74:
                return new Call("m.computeStep()", true, (m, run) -> m.computeStep());
            case 75: case 76: case 77: case 78: {
                int steps = r.nextInt(10) == 0 ? -1 : r.nextInt(200);
                return new Call("m.computeNSteps(" + steps + ")", steps >= 0, (m, run) -> m.computeNSteps(steps),
                        String.valueOf(steps));
            }
            case 79: case 80:
                return new Call("m.draw_physics()", true, (m, run) -> m.draw_physics());
            case 81: {
                int iv = (int) pick(r, 1, 7, 64, MAX_INTERVAL);
                return new Call("m.setDivergenceCheckInterval(" + iv + ")", true,
                        (m, run) -> m.setDivergenceCheckInterval(iv));
            }
            case 82:
                return new Call("m.clearDivergence()", true, (m, run) -> m.clearDivergence());
            case 83: {
                boolean on = r.nextBoolean();
                return new Call("m.setDivergenceListener(" + (on ? "e -> events++" : "null") + ")", true,
                        (m, run) -> m.setDivergenceListener(on ? e -> run.divergenceEvents++ : null));
            }
            case 84:
                return new Call("m.setMatPosition(\"" + a + "\", new Vect3D(1e13, 0, 0))", false,
                        (m, run) -> m.setMatPosition(a, new Vect3D(1e13, 0, 0)), a);
            case 85:
                return new Call("m.getPotentialEnergy()", true, (m, run) -> m.getPotentialEnergy());
            case 86:
                return new Call("m.describeStability()", true, (m, run) -> m.describeStability());
            case 87:
                return new Call("handle(\"" + a + "\").getPosition()", true, (m, run) -> {
                    Mass h = run.massHandles.get(a);
                    if (h != null) {
                        h.getPosition();
                    }
                }, a);
            case 88:
                return new Call("handle(\"" + a + "\").setPosition(" + fmt(p) + ")", false, (m, run) -> {
                    Mass h = run.massHandles.get(a);
                    if (h != null) {
                        h.setPosition(p);
                    }
                }, a);
            case 89:
                return new Call("((InertialMass) handle(\"" + a + "\")).setMass(" + mass + ")", false, (m, run) -> {
                    Mass h = run.massHandles.get(a);
                    if (h instanceof InertialMass) {
                        ((InertialMass) h).setMass(mass);
                    }
                }, a);
            case 90:
                return new Call("linkHandle(\"" + l + "\").getDistance()", true, (m, run) -> {
                    Interaction h = run.linkHandles.get(l);
                    if (h != null) {
                        h.getDistance();
                    }
                }, l);
            case 91:
                return new Call("linkHandle(\"" + l + "\") setStiffness(" + k + ")", false, (m, run) -> {
                    Interaction h = run.linkHandles.get(l);
                    if (h instanceof ElasticInteraction) {
                        ((ElasticInteraction) h).setStiffness(k);
                    } else if (h instanceof Spring3D) {
                        ((Spring3D) h).setStiffness(k);
                    }
                }, l);
            case 92: {
                double att = value(r, -1e-4, 1e-4) * ks;
                return new Call("((Attractor3D) linkHandle(\"" + l + "\")).setAttraction(" + att + ")", false,
                        (m, run) -> {
                            Interaction h = run.linkHandles.get(l);
                            if (h instanceof Attractor3D) {
                                ((Attractor3D) h).setAttraction(att);
                            }
                        }, l);
            }
            case 93:
                return new Call("m.getLinkMatNames(\"" + l + "\")", false, (m, run) -> m.getLinkMatNames(l), l);
            case 94: {
                int mc = r.nextInt(14) - 1;
                return new Call("m.setMaxContactsPerMass(" + mc + ")", mc >= 0, (m, run) -> m.setMaxContactsPerMass(mc),
                        String.valueOf(mc));
            }
            case 95: {
                Vect3D dir = vec(r);
                return new Call("m.setGravityDirection(" + fmt(dir) + ")", false,
                        (m, run) -> m.setGravityDirection(dir), "direction");
            }
            case 96:
                return new Call("m.getStabilityReport()", true, (m, run) -> m.getStabilityReport());
            case 97:
                return new Call("m.getTotalEnergy()", true, (m, run) -> m.getTotalEnergy());
            case 98: {
                int dr = (int) pick(r, 30, 60, 7, 0);
                return new Call("m.setDisplayRate(" + dr + ")", dr > 0, (m, run) -> m.setDisplayRate(dr),
                        String.valueOf(dr));
            }
            default:
                return new Call("m.getMatFrcAt(" + idx + ")", false, (m, run) -> m.getMatFrcAt(idx), indexNames(idx));
        }
    }

    // ------------------------------------------------------------------ checking

    /** The whole observable state, read through the public API (the text of {@link ModelState} and more). */
    static String snapshot(PhysicalModel m) {
        StringBuilder sb = new StringBuilder(ModelState.of(m));
        for (String s : SUBSETS) {
            String members;
            try {
                members = String.join(",", m.getSubsetMembers(s));
            } catch (IllegalArgumentException e) {
                members = "-";
            }
            sb.append("subset ").append(s).append(' ').append(members).append(" group ").append(m.hasContactGroup(s))
                    .append('\n');
        }
        sb.append("policy ").append(m.getStabilityPolicy()).append(" threads ").append(m.getThreads())
                .append(" diverged ").append(m.isDiverged()).append('\n');
        sb.append("energy ").append(m.getKineticEnergy()).append(' ').append(m.getPotentialEnergy()).append('\n');
        sb.append(m.describeStability()).append('\n');
        return sb.toString();
    }

    /** @return a description of the first non-finite value visible through the API, or null. */
    static String nonFinite(PhysicalModel m) {
        if (!Double.isFinite(m.getGravity()) || !Double.isFinite(m.getFriction())) {
            return "medium";
        }
        for (int i = 0; i < m.getNumberOfMats(); i++) {
            if (!m.getMatPosAt(i).isFinite() || !m.getMatVelAt(i).isFinite() || !m.getMatFrcAt(i).isFinite()) {
                return "state of mass " + m.getMatNameAt(i);
            }
        }
        for (int i = 0; i < m.getNumberOfLinks(); i++) {
            if (!Double.isFinite(m.getLinkStiffnessAt(i)) || !Double.isFinite(m.getLinkDampingAt(i))
                    || !Double.isFinite(m.getLinkDRestAt(i))) {
                return "parameters of link " + m.getLinkNameAt(i);
            }
        }
        return null;
    }

    static boolean documented(Throwable t) {
        return t instanceof IllegalArgumentException || t instanceof IllegalStateException;
    }

    static String describe(Throwable t) {
        StackTraceElement[] st = t.getStackTrace();
        String where = st.length > 0 ? st[0].getClassName().replace("tactus.", "") + "." + st[0].getMethodName() : "?";
        return t.getClass().getSimpleName() + " at " + where + ": " + t.getMessage();
    }

    static String method(Call c) {
        String t = c.text;
        int p = t.indexOf('(');
        return p < 0 ? t : t.substring(0, p);
    }

    /**
     * Replays the calls on a fresh run and returns the first broken invariant, or null. Output to System.err
     * (stability warnings) is discarded.
     */
    static Violation replay(List<Call> calls) {
        PrintStream err = System.err;
        System.setErr(new PrintStream(java.io.OutputStream.nullOutputStream()));
        try {
            return check(calls);
        } finally {
            System.setErr(err);
        }
    }

    /**
     * Kinds of failure to step over while exploring (system property {@code tactus.fuzz.ignore}, '|'-separated
     * prefixes): the run calls clearDivergence() and goes on, so that known failures do not hide others.
     */
    static final String[] IGNORE = System.getProperty("tactus.fuzz.ignore", "").isEmpty() ? new String[0]
            : System.getProperty("tactus.fuzz.ignore").split("\\|");

    static boolean ignored(Violation v) {
        for (String p : IGNORE) {
            if (v.kind.startsWith(p)) {
                return true;
            }
        }
        return false;
    }

    private static Violation check(List<Call> calls) {
        Run run = new Run();
        calls.get(0).op.apply(null, run);
        PhysicalModel m = run.model;
        String before = snapshot(m);
        for (int i = 1; i < calls.size(); i++) {
            Call c = calls.get(i);
            Throwable thrown = null;
            try {
                c.op.apply(m, run);
            } catch (Throwable t) {
                thrown = t;
            }
            run.diverged |= thrown instanceof DivergenceException || run.divergenceEvents > 0 || m.isDiverged();
            String[] after = new String[1];
            Violation v = afterCall(m, run, c, i, thrown, before, after);
            if (v != null && ignored(v)) {
                try {
                    m.clearDivergence();
                    after[0] = snapshot(m);
                    v = null;
                } catch (Throwable t) {
                    return v;
                }
            }
            if (v != null) {
                return v;
            }
            before = after[0];
        }
        return null;
    }

    /** Checks the invariants after call i; stores the new snapshot in after[0]. */
    private static Violation afterCall(PhysicalModel m, Run run, Call c, int i, Throwable thrown, String before,
                                       String[] after) {
        try {
            after[0] = snapshot(m);
        } catch (Throwable t) {
            return new Violation("a reader throws " + t.getClass().getSimpleName() + " after " + method(c),
                    describe(t), i);
        }
        if (thrown != null) {
            if (!documented(thrown)) {
                return new Violation(method(c) + " throws " + thrown.getClass().getSimpleName(), describe(thrown), i);
            }
            String msg = thrown.getMessage();
            if (msg == null || msg.isEmpty()) {
                return new Violation(method(c) + " throws without a message", describe(thrown), i);
            }
            if (thrown instanceof IllegalArgumentException && c.argless) {
                return new Violation(method(c) + " throws IllegalArgumentException"
                        + (run.diverged ? " (after a divergence)" : ""), describe(thrown), i);
            }
            if (thrown instanceof IllegalArgumentException && c.names.length > 0) {
                boolean named = false;
                for (String nm : c.names) {
                    named |= msg.contains(nm);
                }
                if (!named) {
                    return new Violation(method(c) + " message does not name the element",
                            describe(thrown) + " (expected one of " + String.join(", ", c.names) + ")", i);
                }
            }
            if (!(thrown instanceof DivergenceException) && !after[0].equals(before)) {
                return new Violation("rejected " + method(c) + " changed the model", describe(thrown) + "\n"
                        + diff(before, after[0]), i);
            }
        }
        String bad;
        try {
            bad = nonFinite(m);
        } catch (Throwable t) {
            return new Violation("a reader throws " + t.getClass().getSimpleName() + " after " + method(c),
                    describe(t), i);
        }
        if (bad != null && !m.isDiverged()) {
            if (run.nonFiniteSince < 0) {
                run.nonFiniteSince = m.getStepCount();
            } else if (m.getStepCount() - run.nonFiniteSince > MAX_INTERVAL) {
                return new Violation("non-finite " + (bad.startsWith("param") ? "parameter" : "state")
                        + " not flagged as diverged", bad + " after " + (m.getStepCount() - run.nonFiniteSince)
                        + " steps", i);
            }
            if (bad.startsWith("param") || bad.equals("medium")) {
                return new Violation("non-finite parameter after " + method(c), bad, i);
            }
        } else {
            run.nonFiniteSince = -1;
        }
        return null;
    }

    static String diff(String a, String b) {
        String[] x = a.split("\n");
        String[] y = b.split("\n");
        StringBuilder sb = new StringBuilder();
        for (int i = 0; i < Math.max(x.length, y.length); i++) {
            String p = i < x.length ? x[i] : "";
            String q = i < y.length ? y[i] : "";
            if (!p.equals(q)) {
                sb.append("  before: ").append(p).append("\n  after:  ").append(q).append('\n');
            }
        }
        return sb.toString();
    }

    /** Shrinks a failing sequence (ending at the failing call) to a 1-minimal one with the same kind of failure. */
    static List<Call> shrink(List<Call> calls, String kind) {
        List<Call> cur = new ArrayList<>(calls);
        int chunk = Math.max(1, (cur.size() - 1) / 2);
        while (chunk >= 1) {
            boolean removed = false;
            for (int start = 1; start < cur.size() - 1; ) {
                int end = Math.min(cur.size() - 1, start + chunk);   // never remove the constructor or the last call
                List<Call> trial = new ArrayList<>(cur.subList(0, start));
                trial.addAll(cur.subList(end, cur.size()));
                Violation v = replay(trial);
                if (v != null && v.kind.equals(kind)) {
                    cur = new ArrayList<>(trial.subList(0, v.at + 1));
                    removed = true;
                } else {
                    start = end;
                }
            }
            if (!removed) {
                chunk /= 2;
            }
        }
        return cur;
    }

    /** Runs the seeds and returns the shrunk first reproduction of each distinct kind of failure. */
    static Map<String, String> findFailures(long firstSeed, int seeds, int calls) {
        Map<String, String> found = new LinkedHashMap<>();
        for (long seed = firstSeed; seed < firstSeed + seeds; seed++) {
            List<Call> seq = generate(seed, calls);
            Violation v = replay(seq);
            if (v == null || found.containsKey(v.kind)) {
                continue;
            }
            List<Call> small = shrink(seq.subList(0, v.at + 1), v.kind);
            Violation again = replay(small);
            StringBuilder sb = new StringBuilder();
            sb.append("seed ").append(seed).append(", call ").append(v.at).append(", shrunk to ")
                    .append(small.size() - 1).append(" calls:\n");
            for (Call c : small) {
                sb.append("    ").append(c.text).append(";\n");
            }
            sb.append("  -> ").append(again != null ? again.detail : v.detail).append('\n');
            found.put(v.kind, sb.toString());
        }
        return found;
    }

    @Test
    @Timeout(120)
    void randomApiSequencesKeepTheInvariants() {
        Map<String, String> found = findFailures(1, SEEDS, CALLS);
        if (!found.isEmpty()) {
            StringBuilder sb = new StringBuilder(found.size() + " kind(s) of failure in " + SEEDS + " sequences of "
                    + CALLS + " calls:\n");
            found.forEach((k, v) -> sb.append("* ").append(k).append("\n  ").append(v));
            fail(sb.toString());
        }
    }

    /** The checker itself must see a broken invariant: a rejected call that changed the model is reported. */
    @Test
    void theCheckerCatchesAChangeMadeByARejectedCall() {
        List<Call> calls = new ArrayList<>();
        calls.add(new Call("new PhysicalModel(1000)", true, (m, run) -> run.model = new PhysicalModel(1000)));
        calls.add(new Call("m.addMass3D(\"m0\", ...)", false,
                (m, run) -> m.addMass3D("m0", 1, new Vect3D(), new Vect3D()), "m0"));
        calls.add(new Call("move m0 then reject", false, (m, run) -> {
            m.setMatPosition("m0", new Vect3D(1, 0, 0));
            throw new IllegalArgumentException("rejected \"m0\"");
        }, "m0"));
        calls.add(new Call("m.computeStep()", true, (m, run) -> m.computeStep()));
        Violation v = replay(calls);
        assertTrue(v != null && v.kind.startsWith("rejected move m0") && v.at == 2, v == null ? "none" : v.kind);
        List<Call> undocumented = new ArrayList<>(calls.subList(0, 2));
        undocumented.add(new Call("npe", true, (m, run) -> {
            throw new NullPointerException("x");
        }));
        v = replay(undocumented);
        assertTrue(v != null && v.kind.equals("npe throws NullPointerException"), v == null ? "none" : v.kind);
        // and a sequence is reproducible: the same seed gives the same calls
        assertTrue(generate(7, 50).toString().equals(generate(7, 50).toString()));
    }

    // ------------------------------------------------------------------ three threads

    /**
     * One thread steps, one edits parameters and topology (removing and re-adding masses and links), one reads
     * through names and through handles obtained before the edits. Every exception that escapes must be a
     * documented one of the right kind: a removed element read by name gives IllegalArgumentException naming it,
     * a stale handle gives IllegalStateException, stepping never throws (the model stays stable).
     */
    @Test
    @Timeout(60)
    void threeThreadsOnlyEverSeeDocumentedExceptions() throws Exception {
        for (int round = 0; round < 4; round++) {
            threeThreadRound(round);
        }
    }

    static void threeThreadRound(long seed) throws Exception {
        PhysicalModel m = new PhysicalModel(1000, 60);
        m.setStabilityPolicy(StabilityPolicy.OFF);
        m.addGround3D("g", new Vect3D(0, 0, 0));
        for (int i = 0; i < 6; i++) {
            m.addMass3D("m" + i, 1, new Vect3D(0.1 * (i + 1), 0, 0), new Vect3D());
            m.addSpringDamper3D("l" + i, 0.1, 0.05, 0.001, i == 0 ? "g" : "m" + (i - 1), "m" + i);
        }
        m.createMatSubset("s0");
        m.init();
        AtomicBoolean stop = new AtomicBoolean();
        AtomicReference<Throwable> error = new AtomicReference<>();
        Thread stepper = new Thread(() -> {
            try {
                while (!stop.get()) {
                    m.computeNSteps(3);
                    m.computeStep();
                    m.draw_physics();
                }
            } catch (Throwable t) {
                error.compareAndSet(null, new AssertionError("stepping threw " + describe(t), t));
            }
        }, "stepper");
        Thread editor = new Thread(() -> {
            SplittableRandom r = new SplittableRandom(seed);
            try {
                for (int n = 0; n < 20_000 && error.get() == null; n++) {
                    int i = r.nextInt(6);
                    String mass = "m" + i;
                    String link = "l" + i;
                    try {
                        switch (r.nextInt(8)) {
                            case 0:
                                m.removeMatAndConnectedLinks(mass);
                                break;
                            case 1:
                                m.addMass3D(mass, 1, new Vect3D(0.1 * (i + 1), 0, 0), new Vect3D());
                                break;
                            case 2:
                                m.addSpringDamper3D(link, 0.1, 0.05, 0.001, i == 0 ? "g" : "m" + (i - 1), mass);
                                break;
                            case 3:
                                m.setLinkStiffness(link, 0.01 + 0.05 * r.nextDouble());
                                break;
                            case 4:
                                m.setMatMass(mass, 0.5 + r.nextDouble());
                                break;
                            case 5:
                                m.addMatToSubset(mass, "s0");
                                break;
                            case 6:
                                m.changeMassParamOfSubset(0.5 + r.nextDouble(), "s0");
                                break;
                            default:
                                m.setMatPosition(mass, new Vect3D(0.1 * (i + 1), 0.01 * r.nextDouble(), 0));
                        }
                    } catch (IllegalArgumentException e) {
                        if (!e.getMessage().contains(mass) && !e.getMessage().contains(link)) {
                            throw new AssertionError("message names neither " + mass + " nor " + link, e);
                        }
                    }
                }
            } catch (Throwable t) {
                error.compareAndSet(null, t);
            }
        }, "editor");
        Thread reader = new Thread(() -> {
            SplittableRandom r = new SplittableRandom(seed + 100);
            try {
                while (!stop.get()) {
                    String mass = "m" + r.nextInt(6);
                    Mass h;
                    try {
                        h = m.getMass(mass);
                    } catch (IllegalArgumentException e) {
                        continue;   // not there now: fine, named
                    }
                    for (int k = 0; k < 20; k++) {
                        try {
                            if (!h.getPosition().isFinite() || !Double.isFinite(h.getVelocity().x)) {
                                throw new AssertionError("non-finite state through a handle");
                            }
                            h.getForce();
                            h.getName();
                        } catch (IllegalStateException e) {
                            if (h.isValid()) {
                                throw new AssertionError("IllegalStateException from a valid handle", e);
                            }
                            break;
                        }
                    }
                    try {
                        m.getMatPosition(mass);
                        m.getTotalEnergy();
                        m.describeStability();
                    } catch (IllegalArgumentException e) {
                        if (!e.getMessage().contains(mass)) {
                            throw new AssertionError("message does not name " + mass, e);
                        }
                    }
                }
            } catch (Throwable t) {
                error.compareAndSet(null, new AssertionError("reader: " + describe(t), t));
            }
        }, "reader");
        stepper.start();
        reader.start();
        editor.start();
        editor.join();
        stop.set(true);
        stepper.join();
        reader.join();
        if (error.get() != null) {
            throw new AssertionError("round " + seed + ": " + error.get().getMessage(), error.get());
        }
    }

    /** Prints the shrunk failures of a seed range: {@code java ... ApiSequenceFuzzTest first count calls}. */
    public static void main(String[] args) {
        long first = args.length > 0 ? Long.parseLong(args[0]) : 1;
        int seeds = args.length > 1 ? Integer.parseInt(args[1]) : SEEDS;
        int calls = args.length > 2 ? Integer.parseInt(args[2]) : CALLS;
        long t0 = System.nanoTime();
        Map<String, String> found = findFailures(first, seeds, calls);
        found.forEach((k, v) -> System.out.println("* " + k + "\n  " + v));
        System.out.printf("%d kinds in %.1f s%n", found.size(), (System.nanoTime() - t0) / 1e9);
    }
}
