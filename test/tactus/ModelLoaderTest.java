package tactus;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import processing.core.PApplet;
import tactus.io.ModelFileException;

/** The ModelLoader shell: the original's calls, relative names in the sketch folder, the loaded flag, headless chooser. */
class ModelLoaderTest {
    static PhysicalModel helloMass() {
        PhysicalModel m = new PhysicalModel(1050, 50);
        m.addMass3D("mass", 1, new Vect3D(0, 0, 0), new Vect3D(0, 0, 1));
        m.addGround3D("ground1", new Vect3D(70, 0, 0));
        m.addSpringDamper3D("spring1", 70, 0.001, 0.01, "mass", "ground1");
        return m;
    }

    @Test
    void saveThenLoadWithTheOriginalsCalls(@TempDir Path dir) {
        ModelLoader loader = new ModelLoader(null);
        String file = dir.resolve("HelloMass.xml").toString();
        assertTrue(loader.saveModel(file, helloMass()));
        assertFalse(loader.getIsLoaded());
        PhysicalModel m = new PhysicalModel(1050, 50);
        assertTrue(loader.loadModel(file, m));
        assertTrue(loader.getIsLoaded());
        assertEquals(2, m.getNumberOfMats());
        assertEquals(0.001, m.getLinkStiffness("spring1"), 0.0);
        loader.setIsLoaded(false);
        assertFalse(loader.getIsLoaded());
    }

    @Test
    void relativeNamesAreInTheSketchFolder(@TempDir Path dir) throws Exception {
        PApplet sketch = new PApplet() {
            @Override
            public String sketchPath() {
                return dir.toString();
            }
        };
        ModelLoader loader = new ModelLoader(sketch);
        loader.saveModel("data/Hello.xml", helloMass());
        File written = dir.resolve("data").resolve("Hello.xml").toFile();
        assertTrue(written.isFile());
        assertTrue(new String(Files.readAllBytes(written.toPath()), "UTF-8").contains("<Hello.xml>"));
        PhysicalModel m = new PhysicalModel(1050, 50);
        loader.loadModel("data/Hello.xml", m);
        assertEquals(3, m.getNumberOfMats() + m.getNumberOfLinks());
    }

    @Test
    void aFailedLoadThrowsAndLeavesTheFlagAndModel(@TempDir Path dir) throws Exception {
        Path bad = dir.resolve("bad.xml");
        Files.write(bad, "<m><global></m>".getBytes("UTF-8"));
        ModelLoader loader = new ModelLoader(null);
        PhysicalModel m = helloMass();
        assertThrows(ModelFileException.class, () -> loader.loadModel(bad.toString(), m));
        assertFalse(loader.getIsLoaded());
        assertEquals(2, m.getNumberOfMats());
        assertThrows(IllegalArgumentException.class, () -> loader.loadModel("", m));
        assertThrows(IllegalArgumentException.class, () -> loader.saveModel("x.xml", null));
    }

    @Test
    void theFileChooserNeedsADisplay() {
        IllegalStateException e = assertThrows(IllegalStateException.class,
                () -> new ModelLoader(null).loadModelFromFile(new PhysicalModel(1000, 50)));
        assertTrue(e.getMessage().contains("loadModel(fileName, model)"), e.getMessage());
        if (java.awt.GraphicsEnvironment.isHeadless()) {
            e = assertThrows(IllegalStateException.class,
                    () -> new ModelLoader(new PApplet()).loadModelFromFile(new PhysicalModel(1000, 50)));
            assertTrue(e.getMessage().contains("no display"), e.getMessage());
        }
    }

    @Test
    void theChooserCallbackLoadsIntoThePendingModel(@TempDir Path dir) {
        // What Processing calls once the user picked a file; a cancelled chooser passes null.
        ModelLoader loader = new ModelLoader(null);
        File file = dir.resolve("picked.xml").toFile();
        loader.saveModel(file.getPath(), helloMass());
        loader.modelFileSelected(null);
        assertFalse(loader.getIsLoaded());
        loader.modelFileSelected(file);   // no pending model: ignored
        assertFalse(loader.getIsLoaded());
    }
}
