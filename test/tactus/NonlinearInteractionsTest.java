package tactus;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.function.BiFunction;
import java.util.function.Function;
import org.junit.jupiter.api.Test;

/**
 * mi.lib's six nonlinear interactions through the facade, in 1-D and 3-D: a mass tied to a fixed point by each one
 * follows, step by step, a reference integrator written here from mi.lib's equations (the scheme's
 * {@code x(n+1) = 2x(n) - x(n-1) + F/M}); handles read and write their parameters, in both unit systems;
 * invalid values are refused with the element named and the model unchanged; subsets change them.
 */
class NonlinearInteractionsTest {
    private static final int STEPS = 400;
    private static final double M = 1.0;

    /** mi.lib's F from its displacement and velocity (per step), for the 1-D laws. */
    interface Law {
        double f(double e, double v);
    }

    // mi.lib's equations, written directly (see /usr/share/faust/mi.lib)
    static Law quadratic(double k, double q, double z) {
        return (e, v) -> k * e + q * Math.signum(e) * e * e + z * v;
    }

    static Law cubic(double k, double q, double z) {
        return (e, v) -> k * e + q * e * e * e + z * v;
    }

    static Law clipped(double s, double c, double k, double z) {
        double b = Math.sqrt(k - s) / c;
        return (e, v) -> Math.abs(e) <= b ? s * e + c * e * e * e + z * v : k * e + (z + 0.3 * k) * v;
    }

    static Law pluck(double k, double scale, double z) {
        double tip = scale / 10, kEnd = k / 10;
        return (e, v) -> Math.abs(e) < tip ? (k - kEnd) * -e + z * v
                : Math.abs(e) < scale ? Math.signum(e) * -tip * k + kEnd * e + z * v : 0;
    }

    static Law bow(double z, double scale) {
        double tip = scale / 3, zEnd = z / 3;
        return (e, v) -> Math.abs(v) < tip ? (z - zEnd) * v
                : Math.abs(v) < scale ? Math.signum(v) * tip * z - zEnd * v : 0;
    }

    /**
     * A 1-D mass at z0 with velocity v0 (per step) under a link to a ground at 0 (mass 1 the mass, mass 2 the
     * ground), the link's law taking mi.lib's displacement {@code z - l0} (or {@code z + t} for a collision).
     */
    private static void follows1D(String what, Function<PhysicalModel, Interaction> add, Law law, double offset,
                                  double threshold, double z0, double v0) {
        PhysicalModel m = new PhysicalModel(1000);
        m.addMass1D("mass", M, new Vect3D(0, 0, z0), new Vect3D(0, 0, v0 * 1000));
        m.addGround1D("ground", new Vect3D(0, 0, 0));
        Interaction h = add.apply(m);
        assertEquals(what, h.getType());
        m.init();
        double x = z0, xp = z0 - v0, f = 0, moved = 0;
        for (int n = 0; n < STEPS; n++) {
            double xn = 2 * x - xp + f / M;
            xp = x;
            x = xn;
            boolean engaged = Double.isNaN(threshold) || -x < threshold;
            f = engaged ? -law.f(x - offset, x - xp) : 0;
            m.computeStep();
            double got = m.getMatPosition("mass").z;
            assertEquals(x, got, 1e-12 * Math.max(1, Math.abs(x)), what + " at step " + n);
            moved = Math.max(moved, Math.abs(x - z0));
        }
        assertTrue(moved > 1e-3, what + ": the mass must move for the comparison to mean anything, moved " + moved);
    }

    /** The same in 3-D, the mass at p0 moving with v0 (per step) and the law acting along the unit vector X / |X|. */
    private static void follows3D(String what, Function<PhysicalModel, Interaction> add,
                                  BiFunction<double[], double[], double[]> force, double[] p0, double[] v0) {
        PhysicalModel m = new PhysicalModel(1000);
        m.addMass3D("mass", M, new Vect3D(p0[0], p0[1], p0[2]),
                new Vect3D(v0[0] * 1000, v0[1] * 1000, v0[2] * 1000));
        m.addGround3D("ground", new Vect3D(0, 0, 0));
        Interaction h = add.apply(m);
        assertEquals(what, h.getType());
        m.init();
        double[] x = p0.clone(), xp = {p0[0] - v0[0], p0[1] - v0[1], p0[2] - v0[2]}, f = new double[3];
        double moved = 0;
        for (int n = 0; n < STEPS; n++) {
            for (int a = 0; a < 3; a++) {
                double xn = 2 * x[a] - xp[a] + f[a] / M;
                xp[a] = x[a];
                x[a] = xn;
            }
            f = force.apply(x, xp);
            m.computeStep();
            Vect3D got = m.getMatPosition("mass");
            double[] g = {got.x, got.y, got.z};
            for (int a = 0; a < 3; a++) {
                assertEquals(x[a], g[a], 1e-12, what + " axis " + a + " at step " + n);
            }
            moved = Math.max(moved, Math.abs(x[0] - p0[0]) + Math.abs(x[1] - p0[1]));
        }
        assertTrue(moved > 1e-3, what + ": the mass must move, moved " + moved);
    }

    private static double norm(double[] a) {
        return Math.sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    }

    /** Force on mass 1 of a 3-D elastic kind: -F(d - l0, d - dPrev) along X/d. */
    private static BiFunction<double[], double[], double[]> along(Law law, double l0) {
        return (x, xp) -> {
            double d = norm(x), dp = norm(xp);
            double s = -law.f(d - l0, d - dp) / d;
            return new double[] {s * x[0], s * x[1], s * x[2]};
        };
    }

    @Test
    void theQuadraticSpringsFollowMiLib() {
        follows1D("QuadraticSpringDamper1D", m -> m.addQuadraticSpringDamper1D("l", 0.1, 0.01, 0.001, 2.0,
                "mass", "ground"), quadratic(0.01, 2.0, 0.001), 0.1, Double.NaN, 0.35, 0.001);
        follows3D("QuadraticSpringDamper3D", m -> m.addQuadraticSpringDamper3D("l", 0.2, 0.01, 0.001, 2.0,
                "mass", "ground"), along(quadratic(0.01, 2.0, 0.001), 0.2), new double[] {0.3, 0.4, 0},
                new double[] {0, 0.002, 0.001});
    }

    @Test
    void theCubicSpringsFollowMiLib() {
        follows1D("CubicSpringDamper1D", m -> m.addCubicSpringDamper1D("l", 0, 0.01, 0.001, 3.0, "mass", "ground"),
                cubic(0.01, 3.0, 0.001), 0, Double.NaN, 0.3, 0);
        follows3D("CubicSpringDamper3D", m -> m.addCubicSpringDamper3D("l", 0.2, 0.01, 0.001, 3.0, "mass", "ground"),
                along(cubic(0.01, 3.0, 0.001), 0.2), new double[] {0.3, 0.4, 0}, new double[] {0.001, 0, 0});
    }

    @Test
    void theClippedSpringsFollowMiLibOnBothSidesOfTheClip() {
        // b = sqrt(0.04 - 0.01) / 0.5 = 0.346: the mass swings through the cubic and the clipped parts
        follows1D("ClippedSpringDamper1D", m -> m.addClippedSpringDamper1D("l", 0, 0.01, 0.0005, 0.5, 0.04,
                "mass", "ground"), clipped(0.01, 0.5, 0.04, 0.0005), 0, Double.NaN, 0.5, 0);
        follows3D("ClippedSpringDamper3D", m -> m.addClippedSpringDamper3D("l", 0.1, 0.01, 0.0005, 0.5, 0.04,
                "mass", "ground"), along(clipped(0.01, 0.5, 0.04, 0.0005), 0.1), new double[] {0.3, 0.4, 0},
                new double[] {0, 0, 0.002});
    }

    @Test
    void thePlucksFollowMiLib() {
        follows1D("Pluck1D", m -> m.addPluck1D("l", 0, 0.02, 0.0005, 0.5, "mass", "ground"),
                pluck(0.02, 0.5, 0.0005), 0, Double.NaN, 0.01, 0.002);
        follows3D("Pluck3D", m -> m.addPluck3D("l", 0.45, 0.02, 0.0005, 0.5, "mass", "ground"),
                along(pluck(0.02, 0.5, 0.0005), 0.45), new double[] {0.3, 0.4, 0}, new double[] {0.003, 0.001, 0});
    }

    @Test
    void theBowsFollowMiLib() {
        follows1D("Bow1D", m -> m.addBow1D("l", 0.5, 0.01, 0, "mass", "ground"), bow(0.5, 0.01), 0, Double.NaN,
                0.1, 0.02);
        Law b = bow(0.5, 0.01);
        follows3D("Bow3D", m -> m.addBow3D("l", 0.5, 0.01, 0, "mass", "ground"), (x, xp) -> {
            double[] w = {x[0] - xp[0], x[1] - xp[1], x[2] - xp[2]};
            double n = norm(w);
            double s = n > 0 ? -b.f(0, n) / n : 0;
            return new double[] {s * w[0], s * w[1], s * w[2]};
        }, new double[] {0.3, 0.4, 0}, new double[] {0.01, 0.02, 0});
    }

    @Test
    void theClippedContactsFollowMiLib() {
        // the mass (mass 1) starts 0.02 below the ground (mass 2) with a threshold of 0.1, moving up into it
        follows1D("ClippedContact1D", m -> m.addClippedContact1D("l", 0.1, 0.01, 0.001, 0.5, 0.04, "mass", "ground"),
                clipped(0.01, 0.5, 0.04, 0.001), -0.1, 0.1, -0.2, 0.004);
        Law c = clipped(0.01, 0.5, 0.04, 0.001);
        follows3D("ClippedContact3D", m -> m.addClippedContact3D("l", 0.6, 0.01, 0.001, 0.5, 0.04, "mass", "ground"),
                (x, xp) -> {
                    double d = norm(x), dp = norm(xp);
                    if (d >= 0.6) {
                        return new double[3];
                    }
                    double s = c.f(0.6 - d, dp - d) / d;
                    return new double[] {s * x[0], s * x[1], s * x[2]};
                }, new double[] {0.3, 0.4, 0}, new double[] {0.002, 0.001, 0});
    }

    @Test
    void handlesReadAndWriteTheirParametersInRealUnits() {
        PhysicalModel m = new PhysicalModel(1000, paramSystem.REAL_UNITS);
        m.addMass3D("a", 1, new Vect3D(0, 0, 0), new Vect3D());
        m.addMass3D("b", 1, new Vect3D(1, 0, 0), new Vect3D());
        ClippedSpringDamper3D c = m.addClippedSpringDamper3D("c", 1, 100, 0.1, 5e3, 400, "a", "b");
        Bow3D bow = m.addBow3D("bow", 2, 0.3, 1, "a", "b");
        Pluck3D p = m.addPluck3D("p", 1, 50, 0.1, 0.02, "a", "b");
        QuadraticSpringDamper3D q = m.addQuadraticSpringDamper3D("q", 1, 10, 0, 30, "a", "b");
        m.init();
        assertEquals(5e3, c.getCubicStiffness(), 1e-9);
        assertEquals(400, c.getMaxStiffness(), 1e-12);
        assertEquals(100, c.getStiffness(), 1e-12);
        assertEquals(0.3, bow.getScale(), 1e-15);
        assertEquals(1, bow.getProfile());
        assertEquals(2, bow.getDamping(), 1e-15);
        assertEquals(0.02, p.getScale(), 0);
        assertEquals(30, q.getQuadraticStiffness(), 1e-12);
        c.setMaxStiffness(800);
        bow.setScale(0.5);
        bow.setProfile(0);
        assertEquals(800, c.getExtraParameter("Kmax"), 1e-12);
        assertEquals(0.5, bow.getExtraParameter("scale"), 1e-15);
        assertEquals(0, bow.getProfile());
        // switching the rate keeps the values in newtons and seconds
        m.setSimRate(2000);
        assertEquals(800, c.getMaxStiffness(), 1e-9);
        assertEquals(0.5, bow.getScale(), 1e-12);
        assertEquals(5e3, c.getCubicStiffness(), 1e-6);
        assertEquals(linkModuleType.Bow3D, m.getLinkTypeAt(1));
        assertSame(bow, m.getInteractionAt(1));
    }

    @Test
    void invalidValuesAreRefusedAndLeaveTheModelUnchanged() {
        PhysicalModel m = new PhysicalModel(1000);
        m.addMass1D("a", 1, new Vect3D(0, 0, 0), new Vect3D());
        m.addGround1D("g", new Vect3D(0, 0, 1));
        Bow1D bow = m.addBow1D("bow", 0.1, 0.01, 0, "a", "g");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> bow.setProfile(2));
        assertTrue(e.getMessage().contains("bow") && e.getMessage().contains("profile"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> bow.setScale(0));
        assertThrows(IllegalArgumentException.class, () -> bow.setExtraParameter("Kmax", 1));
        assertEquals(0.01, bow.getScale(), 0);
        int links = m.getNumberOfLinks();
        e = assertThrows(IllegalArgumentException.class,
                () -> m.addPluck1D("pl", 0, 0.1, 0, -1, "a", "g"));
        assertTrue(e.getMessage().contains("pl") && e.getMessage().contains("scale"), e.getMessage());
        assertThrows(IllegalArgumentException.class,
                () -> m.addClippedContact1D("cc", 0.1, 0.1, 0, -2, 1, "a", "g"));
        assertThrows(IllegalArgumentException.class,
                () -> m.addCubicSpringDamper1D("cs", 0, 0.1, 0, Double.NaN, "a", "g"));
        assertEquals(links, m.getNumberOfLinks(), "a refused add adds nothing");
    }

    @Test
    void subsetsAndTheGenericAddReachThem() {
        PhysicalModel m = new PhysicalModel(1000);
        m.addMass1D("a", 1, new Vect3D(0, 0, 0), new Vect3D());
        m.addGround1D("g", new Vect3D(0, 0, 1));
        CubicSpringDamper1D s = m.addCubicSpringDamper1D("s", 0, 0.1, 0, 2, "a", "g");
        Interaction c = m.addInteraction(linkModuleType.ClippedContact1D, "c", 0.1, 0.2, 0.01,
                new double[] {0.5, 0.4}, "a", "g");
        assertTrue(c instanceof ClippedContact1D);
        assertEquals(0.4, ((ClippedContact1D) c).getMaxStiffness(), 0);
        m.createLinkSubset("nl");
        m.addLinkToSubset("s", "nl");
        m.addLinkToSubset("c", "nl");
        m.changeStiffnessParamOfSubset(0.05, "nl");
        assertEquals(0.05, s.getStiffness(), 0);
        assertEquals(0.05, ((ClippedContact1D) c).getStiffness(), 0);
        assertEquals(2, s.getCubicStiffness(), 0);
        assertThrows(IllegalArgumentException.class, () -> m.addInteraction(linkModuleType.Spring3D, "x", 0, 1, 0,
                new double[0], "a", "g"));
    }

    @Test
    void thePotentialEnergyIsTheLawsIntegral() {
        PhysicalModel m = new PhysicalModel(1000);
        m.addMass1D("a", 1, new Vect3D(0, 0, 0.3), new Vect3D());
        m.addGround1D("g", new Vect3D(0, 0, 0));
        m.addCubicSpringDamper1D("s", 0.1, 0.01, 0, 3, "a", "g");
        m.init();
        double e = 0.2;
        assertEquals(0.5 * 0.01 * e * e + 0.25 * 3 * e * e * e * e, m.getPotentialEnergy(), 1e-15);
    }

    /**
     * While a stand-in audio thread owns and steps the model, extra parameters set from another thread go through
     * the queued path: each one reaches the model between two steps, in order, whether set on the handle or by name.
     */
    @Test
    void extraParametersReachAModelThatAnotherThreadSteps() throws Exception {
        PhysicalModel m = new PhysicalModel(1000);
        m.addMass1D("a", 1, new Vect3D(0, 0, 0.1), new Vect3D());
        m.addGround1D("g", new Vect3D(0, 0, 0));
        ClippedSpringDamper1D c = m.addClippedSpringDamper1D("c", 0, 0.01, 0.001, 0.5, 0.04, "a", "g");
        Bow1D b = m.addBow1D("b", 0.1, 0.01, 0, "a", "g");
        m.init();
        m.beginRealtimeStepping();
        OwnerLoop owner = new OwnerLoop(m, 64, 100_000L, "audio").begin();
        try {
            for (int k = 1; k <= 20; k++) {
                c.setMaxStiffness(0.04 + 0.001 * k);
                b.setExtraParameter("scale", 0.01 * k);
                b.setProfile(k % 2);
            }
            assertTrue(owner.awaitCalls(3));
            assertEquals(0.06, c.getMaxStiffness(), 1e-15);
            assertEquals(0.2, b.getScale(), 1e-15);
            assertEquals(0, b.getProfile());
            assertSame(null, owner.firstError.get());
        } finally {
            assertTrue(owner.halt());
            m.endRealtimeStepping();
        }
    }
}
