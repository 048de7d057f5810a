package tactus.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;
import tactus.PhysicalModel;
import tactus.Vect3D;

/**
 * draw_physics() runs simRate / dispRate steps per frame on average, carrying the fractional residue, so that
 * after k frames exactly floor(k simRate / dispRate) steps have run: frame k runs
 * floor(k S / D) - floor((k - 1) S / D) steps (computed here in exact integer arithmetic), and every D frames
 * (one second) add exactly S steps.
 */
class DrawPhysicsTest {

    private static PhysicalModel model(int sim, int disp) {
        PhysicalModel pm = new PhysicalModel(sim, disp);
        pm.addMass3D("m", 1, new Vect3D(0, 0, 0), new Vect3D(0, 0, 0));
        pm.init();
        return pm;
    }

    // 1000 Hz displayed at 60 fps: 16, 17, 17, 16, 17, 17, ... and 60 frames are exactly 1000 steps.
    @Test
    void thousandHertzAtSixtyFps() {
        PhysicalModel pm = model(1000, 60);
        int[] pattern = {16, 17, 17};
        for (int k = 1; k <= 60; k++) {
            assertEquals(pattern[(k - 1) % 3], pm.draw_physics(), "frame " + k);
        }
        assertEquals(1000, pm.getStepCount());
    }

    // Many rate pairs over ten seconds: each frame matches the exact integer schedule, each second adds S steps.
    @Test
    void residueIsCarriedExactlyForManyRates() {
        int[][] rates = {{1000, 60}, {1000, 30}, {1000, 7}, {44100, 60}, {44100, 59}, {48000, 144}, {96000, 90},
                         {1000, 144}, {250, 60}, {30, 60}, {1, 3}, {44100, 1000}};
        for (int[] r : rates) {
            int s = r[0];
            int d = r[1];
            PhysicalModel pm = model(s, d);
            long total = 0;
            for (long k = 1; k <= 10L * d; k++) {
                long expected = (k * s) / d - ((k - 1) * s) / d;
                int ran = pm.draw_physics();
                assertEquals(expected, ran, s + " Hz at " + d + " fps, frame " + k);
                total += ran;
                if (k % d == 0) {
                    assertEquals(s * (k / d), total, s + " Hz at " + d + " fps after " + k / d + " s");
                }
            }
            assertEquals(total, pm.getStepCount());
        }
    }
}
