package tactus.demo;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/** The demo's hand script names the move under way at any time, as the scene's caption shows it. */
class PluckPathTest {
    @Test
    void namesTheMoveUnderWayFromItsStartToTheNextOne() {
        PluckPath path = new PluckPath(0.1, -1);
        double[] starts = path.phaseStarts();
        String[] names = PluckPath.phases();
        assertEquals(names.length, starts.length);
        for (int i = 0; i < names.length; i++) {
            double end = i + 1 < starts.length ? starts[i + 1] : PluckPath.DURATION;
            assertEquals(names[i], path.phaseAt(starts[i]), "at the start of move " + i);
            assertEquals(names[i], path.phaseAt((starts[i] + end) / 2), "in the middle of move " + i);
        }
        assertEquals("glide", path.phaseAt(-1));
        assertEquals("ring", path.phaseAt(PluckPath.DURATION + 1));
        assertEquals("pluck down", path.phaseAt(0.9));
    }
}
