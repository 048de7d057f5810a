package tactus;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import processing.core.PApplet;

/**
 * What happens when the file chooser of {@code loadModelFromFile} closes (called here as Processing calls it, with
 * no display): the paper's engine called the sketch's own {@code load(File)}, and so must Tactus; a sketch
 * without one gets the file loaded for it and one message, never an exception.
 */
class ModelLoaderChooserTest {
    /** A paper sketch: its load(File) loads the model itself, as GenericModelLoader does. */
    public static class PaperSketch extends PApplet {
        final List<File> calls = new ArrayList<>();
        ModelLoader loader;
        PhysicalModel mdl = new PhysicalModel(1050, 50);

        public void load(File selection) {
            calls.add(selection);
            if (selection != null) {
                loader.loadModel(selection.getAbsolutePath(), mdl);
            }
        }
    }

    /** A sketch whose load(File) fails. */
    public static class FailingSketch extends PApplet {
        public void load(File selection) {
            throw new IllegalStateException("the sketch's own failure");
        }
    }

    /** A sketch with a load(File) that is not public (a Java sketch can have one; Processing would not call it). */
    public static class HiddenLoadSketch extends PApplet {
        int calls;

        void load(File selection) {
            calls++;
        }
    }

    static File saved(Path dir) {
        File f = dir.resolve("Hello.xml").toFile();
        new ModelLoader(null).saveModel(f.getPath(), ModelLoaderTest.helloMass());
        return f;
    }

    @Test
    void theSketchsOwnLoadIsCalledWithTheChosenFileAndTheModelIsLoadedOnce(@TempDir Path dir) {
        PaperSketch sketch = new PaperSketch();
        ModelLoader loader = new ModelLoader(sketch);
        sketch.loader = loader;
        File f = saved(dir);
        String printed = GravityNoteTest.stderrOf(() -> loader.modelFileSelected(f));
        assertEquals(1, sketch.calls.size(), "load(File) is called once");
        assertSame(f, sketch.calls.get(0));
        assertEquals(2, sketch.mdl.getNumberOfMats(), "loaded once, by the sketch (twice would refuse the names)");
        assertTrue(loader.getIsLoaded());
        assertEquals("", printed, "nothing to say when the sketch handles the file");
    }

    @Test
    void aCancelledChooserCallsTheSketchWithNull() {
        PaperSketch sketch = new PaperSketch();
        ModelLoader loader = new ModelLoader(sketch);
        sketch.loader = loader;
        loader.modelFileSelected(null);
        assertEquals(1, sketch.calls.size());
        assertNull(sketch.calls.get(0), "the original passed null, and its sketches print \"No file was selected\"");
        assertFalse(loader.getIsLoaded());
    }

    @Test
    void whatTheSketchsLoadThrowsIsPrintedNotPassedOn(@TempDir Path dir) {
        ModelLoader loader = new ModelLoader(new FailingSketch());
        File f = saved(dir);
        String printed = GravityNoteTest.stderrOf(() -> loader.modelFileSelected(f));
        assertTrue(printed.contains("load(File) threw") && printed.contains("the sketch's own failure"), printed);
    }

    @Test
    void aSketchWithoutLoadGetsTheFileLoadedAndOneMessage(@TempDir Path dir) {
        ModelLoader loader = new ModelLoader(new PApplet());
        File f = saved(dir);
        PhysicalModel m = new PhysicalModel(1050, 50);
        PhysicalModel other = new PhysicalModel(1050, 50);
        String printed = GravityNoteTest.stderrOf(() -> {
            loader.deliver(f, m);
            loader.deliver(f, other);
        });
        assertEquals(2, m.getNumberOfMats());
        assertEquals(2, other.getNumberOfMats());
        assertTrue(loader.getIsLoaded());
        assertEquals(1, printed.split("\n").length, "one message, once:\n" + printed);
        assertTrue(printed.contains("loadModelFromFile") && printed.contains("no load(File) method")
                && printed.contains("public void load(File selection)"), printed);
    }

    @Test
    void aLoadThatIsNotPublicIsNamedInTheMessage(@TempDir Path dir) {
        HiddenLoadSketch sketch = new HiddenLoadSketch();
        ModelLoader loader = new ModelLoader(sketch);
        PhysicalModel m = new PhysicalModel(1050, 50);
        String printed = GravityNoteTest.stderrOf(() -> loader.deliver(saved(dir), m));
        assertEquals(0, sketch.calls, "Processing calls only a public method");
        assertTrue(printed.contains("load(File) method is not public"), printed);
        assertEquals(2, m.getNumberOfMats());
    }
}
