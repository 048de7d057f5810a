package tactus.engine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * The x and y forces of one-dimensional masses (Mass1D, Osc1D), which never move them: their kernels clear them
 * only when an interaction can write them ({@link StepPlan#offAxisWriters}), and the engine clears what the API
 * wrote before the next step. Whichever way they are cleared, a model moves the same, bit for bit, and
 * {@link Engine#force} reads the same: what was added since the last step.
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class OffAxisForcesTest {

    /**
     * The struck 1-D string of {@link SpringDamper1DSegmentTest} (n masses of a kind between two Ground1D, varied
     * masses and parameters); with {@code zeroLink}, a SpringDamper3D of zero stiffness and damping also ties mass 3
     * to a Ground3D off the axis, so that an interaction can write x and y forces into a 1-D mass (it writes zeros).
     */
    private static Engine string(MassKind kind, int n, boolean zeroLink, int[] ids) {
        Engine e = SpringDamper1DSegmentTest.string(kind, n, true, ids);
        if (zeroLink) {
            int off = e.addMass(MassKind.GROUND3D, 1, 3, 5, 1, 0, 0, 0);
            e.addLink(LinkKind.SPRING_DAMPER3D, ids[3], off, 0, 0, 0);
        }
        return e;
    }

    private static double z(Engine e, int id) {
        double[] p = new double[3];
        e.position(id, p);
        return p[2];
    }

    private static double[] force(Engine e, int id) {
        double[] f = new double[3];
        e.force(id, f);
        return f;
    }

    @ParameterizedTest
    @EnumSource(value = MassKind.class, names = {"MASS1D", "OSC1D"})
    void aOneDimensionalModelMovesTheSameWhetherOrNotItsKernelsClearTheOffAxisForces(MassKind kind) {
        int n = 40;
        int[] ids = new int[n + 1];
        int[] idsRef = new int[n + 1];
        Engine lone = string(kind, n, false, ids);
        Engine ref = string(kind, n, true, idsRef);
        double z0 = z(lone, ids[n / 2]);
        lone.step(1);
        ref.step(1);
        assertFalse(lone.plan().offAxisWriters, "only 1-D links: nothing but the API writes x or y");
        assertTrue(ref.plan().offAxisWriters, "a SpringDamper3D touches a 1-D mass");
        for (int step = 0; step < 400; step++) {
            if (step % 7 == 0) {
                // the API adds forces with x and y parts on a few masses, some every step and some now and then
                for (int i : new int[] {1, 5 + step % 11, n}) {
                    double fx = 0.01 * Math.sin(step + i);
                    double fy = -0.02 * Math.cos(step * 0.3 + i);
                    double fz = 0.001 * Math.sin(step * 0.1 + i);
                    lone.addForce(ids[i], fx, fy, fz);
                    ref.addForce(idsRef[i], fx, fy, fz);
                    assertEquals(fx, force(lone, ids[i])[0], 0.0, "an added x force reads until the step");
                    assertEquals(fy, force(lone, ids[i])[1], 0.0, "an added y force reads until the step");
                }
            }
            lone.step(1 + step % 3);
            ref.step(1 + step % 3);
            for (int i = 1; i <= n; i++) {
                double[] a = force(lone, ids[i]);
                double[] b = force(ref, idsRef[i]);
                assertEquals(0.0, a[0], 0.0, "x force of mass " + i + " after step " + step);
                assertEquals(0.0, a[1], 0.0, "y force of mass " + i + " after step " + step);
                assertEquals(b[2], a[2], 0.0, "z force of mass " + i + " after step " + step);
                assertEquals(z(ref, idsRef[i]), z(lone, ids[i]), 0.0, "z of mass " + i + " after step " + step);
            }
        }
        assertNotEquals(z0, z(lone, ids[n / 2]), "the string moves");
    }

    @Test
    void anOffAxisForceFromAThreeDLinkIsClearedEveryStepAndGoesWithTheLink() {
        Engine e = new Engine();
        int m = e.addMass(MassKind.MASS1D, 1, 0, 0, 0, 0, 0, 0);
        int g = e.addMass(MassKind.GROUND3D, 1, 3, 4, 0, 0, 0, 0);
        int link = e.addLink(LinkKind.SPRING3D, m, g, 0.01, 0, 1);
        e.step(1);
        assertTrue(e.plan().offAxisWriters);
        // the mass moves along z only, so the link's x and y force is the same after every step: not summed up
        double fx = force(e, m)[0];
        double fy = force(e, m)[1];
        assertEquals(0.01 * (5 - 1) * 3 / 5, fx, 1e-15, "the spring pulls the mass toward the ground along x");
        assertEquals(0.01 * (5 - 1) * 4 / 5, fy, 1e-15);
        for (int step = 0; step < 5; step++) {
            e.step(1);
            assertEquals(fx, force(e, m)[0], 1e-15, "after step " + step);
            assertEquals(fy, force(e, m)[1], 1e-15, "after step " + step);
        }
        e.removeLink(link);
        e.step(1);
        assertFalse(e.plan().offAxisWriters);
        assertEquals(0.0, force(e, m)[0], 0.0, "the x force the removed link wrote is gone");
        assertEquals(0.0, force(e, m)[1], 0.0, "the y force the removed link wrote is gone");
        e.addForce(m, 2, 3, 0);
        e.addForce(m, 2, 3, 0);
        assertEquals(4.0, force(e, m)[0], 0.0, "forces added before a step add up");
        e.step(1);
        assertEquals(0.0, force(e, m)[0], 0.0, "and act once");
        double[] p = new double[3];
        e.position(m, p);
        assertEquals(0.0, p[0], 0.0, "a Mass1D never moves along x");
    }

    @Test
    void aContactGroupOrAPlaneContactOnAOneDimensionalMassCountsAsAWriter() {
        Engine group = new Engine();
        int a = group.addMass(MassKind.MASS1D, 1, 0, 0, 0, 0, 0, 0);
        int b = group.addMass(MassKind.MASS3D, 1, 0.5, 0, 0, 0, 0, 0);
        group.step(1);
        assertFalse(group.plan().offAxisWriters);
        group.addContactGroup(new int[] {a, b}, 1, 0.1, 0);
        group.step(1);
        assertTrue(group.plan().offAxisWriters, "a contact group with a 1-D member");
        assertNotEquals(0.0, force(group, a)[0], "the contact pushes the Mass1D along x");

        Engine plane = new Engine();
        int c = plane.addMass(MassKind.OSC1D, 1, 0, 0, 0, 0, 0, 0);
        plane.addPlaneContact(c, 0, 0.5, 0, 0.1, 0);
        plane.step(1);
        assertTrue(plane.plan().offAxisWriters, "a plane contact along x on an Osc1D");
    }

    /**
     * Steps an engine on two threads from its first batch on: its step-mode chooser gets a clock on which the
     * one-thread probe takes 1000 ns and every later run 1 ns.
     */
    static void parallelFromTheProbeOn(Engine e) {
        e.setThreads(2);
        long[] t = {0};
        int[] calls = {0};
        e.setModeClock(() -> t[0] += ++calls[0] <= 2 ? 1000 : 1);
    }

    @Test
    void theParallelStepperClearsWhatTheApiWroteToo() {
        int n = 12_000;   // 24,001 elements: past the parallel stepper's threshold of 20,000
        int[] ids = new int[n + 1];
        int[] idsRef = new int[n + 1];
        try (Engine par = string(MassKind.MASS1D, n, false, ids); Engine ser = string(MassKind.MASS1D, n, false, idsRef)) {
            parallelFromTheProbeOn(par);
            for (int round = 0; round < 6; round++) {
                for (int i = 1; i <= n; i += 997) {
                    par.addForce(ids[i], 1, -1, 0.001 * i / n);
                    ser.addForce(idsRef[i], 1, -1, 0.001 * i / n);
                }
                assertEquals(4, par.step(4));
                assertEquals(4, ser.step(4));
                for (int i = 1; i <= n; i += 97) {
                    assertEquals(0.0, force(par, ids[i])[0], 0.0, "x force of mass " + i);
                    assertEquals(0.0, force(par, ids[i])[1], 0.0, "y force of mass " + i);
                    assertEquals(z(ser, idsRef[i]), z(par, ids[i]), 0.0, "z of mass " + i);
                }
            }
            assertEquals(6 * 4 - 1, par.stepsByMode()[0], "every step but the first probe ran in parallel");
        }
    }
}
