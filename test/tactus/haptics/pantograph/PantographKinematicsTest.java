package tactus.haptics.pantograph;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import tactus.haptics.HaplyPreset;
import tactus.haptics.Pantograph;

/** Forward kinematics and J^T torques against the reference vectors and against finite differences. */
class PantographKinematicsTest {
    // l, L, d, th1, th2 (deg), x, y, tau for F=(1,0), tau for F=(0,1): haply-minim-serial.md A.3
    private static final double[][] VECTORS = {
        {0.07, 0.09, 0.038, 120, 60, 0.019000, 0.132622, -0.053644, -0.053644, -0.040233, 0.040233},
        {0.07, 0.09, 0.038, 100, 30, 0.063408, 0.117825, -0.060233, -0.038311, -0.025608, 0.059214},
        {0.07, 0.09, 0.0, 135, 45, 0.000000, 0.124664, -0.062332, -0.062332, -0.041046, 0.041046},
        {0.05, 0.07, 0.02, 150, 70, -0.017934, 0.090242, -0.031920, -0.046282, -0.040611, 0.017995},
    };

    @Test
    void matchesReferenceVectors() {
        double[] tau = new double[2];
        for (double[] v : VECTORS) {
            PantographKinematics k = new PantographKinematics(v[0], v[1], v[2]);
            assertTrue(k.forward(Math.toRadians(v[3]), Math.toRadians(v[4])));
            assertEquals(v[5], k.x(), 1e-6, "x");
            assertEquals(v[6], k.y(), 1e-6, "y");
            k.torques(1, 0, 1.0, tau);
            assertEquals(v[7], tau[0], 1e-6, "tau1 for Fx");
            assertEquals(v[8], tau[1], 1e-6, "tau2 for Fx");
            k.torques(0, 1, 1.0, tau);
            assertEquals(v[9], tau[0], 1e-6, "tau1 for Fy");
            assertEquals(v[10], tau[1], 1e-6, "tau2 for Fy");
        }
    }

    @Test
    void jacobianMatchesFiniteDifferences() {
        PantographKinematics k = new PantographKinematics(0.07, 0.09, 0.038);
        double h = 1e-6;
        for (double a1 = 95; a1 <= 160; a1 += 13) {
            for (double a2 = 20; a2 <= 85; a2 += 13) {
                double t1 = Math.toRadians(a1);
                double t2 = Math.toRadians(a2);
                if (!k.forward(t1, t2)) {
                    continue;
                }
                double[][] j = {{k.jacobian(0, 0), k.jacobian(0, 1)}, {k.jacobian(1, 0), k.jacobian(1, 1)}};
                k.forward(t1 + h, t2);
                double xp = k.x();
                double yp = k.y();
                k.forward(t1 - h, t2);
                assertEquals((xp - k.x()) / (2 * h), j[0][0], 1e-7);
                assertEquals((yp - k.y()) / (2 * h), j[1][0], 1e-7);
                k.forward(t1, t2 + h);
                xp = k.x();
                yp = k.y();
                k.forward(t1, t2 - h);
                assertEquals((xp - k.x()) / (2 * h), j[0][1], 1e-7);
                assertEquals((yp - k.y()) / (2 * h), j[1][1], 1e-7);
            }
        }
    }

    @Test
    void torquesDoVirtualWork() {
        // tau . dtheta = F . dx for a small joint motion: J^T is the right transpose.
        PantographKinematics k = new PantographKinematics(0.05, 0.07, 0.02);
        double t1 = Math.toRadians(140);
        double t2 = Math.toRadians(50);
        double d1 = 1e-7;
        double d2 = -2e-7;
        k.forward(t1, t2);
        double x0 = k.x();
        double y0 = k.y();
        double[] tau = new double[2];
        k.torques(0.7, -1.3, 1.0, tau);
        k.forward(t1 + d1, t2 + d2);
        assertEquals(0.7 * (k.x() - x0) - 1.3 * (k.y() - y0), tau[0] * d1 + tau[1] * d2, 1e-12);
    }

    @Test
    void inverseUndoesForwardAndForceFromTorquesUndoesTorques() {
        for (HaplyPreset p : HaplyPreset.values()) {
            PantographKinematics k = p.newKinematics();
            double t1 = Math.toRadians(p == HaplyPreset.HAPLY_2018 ? 150 : 120);
            double t2 = Math.toRadians(p == HaplyPreset.HAPLY_2018 ? 40 : 60);
            assertTrue(k.forward(t1, t2), p.name());
            double[] th = new double[2];
            assertTrue(k.inverse(k.x(), k.y(), th));
            assertEquals(t1, th[0], 1e-9, p.name());
            assertEquals(t2, th[1], 1e-9, p.name());
            double[] tau = new double[2];
            double[] f = new double[2];
            k.torques(0.4, -0.9, 1.0, tau);
            k.forceFromTorques(tau[0], tau[1], f);
            assertEquals(0.4, f[0], 1e-9);
            assertEquals(-0.9, f[1], 1e-9);
        }
    }

    @Test
    void unreachablePoseIsReportedNotInvented() {
        PantographKinematics k = new PantographKinematics(0.05, 0.05, 0.02);
        // arms pointing apart: the elbows are 0.12 m apart, more than 2L = 0.10 m
        assertFalse(k.forward(Math.PI, 0.0));
        assertFalse(k.isValid());
        assertTrue(Double.isNaN(k.x()));
        assertFalse(k.inverse(0.5, 0.5, new double[2]));
        assertThrows(IllegalArgumentException.class, () -> k.setParameters(0, 0.07, 0.02));
        assertThrows(IllegalArgumentException.class, () -> k.setParameters(0.05, Double.NaN, 0.02));
        assertThrows(IllegalArgumentException.class, () -> k.setParameters(0.05, 0.07, -0.01));
    }

    @Test
    void hapiPantographKeepsItsGainAndTakesPVectorArrays() {
        Pantograph legacy = new Pantograph();
        // 3-element arrays, as PVector.array() gives
        legacy.forwardKinematics(new float[] {150f, 70f, 0f});
        assertArrayEquals(new float[] {-0.017934f, 0.090242f}, legacy.get_coordinate(), 1e-6f);
        legacy.torqueCalculation(new float[] {1f, 0f, 0f});
        // 2018 hAPI: (0.1 / l) J^T F = 2 J^T F for l = 0.05
        assertArrayEquals(new float[] {2 * -0.031920f, 2 * -0.046282f}, legacy.get_torque(), 2e-6f);
        assertArrayEquals(new float[] {(float) Math.toRadians(150), (float) Math.toRadians(70)}, legacy.get_angle(), 1e-6f);

        Pantograph v3 = new Pantograph(3);
        v3.forwardKinematics(new float[] {100f, 30f, 0f});
        v3.torqueCalculation(new float[] {0f, 1f, 0f});
        assertArrayEquals(new float[] {-0.025608f, 0.059214f}, v3.get_torque(), 1e-6f);

        Pantograph v2 = new Pantograph(2);
        v2.forwardKinematics(new float[] {135f, 45f});
        assertArrayEquals(new float[] {0f, 0.124664f}, v2.get_coordinate(), 1e-6f);

        // every parameter settable, through hAPI's call
        v2.set_mechanism_parameters(new float[] {0.07f, 0.09f, 0.038f});
        v2.forwardKinematics(new float[] {120f, 60f});
        assertArrayEquals(new float[] {0.019f, 0.132622f}, v2.get_coordinate(), 1e-6f);
        assertThrows(IllegalArgumentException.class, () -> v2.set_mechanism_parameters(new float[] {0.07f, 0.09f}));
    }
}
