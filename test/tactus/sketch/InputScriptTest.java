package tactus.sketch;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import processing.core.PConstants;
import processing.event.Event;
import processing.event.KeyEvent;
import processing.event.MouseEvent;

/**
 * The scripted input that {@link ExamplesTest} plays to every example after its checked frames: which keys are
 * found in a sketch's source, which events they become, and that an exception thrown by a key handler fails the
 * run.
 */
class InputScriptTest {

    @TempDir
    Path tmp;

    @Test
    void theKeysASketchComparesWithAreFoundInOrder() {
        String src = "void keyPressed() {\n"
                + "  if (key == 'a' || key == 'A') { }\n"
                + "  else if (keyCode == UP) { }\n"
                + "  else if (key == '\\'') { }\n"
                + "  else if (key >= '1' && key <= '9') { }\n"
                + "  else if (key == ' ') { }\n"
                + "  else if (key == 'a') { }\n" // a repeat counts once
                + "}\n"
                + "void mouseDragged() { }\n";
        assertEquals("k97,k65,c" + PConstants.UP + ",k39,k49,k57,k32,mouse", ExamplesTest.inputScript(src));
        assertEquals("", ExamplesTest.inputScript("void draw() { if (keyPressed) { } }"));
    }

    @Test
    void eachKeyIsAPressThenAReleaseWithTheKeyboardsKeyCode() {
        List<Event> events = SketchRunner.inputEvents("k39,c38,mouse", 400, 200);
        assertEquals(2 + 2 + 4, events.size());
        KeyEvent quote = (KeyEvent) events.get(0);
        assertEquals(KeyEvent.PRESS, quote.getAction());
        assertEquals('\'', quote.getKey());
        // A quote is VK_QUOTE, not 39, which a sketch would read as RIGHT.
        assertEquals(java.awt.event.KeyEvent.VK_QUOTE, quote.getKeyCode());
        assertEquals(KeyEvent.RELEASE, events.get(1).getAction());
        KeyEvent up = (KeyEvent) events.get(2);
        assertEquals(PConstants.CODED, up.getKey());
        assertEquals(PConstants.UP, up.getKeyCode());
        MouseEvent press = (MouseEvent) events.get(4);
        assertEquals(MouseEvent.PRESS, press.getAction());
        assertEquals(200, press.getX());
        assertEquals(100, press.getY());
        assertEquals(MouseEvent.RELEASE, events.get(7).getAction());
        assertTrue(SketchRunner.inputEvents("", 10, 10).isEmpty());
        assertThrows(IllegalArgumentException.class, () -> SketchRunner.inputEvents("x12", 10, 10));
    }

    /** One child run: a key handler that throws fails the run, after the checked frames were fine. */
    @Test
    void anExceptionInAKeyHandlerFailsTheRun() {
        SketchHarness.JavaSketch sketch = SketchHarness.preprocess("KeyThrower",
                "void setup() { size(200, 100); }\n"
                + "void draw() { background(255); line(0, 0, width, frameCount % height); }\n"
                + "void keyPressed() { if (key == 'x') throw new IllegalStateException(\"x pressed\"); }\n");
        String cp = SketchHarness.sketchClasspath();
        Path classes = SketchHarness.compile(sketch, tmp, cp);
        SketchHarness.Run run = SketchHarness.run(sketch.className, classes, cp, 10, tmp.resolve("frame.png"), 60,
                null, java.util.Map.of(SketchRunner.INPUT_PROPERTY, ExamplesTest.inputScript(
                        "void keyPressed() { if (key == 'x') { } }")));
        assertEquals(SketchRunner.EXCEPTION_STATUS, run.exitCode, run.logs());
        assertTrue(run.stderr.contains("x pressed"), run.logs());
    }
}
