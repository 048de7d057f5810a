package tactus;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/**
 * The figures of docs/coming-from-miphysics.md on frame stepping: Tactus's {@code draw_physics} runs the exact
 * integer share of steps of each frame; the paper's engine divided the rates in float and carried the remainder in
 * double (restated here from its equations: factor = (float) sr / (float) fps, n = floor(factor + r), r = factor +
 * r - n), so it runs one step fewer on some frames and catches up on the next.
 */
class FrameStepsVsPaperTest {
    static int[] tactus(int sr, int fps, int frames) {
        PhysicalModel m = new PhysicalModel(sr, fps);
        m.addGround3D("g", new Vect3D(0, 0, 0));
        m.init();
        int[] steps = new int[frames];
        for (int i = 0; i < frames; i++) {
            steps[i] = m.draw_physics();
        }
        return steps;
    }

    static int[] paper(int sr, int fps, int frames) {
        double factor = (float) sr / (float) fps;
        double residue = 0;
        int[] steps = new int[frames];
        for (int i = 0; i < frames; i++) {
            double f = factor + residue;
            steps[i] = (int) Math.floor(f);
            residue = f - steps[i];
        }
        return steps;
    }

    /** @return the 1-based frames after which Tactus has run more steps in all than the paper's engine. */
    static String framesAhead(int sr, int fps, int frames) {
        int[] t = tactus(sr, fps, frames);
        int[] p = paper(sr, fps, frames);
        long st = 0, sp = 0;
        StringBuilder b = new StringBuilder();
        for (int i = 0; i < frames; i++) {
            st += t[i];
            sp += p[i];
            if (st != sp) {
                b.append(b.length() == 0 ? "" : ",").append(i + 1).append(st > sp ? "" : "(behind)");
            }
        }
        return b.toString();
    }

    @Test
    void at1000HzAnd60FpsTactusIsOneStepAheadAfterEveryThirdFrame() {
        assertArrayEquals(new int[] {16, 17, 17, 16, 17, 17}, tactus(1000, 60, 6));
        assertArrayEquals(new int[] {16, 17, 16, 17, 17, 16}, paper(1000, 60, 6));
        assertEquals("3,6,9,12,15,18", framesAhead(1000, 60, 18));
        assertEquals("3,6,9,12,15,18", framesAhead(1000, 30, 18));
        assertEquals("6,12,18", framesAhead(250, 60, 18));
        assertEquals("20,40,60", framesAhead(441, 60, 60));
    }

    @Test
    void whenTheRatioIsExactInFloatBothRunTheSameSteps() {
        for (int[] r : new int[][] {{44100, 60}, {44100, 50}, {44100, 90}, {44100, 24}, {48000, 60}, {1050, 60}}) {
            assertEquals("", framesAhead(r[0], r[1], 600), r[0] + " Hz, " + r[1] + " fps");
        }
    }
}
