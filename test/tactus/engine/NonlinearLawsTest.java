package tactus.engine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * The nonlinear laws against a direct evaluation of mi.lib's own equations, transcribed here as mi.lib writes
 * them ({@code select2(c, else, then)}, {@code ma.signum}, {@code pow}), over a grid of displacements and
 * velocities that crosses every branch; their potentials against the integral of their elastic force; their
 * stability bounds against the slopes they reach.
 */
class NonlinearLawsTest {
    /** Faust's select2: the second branch when the condition holds, else the first. */
    private static double select2(boolean c, double whenFalse, double whenTrue) {
        return c ? whenTrue : whenFalse;
    }

    private static double signum(double x) {
        return x > 0 ? 1 : x < 0 ? -1 : 0;
    }

    // mi.lib, transcribed: F before "<: *(-1), _"
    static double miNlSpringDamper2(double k, double q, double z, double dp, double dv) {
        return k * dp + q * signum(dp) * Math.pow(dp, 2) + z * dv;
    }

    static double miNlSpringDamper3(double k, double q, double z, double dp, double dv) {
        return k * dp + q * Math.pow(dp, 3) + z * dv;
    }

    static double miNlSpringDamperClipped(double s, double c, double k, double z, double dp, double dv) {
        double b = Math.sqrt(k - s) / c;
        return select2(c == 0,
                select2(s >= k,
                        select2(Math.abs(dp) <= b, k * dp + (z + 0.3 * k) * dv, s * dp + c * Math.pow(dp, 3) + z * dv),
                        k * dp + z * dv),
                s * dp + z * dv);
    }

    static double miNlPluck(double k, double scale, double z, double dp, double dv) {
        double tipdist = scale / 10, kEnd = k / 10, a = Math.abs(dp);
        return select2(a < tipdist,
                select2(a < scale, 0, signum(dp) * -tipdist * k + kEnd * dp + z * dv),
                (k - kEnd) * -dp + z * dv);
    }

    static double miNlBow(double z, double scale, double type, double dv) {
        double tipvel = scale / 3, zEnd = z / 3, a = Math.abs(dv);
        return select2(type > 0,
                select2(a < tipvel, select2(a < scale, 0, signum(dv) * tipvel * z - zEnd * dv), (z - zEnd) * dv),
                0.63 * z * dv * Math.exp(-4 * Math.pow(dv / scale, 2) + 0.5));
    }

    private static final double[] VELOCITIES = {-0.02, -0.003, 0, 0.0004, 0.01, 0.05};

    private static void close(double expected, double actual, String what) {
        assertEquals(expected, actual, 1e-14 * Math.max(1, Math.abs(expected)), what);
    }

    @Test
    void theSpringsFollowMiLib() {
        double k = 0.01, q = 0.3, z = 0.002;
        int checked = 0;
        for (double e = -1.5; e <= 1.5; e += 0.0371) {
            for (double v : VELOCITIES) {
                close(miNlSpringDamper2(k, q, z, e, v), NonlinearLaws.quadratic(k, q, z, e, v), "quadratic " + e);
                close(miNlSpringDamper3(k, q, z, e, v), NonlinearLaws.cubic(k, q, z, e, v), "cubic " + e);
                checked++;
            }
        }
        assertTrue(checked > 400);
        // the quadratic term is odd: it pushes back on both sides
        assertTrue(NonlinearLaws.quadratic(0, 1, 0, -0.5, 0) < 0 && NonlinearLaws.quadratic(0, 1, 0, 0.5, 0) > 0);
    }

    @Test
    void theClippedSpringFollowsMiLibOnEveryBranch() {
        double[][] params = {{0.01, 0.5, 0.2, 0.001}, {0.3, 0.5, 0.2, 0.001}, {0.01, 0, 0.2, 0.001}};
        boolean sawCubic = false, sawClipped = false;
        for (double[] pr : params) {
            double b = NonlinearLaws.clipPoint(pr[0], pr[1], pr[2]);
            for (double e = -2; e <= 2; e += 0.0137) {
                for (double v : VELOCITIES) {
                    close(miNlSpringDamperClipped(pr[0], pr[1], pr[2], pr[3], e, v),
                            NonlinearLaws.clipped(pr[0], pr[1], pr[2], pr[3], e, v), "clipped " + e);
                }
                if (pr[1] != 0 && pr[0] < pr[2]) {
                    sawCubic |= Math.abs(e) <= b;
                    sawClipped |= Math.abs(e) > b;
                }
            }
        }
        assertTrue(sawCubic && sawClipped, "the grid crosses mi.lib's clipping point b = sqrt(k - s) / c");
    }

    @Test
    void thePluckFollowsMiLibAndLetsGo() {
        double k = 0.05, scale = 0.4, z = 0.001;
        for (double e = -0.6; e <= 0.6; e += 0.00731) {
            for (double v : VELOCITIES) {
                close(miNlPluck(k, scale, z, e, v), NonlinearLaws.pluck(k, scale, z, e, v), "pluck " + e);
            }
        }
        // continuous at the tip and at the scale, zero beyond
        double tip = scale / 10;
        assertEquals(NonlinearLaws.pluck(k, scale, 0, tip - 1e-12, 0), NonlinearLaws.pluck(k, scale, 0, tip, 0), 1e-12);
        assertEquals(0, NonlinearLaws.pluck(k, scale, 0, scale - 1e-12, 0), 1e-12);
        assertEquals(0, NonlinearLaws.pluck(k, scale, z, 0.5, 0.3));
    }

    @Test
    void theBowFollowsMiLibInBothProfiles() {
        double z = 0.8, scale = 0.01;
        for (double type : new double[] {0, 1}) {
            for (double v = -0.03; v <= 0.03; v += 0.000173) {
                close(miNlBow(z, scale, type, v), NonlinearLaws.bow(z, scale, type, v), "bow " + type + " " + v);
            }
        }
        // stick-slip shape: the friction rises to a peak at a third of the scale, then falls
        double peak = NonlinearLaws.bow(z, scale, 0, scale / 3);
        assertTrue(peak > NonlinearLaws.bow(z, scale, 0, scale / 6) && peak > NonlinearLaws.bow(z, scale, 0, scale / 2));
    }

    @Test
    void thePotentialsAreTheIntegralsOfTheElasticForces() {
        double[][] cases = {{0.01, 0.3, 0.2}, {0.01, 0.5, 0.2}};
        for (double[] c : cases) {
            for (double e = -1.2; e <= 1.2; e += 0.0917) {
                double h = 1e-6;
                assertEquals(NonlinearLaws.quadratic(c[0], c[1], 0, e, 0),
                        (NonlinearLaws.quadraticPotential(c[0], c[1], e + h)
                                - NonlinearLaws.quadraticPotential(c[0], c[1], e - h)) / (2 * h), 1e-6);
                assertEquals(NonlinearLaws.cubic(c[0], c[1], 0, e, 0),
                        (NonlinearLaws.cubicPotential(c[0], c[1], e + h)
                                - NonlinearLaws.cubicPotential(c[0], c[1], e - h)) / (2 * h), 1e-6);
                double b = NonlinearLaws.clipPoint(c[0], c[1], c[2]);
                if (Math.abs(Math.abs(e) - b) > 2 * h) {
                    assertEquals(NonlinearLaws.clipped(c[0], c[1], c[2], 0, e, 0),
                            (NonlinearLaws.clippedPotential(c[0], c[1], c[2], e + h)
                                    - NonlinearLaws.clippedPotential(c[0], c[1], c[2], e - h)) / (2 * h), 1e-6);
                }
                assertEquals(NonlinearLaws.pluck(0.05, 0.4, 0, e, 0),
                        (NonlinearLaws.pluckPotential(0.05, 0.4, e + h)
                                - NonlinearLaws.pluckPotential(0.05, 0.4, e - h)) / (2 * h), 1e-6, "pluck " + e);
            }
        }
    }

    @Test
    void theStabilityBoundsCoverTheSlopesTheLawsReach() {
        double s = 0.01, c = 0.5, k = 0.2;
        double bound = NonlinearLaws.clippedStiffnessBound(s, c, k);
        double z = 0.8, scale = 0.01;
        double dBound = NonlinearLaws.bowDampingBound(z, 1);
        double h = 1e-7;
        for (double e = -2; e <= 2; e += 0.001) {
            double slope = (NonlinearLaws.clipped(s, c, k, 0, e + h, 0) - NonlinearLaws.clipped(s, c, k, 0, e - h, 0))
                    / (2 * h);
            if (Math.abs(Math.abs(e) - NonlinearLaws.clipPoint(s, c, k)) > 2 * h) {
                assertTrue(Math.abs(slope) <= bound * (1 + 1e-6), "clipped slope " + slope + " at " + e);
            }
            double v = e * scale;
            double dSlope = (NonlinearLaws.bow(z, scale, 1, v + h) - NonlinearLaws.bow(z, scale, 1, v - h)) / (2 * h);
            assertTrue(Math.abs(dSlope) <= dBound * (1 + 1e-6), "bow slope " + dSlope + " at " + v);
        }
        assertEquals(NonlinearLaws.bow(z, scale, 1, 1e-9) / 1e-9, dBound, 1e-6, "the smooth bow's slope peaks at 0");
        assertTrue(LinkKind.PLUCK1D.boundStiffness(0.05, 0.4, 0) >= 0.9 * 0.05 - 1e-15);
        assertEquals(0.01, LinkKind.CUBIC_SPRING_DAMPER3D.boundStiffness(0.01, 5, 0), 0,
                "a cubic spring is bounded by its linear part only");
    }
}
