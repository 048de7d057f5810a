package tactus.haptics.passivity;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/** The play between the handle and the avatar: a one-count flicker leaves the anchor put, a motion drags it. */
class ContactPlayTest {
    private static final double COUNT = 148e-6;
    private static final double[] WIDTHS = {1.1 * COUNT, 1.1 * COUNT, 0};

    @Test
    void aReadingThatFlickersByOneCountLeavesTheAnchorWhereItIs() {
        ContactPlay play = new ContactPlay();
        double[] out = new double[3];
        play.follow(new double[] {0.01, 0.08, 0}, WIDTHS, out);
        double[] start = out.clone();
        for (int k = 0; k < 50; k++) {   // up one count, back, down one count, back, on both axes
            double dx = (k % 4 == 1 ? COUNT : k % 4 == 3 ? -COUNT : 0);
            play.follow(new double[] {0.01 + dx, 0.08 - dx, 0}, WIDTHS, out);
            assertArrayEquals(start, out, 0, "tick " + k);
        }
    }

    @Test
    void aMotionDragsTheAnchorTheWidthBehindAndAReversalTakesUpThePlayFirst() {
        ContactPlay play = new ContactPlay();
        double[] out = new double[3];
        double y = 0.08;
        play.follow(new double[] {0, y, 0}, WIDTHS, out);
        for (int k = 1; k <= 10; k++) {
            play.follow(new double[] {0, y - k * COUNT, 0}, WIDTHS, out);
        }
        assertEquals(y - 10 * COUNT + WIDTHS[1], out[1], 1e-12, "moving down: the width behind");
        assertEquals(0, out[0], 0, "x did not move");
        play.follow(new double[] {0, y - 8 * COUNT, 0}, WIDTHS, out);   // back up two counts: within the play
        assertEquals(y - 10 * COUNT + WIDTHS[1], out[1], 1e-12, "two counts back: the play is taken up");
        play.follow(new double[] {0, y - 7 * COUNT, 0}, WIDTHS, out);   // a third: the anchor moves
        assertEquals(y - 7 * COUNT - WIDTHS[1], out[1], 1e-12, "moving up: the width behind the other way");
    }

    @Test
    void afterAResetTheAnchorStartsAtTheReading() {
        ContactPlay play = new ContactPlay();
        double[] out = new double[3];
        play.follow(new double[] {0, 0, 0}, WIDTHS, out);
        play.reset();
        play.follow(new double[] {0.05, -0.02, 0.3}, WIDTHS, out);
        assertArrayEquals(new double[] {0.05, -0.02, 0.3}, out, 0);
    }
}
