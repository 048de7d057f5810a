package tactus.haptics;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.junit.jupiter.api.Test;

/** Device metres to model units and model forces back: axes, signs, handedness, scale, offset, passivity. */
class WorkspaceMappingTest {

    @Test
    void aSpecPermutesAndSignsTheAxes() {
        WorkspaceMapping m = WorkspaceMapping.of("z, -x, y").withScale(200).withOffset(1, 2, 3);
        double[] out = new double[3];
        m.toModel(new double[] {0.1, 0.2, 0.3}, out);
        assertEquals(200 * 0.3 + 1, out[0], 1e-12);
        assertEquals(-200 * 0.1 + 2, out[1], 1e-12);
        assertEquals(200 * 0.2 + 3, out[2], 1e-12);
        double[] back = new double[3];
        m.toDevice(out, back);
        assertEquals(0.1, back[0], 1e-12);
        assertEquals(0.2, back[1], 1e-12);
        assertEquals(0.3, back[2], 1e-12);
        assertEquals("z,-x,y", m.axes());
        assertThrows(IllegalArgumentException.class, () -> WorkspaceMapping.of("x,x,y"));
        assertThrows(IllegalArgumentException.class, () -> WorkspaceMapping.of("x,y"));
        assertThrows(IllegalArgumentException.class, () -> WorkspaceMapping.identity().withScale(0));
    }

    @Test
    void handednessIsTheDeterminantsSign() {
        assertTrue(WorkspaceMapping.identity().keepsHandedness());
        assertTrue(WorkspaceMapping.inverse3YUp().keepsHandedness(), "y-up physics: right-handed to right-handed");
        assertFalse(WorkspaceMapping.inverse3Screen().keepsHandedness(), "Processing's screen space is left-handed");
        assertFalse(WorkspaceMapping.pantograph().keepsHandedness(), "the paper's mirrored x");
        assertFalse(WorkspaceMapping.of("y,x,z").keepsHandedness(), "a swap of two axes");
        assertTrue(WorkspaceMapping.of("y,z,x").keepsHandedness(), "a cyclic permutation");
        assertFalse(WorkspaceMapping.identity().withScale(-1).keepsHandedness(), "a negative scale is a point reflection");
        assertTrue(WorkspaceMapping.identity().mirrored(0).mirrored(2).keepsHandedness());
    }

    @Test
    void theDefaultsPerDeviceKind() {
        assertEquals("x,z,-y", WorkspaceMapping.inverse3YUp().axes());
        assertEquals("x,-z,-y", WorkspaceMapping.inverse3Screen().axes());
        assertEquals("-x,y,z", WorkspaceMapping.pantograph().axes());
        assertEquals("x,z,-y", new tactus.haptics.inverse.Inverse3DeviceDefaults().axes());
    }

    @Test
    void centringPutsADevicePointAtAModelPoint() {
        double[] home = {0, -0.12, 0.15};
        WorkspaceMapping m = WorkspaceMapping.inverse3Screen().withScale(1000).centring(home, 400, 300, 0);
        double[] out = new double[3];
        m.toModel(home, out);
        assertEquals(400, out[0], 1e-9);
        assertEquals(300, out[1], 1e-9);
        assertEquals(0, out[2], 1e-9);
    }

    @Test
    void forcesGoBackAlongTheSameAxesSoAMappingStaysPassive() {
        Random r = new Random(24);
        String[] specs = {"x,y,z", "z,-x,y", "-y,z,-x", "x,-z,-y", "-x,-y,-z"};
        for (String spec : specs) {
            for (double scale : new double[] {1, 250, -40}) {
                WorkspaceMapping m = WorkspaceMapping.of(spec).withScale(scale).withOffset(5, -7, 11);
                for (int k = 0; k < 100; k++) {
                    double[] d0 = {r.nextGaussian(), r.nextGaussian(), r.nextGaussian()};
                    double[] d1 = {d0[0] + 1e-3 * r.nextGaussian(), d0[1] + 1e-3 * r.nextGaussian(), d0[2] + 1e-3 * r.nextGaussian()};
                    double[] m0 = new double[3];
                    double[] m1 = new double[3];
                    m.toModel(d0, m0);
                    m.toModel(d1, m1);
                    double[] fm = {r.nextGaussian(), r.nextGaussian(), r.nextGaussian()};
                    double[] fd = new double[3];
                    double gain = 0.5;
                    m.forceToDevice(fm, gain, fd);
                    double workDevice = fd[0] * (d1[0] - d0[0]) + fd[1] * (d1[1] - d0[1]) + fd[2] * (d1[2] - d0[2]);
                    double workModel = fm[0] * (m1[0] - m0[0]) + fm[1] * (m1[1] - m0[1]) + fm[2] * (m1[2] - m0[2]);
                    // the device does the model's work times gain / |scale|: same sign, so no energy is made
                    assertEquals(workModel * gain / Math.abs(scale), workDevice, 1e-12, spec + " scale " + scale);
                    double[] back = new double[3];
                    m.forceToModel(fd, gain, back);
                    for (int i = 0; i < 3; i++) {
                        assertEquals(fm[i], back[i], 1e-12);
                    }
                }
            }
        }
    }
}
