package tactus.engine;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * Oscillator kernels (Osc1D, Osc3D) whose masses all share one retention and one stiffness run with them as constants
 * ({@link MassKernels.OscKernel}). The model moves bit for bit as with the coefficients read per mass (the reference
 * form, stencil sweeps off); a parameter change switches the shared form off, and back on, at the next step, kernels
 * selected again (air friction, gravity, stencil sweeps off and on) share the values; and so does the parallel
 * stepper.
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class SharedOscillatorCoefficientsTest {

    /**
     * An n x n plate of oscillators of a kind, tied to their right and lower neighbours (SpringDamper1D for Osc1D,
     * SpringDamper3D for Osc3D) and struck near one corner; with {@code reference}, stencil sweeps off, so that the
     * oscillators read their coefficients per mass.
     *
     * @param ids receives the plate's mass ids, row by row
     */
    static Engine plate(MassKind kind, int n, boolean reference, int[] ids) {
        Engine e = new Engine();
        e.setStencilSweeps(!reference);
        boolean oneD = kind == MassKind.OSC1D;
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++) {
                int m = e.addMass(kind, 1, i, j, 0.001 * ((i * 7 + j * 3) % 5), 0, 0, 0);
                e.setOscillator(m, 0.0005, 0.00002);
                ids[i * n + j] = m;
            }
        }
        LinkKind link = oneD ? LinkKind.SPRING_DAMPER1D : LinkKind.SPRING_DAMPER3D;
        double length = oneD ? 0 : 1;
        for (int i = 0; i < n; i++) {
            for (int j = 0; j < n; j++) {
                if (i + 1 < n) {
                    e.addLink(link, ids[i * n + j], ids[(i + 1) * n + j], 0.15, 0.00002, length);
                }
                if (j + 1 < n) {
                    e.addLink(link, ids[i * n + j], ids[i * n + j + 1], 0.15, 0.00002, length);
                }
            }
        }
        e.addForce(ids[n + 1], 0.01, -0.02, 1);
        return e;
    }

    /**
     * @return whether the engine's oscillator kernels (on their own, or moved by a chain kernel that fuses them) all
     *     run with shared coefficients (after a step)
     */
    static boolean shared(Engine e) {
        int found = 0;
        boolean all = true;
        for (Kernel k : e.plan().kernels()) {
            Kernel m = k instanceof StencilKernel ? ((StencilKernel) k).masses() : k;
            if (m instanceof MassKernels.OscKernel) {
                found++;
                all &= ((MassKernels.OscKernel) m).shared;
            }
        }
        assertTrue(found > 0, "no oscillator kernel in " + String.join(",", e.kernelNames()));
        return all;
    }

    private static void assertSameMotion(Engine a, int[] ida, Engine b, int[] idb, String what) {
        double[] pa = new double[3];
        double[] pb = new double[3];
        for (int i = 0; i < ida.length; i++) {
            a.position(ida[i], pa);
            b.position(idb[i], pb);
            assertArrayEquals(pb, pa, what + ", mass " + i);
        }
    }

    @ParameterizedTest
    @EnumSource(value = MassKind.class, names = {"OSC1D", "OSC3D"})
    void aPlateMovesBitForBitAsWithItsCoefficientsReadPerMassThroughParameterChanges(MassKind kind) {
        int n = 8;
        int[] ids = new int[n * n];
        int[] idsRef = new int[n * n];
        Engine plate = plate(kind, n, false, ids);
        Engine ref = plate(kind, n, true, idsRef);
        plate.step(1);
        ref.step(1);
        assertTrue(shared(plate), "one stiffness and one damping for every oscillator");
        assertFalse(shared(ref), "the reference reads the coefficients per mass");
        for (int step = 1; step < 3000; step++) {
            if (step == 700) {   // one oscillator retuned: the kernel reads the coefficients per mass from now on
                plate.setOscillator(ids[20], 0.0011, 0.00002);
                ref.setOscillator(idsRef[20], 0.0011, 0.00002);
            } else if (step == 1400) {   // and back: shared again
                plate.setOscillator(ids[20], 0.0005, 0.00002);
                ref.setOscillator(idsRef[20], 0.0005, 0.00002);
            } else if (step == 2100) {   // every mass heavier: shared, with other values
                for (int i = 0; i < n * n; i++) {
                    plate.setMass(ids[i], 1.5);
                    ref.setMass(idsRef[i], 1.5);
                }
            } else if (step == 2500) {   // air friction: the kernels are selected again, and share the new values
                plate.setFriction(0.0001);
                ref.setFriction(0.0001);
            } else if (step == 2700) {   // the reference form: a new plan reads the coefficients per mass
                plate.setStencilSweeps(false);
            } else if (step == 2800) {   // sweeps again, and gravity: the kernels selected again, with no new values
                plate.setStencilSweeps(true);
                plate.step(1);
                ref.step(1);
                plate.setGravity(0, 0, -1e-9);
                ref.setGravity(0, 0, -1e-9);
            }
            plate.step(1);
            ref.step(1);
            if (step == 700 || step == 2700) {
                assertFalse(shared(plate), "after step " + step + "'s change");
            } else if (step == 1400 || step == 2100 || step == 2500 || step == 2800) {
                assertTrue(shared(plate), "after step " + step + "'s change");
            }
            if (step % 50 == 0 || step >= 699 && step <= 702 || step >= 1399 && step <= 1402
                    || step >= 2499 && step <= 2502 || step >= 2799 && step <= 2802) {
                assertSameMotion(plate, ids, ref, idsRef, kind + " after step " + step);
            }
        }
        double[] p = new double[3];
        plate.position(ids[n + 1], p);
        assertTrue(Math.abs(p[2]) > 1e-6, "the plate moves (" + p[2] + ")");
    }

    @Test
    void theParallelStepperLooksAtTheCoefficientsAgainToo() {
        int n = 110;   // 12,100 oscillators and 23,980 links: past the parallel stepper's threshold
        int[] ids = new int[n * n];
        int[] idsRef = new int[n * n];
        try (Engine par = plate(MassKind.OSC1D, n, false, ids); Engine ser = plate(MassKind.OSC1D, n, true, idsRef)) {
            OffAxisForcesTest.parallelFromTheProbeOn(par);
            for (int round = 0; round < 6; round++) {
                if (round == 2) {
                    par.setOscillator(ids[5], 0.002, 0.00002);
                    ser.setOscillator(idsRef[5], 0.002, 0.00002);
                } else if (round == 4) {
                    par.setOscillator(ids[5], 0.0005, 0.00002);
                    ser.setOscillator(idsRef[5], 0.0005, 0.00002);
                }
                assertEquals(4, par.step(4));
                assertEquals(4, ser.step(4));
                assertEquals(round < 2 || round >= 4, shared(par), "shared coefficients in round " + round);
                assertSameMotion(par, ids, ser, idsRef, "round " + round);
            }
            assertEquals(6 * 4 - 1, par.stepsByMode()[0], "every step but the first probe ran in parallel");
        }
    }
}
