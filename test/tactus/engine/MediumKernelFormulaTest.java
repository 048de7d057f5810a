package tactus.engine;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/**
 * The specialised mass kernels must all implement the one general update of the paper's scheme,
 * X(n+1) = X(n) + (1 - f/M) (X(n) - X(n-1)) + F/M + g, which is (2 - f/M) X(n) - (1 - f/M) X(n-1) + F/M + g
 * (f air friction, g the gravity acceleration per step^2, F the force of the previous interaction phase).
 * A scene with neither gravity nor friction runs the reduced kernel (Free3D, X(n+1) = 2X(n) - X(n-1) + F/M);
 * switching an effect on mid-run selects the general kernel, and every step must then match the formula,
 * with coefficients computed here from M, f and g (not read from the plan).
 */
class MediumKernelFormulaTest {

    private static Engine springChain() {
        Engine e = new Engine();
        int g = e.addMass(MassKind.GROUND3D, 1, 0, 0, 0, 0, 0, 0);
        int prev = g;
        for (int i = 1; i <= 6; i++) {
            int m = e.addMass(MassKind.MASS3D, 0.5 + 0.25 * i, i, 0.1 * i, -0.2 * i, 0.01, -0.02 * i, 0.003);
            e.addLink(LinkKind.SPRING3D, prev, m, 0.05, 0, 1.0);
            prev = m;
        }
        e.compile();
        return e;
    }

    /** Steps once and checks every Mass3D slot against the general formula. */
    private static void stepAndCheck(Engine e, double f, double gx, double gy, double gz, String what) {
        StepPlan p = e.plan();
        int s0 = p.start(MassKind.MASS3D);
        int s1 = p.end(MassKind.MASS3D);
        int k = s1 - s0;
        double[][] expected = new double[3][k];
        for (int s = s0; s < s1; s++) {
            double m = e.mass(p.massId[s]);
            double r = 1 - f / m;
            expected[0][s - s0] = p.x[s] + r * (p.x[s] - p.px[s]) + p.fx[s] / m + gx;
            expected[1][s - s0] = p.y[s] + r * (p.y[s] - p.py[s]) + p.fy[s] / m + gy;
            expected[2][s - s0] = p.z[s] + r * (p.z[s] - p.pz[s]) + p.fz[s] / m + gz;
        }
        e.step();
        for (int s = s0; s < s1; s++) {
            // F/M is computed as F * (1/M) by the engine: one rounding apart, far below 1e-15
            assertEquals(expected[0][s - s0], p.x[s], 1e-15, what + " x of slot " + s);
            assertEquals(expected[1][s - s0], p.y[s], 1e-15, what + " y of slot " + s);
            assertEquals(expected[2][s - s0], p.z[s], 1e-15, what + " z of slot " + s);
        }
    }

    @Test
    void switchingGravityAndFrictionSelectsTheGeneralKernelAndItMatchesTheFormula() {
        Engine e = springChain();
        assertArrayEquals(new String[] {"Free3D", "Fixed", "Spring"}, e.plan().kernelNames());
        for (int n = 0; n < 200; n++) {
            stepAndCheck(e, 0, 0, 0, 0, "plain");
        }
        e.setGravity(0, 0, -1e-6);
        assertArrayEquals(new String[] {"Medium3D", "Fixed", "Spring"}, e.plan().kernelNames());
        for (int n = 0; n < 200; n++) {
            stepAndCheck(e, 0, 0, 0, -1e-6, "gravity");
        }
        e.setFriction(0.003);
        for (int n = 0; n < 200; n++) {
            stepAndCheck(e, 0.003, 0, 0, -1e-6, "gravity + friction");
        }
        e.setGravity(2e-7, -3e-7, 0);
        for (int n = 0; n < 200; n++) {
            stepAndCheck(e, 0.003, 2e-7, -3e-7, 0, "oblique gravity + friction");
        }
        e.setGravity(0, 0, 0);
        assertArrayEquals(new String[] {"Medium3D", "Fixed", "Spring"}, e.plan().kernelNames(),
                "friction alone still needs the general kernel");
        for (int n = 0; n < 200; n++) {
            stepAndCheck(e, 0.003, 0, 0, 0, "friction");
        }
        e.setFriction(0);
        assertArrayEquals(new String[] {"Free3D", "Fixed", "Spring"}, e.plan().kernelNames());
        for (int n = 0; n < 200; n++) {
            stepAndCheck(e, 0, 0, 0, 0, "plain again");
        }
    }

    // Free3D is the exact reduction of the general kernel: with a friction so small that 1 - f/M rounds to 1.0
    // (1e-300) the general kernel runs, and it must produce bit-identical states to the reduced one.
    @Test
    void reducedKernelIsTheExactReductionOfTheGeneralOne() {
        Engine a = springChain();
        Engine b = springChain();
        b.setFriction(1e-300);
        assertArrayEquals(new String[] {"Free3D", "Fixed", "Spring"}, a.plan().kernelNames());
        assertArrayEquals(new String[] {"Medium3D", "Fixed", "Spring"}, b.plan().kernelNames());
        a.step(5000);
        b.step(5000);
        StepPlan pa = a.plan();
        StepPlan pb = b.plan();
        assertArrayEquals(pa.x, pb.x);
        assertArrayEquals(pa.y, pb.y);
        assertArrayEquals(pa.z, pb.z);
    }
}
