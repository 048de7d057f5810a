package tactus;

import java.io.File;
import processing.core.PApplet;
import tactus.io.ModelXml;

/**
 * Saves and loads models in the XML format of the paper's engine, from a sketch: a thin shell over
 * {@link tactus.io.ModelXml}, which documents the format and the rules.
 *
 * <pre>
 * ModelLoader loader = new ModelLoader(this);
 * loader.saveModel("HelloMass.xml", mdl);
 * loader.loadModel(dataPath("BeamModel.xml"), other);
 * </pre>
 *
 * <p>Outside Processing, use {@link tactus.io.ModelXml} directly: it needs no {@code PApplet}.
 * Relative file names are taken in the sketch folder. Unlike the original, which printed
 * "oh no." and returned false after a partial load, a load that fails throws a
 * {@link tactus.io.ModelFileException} naming the line and the element, and leaves the model as it was.
 */
public class ModelLoader {
    private final PApplet app;
    private volatile boolean loaded;
    private PhysicalModel pending;
    /** Whether the one message about a sketch without {@code load(File)} was printed. */
    private boolean toldNoHandler;

    /**
     * Creates a loader that reads and writes model files for a sketch.
     *
     * @param parent the sketch ({@code this}); may be null outside Processing, then file names are
     *     taken as they are
     */
    public ModelLoader(PApplet parent) {
        this.app = parent;
    }

    /**
     * Writes a model to an XML file.
     *
     * @param xmlFileName the file to write; a relative name is taken in the sketch folder
     * @return true (a failure throws {@link java.io.UncheckedIOException})
     */
    public boolean saveModel(String xmlFileName, PhysicalModel mdl) {
        requireModel("saveModel", mdl);
        ModelXml.save(mdl, resolve("saveModel", xmlFileName));
        return true;
    }

    /**
     * Adds the content of an XML model file to a model (gravity, friction, masses, interactions),
     * then calls {@link PhysicalModel#init()}.
     *
     * @param xmlFileName the file to read; a relative name is taken in the sketch folder
     * @return true (a failure throws, and the model is unchanged)
     */
    public boolean loadModel(String xmlFileName, PhysicalModel mdl) {
        requireModel("loadModel", mdl);
        ModelXml.load(resolve("loadModel", xmlFileName), mdl);
        loaded = true;
        return true;
    }

    /**
     * Opens a file chooser, as the paper's engine did; when it closes, the sketch's own {@code load(File)} method
     * is called with the chosen file (null when the user cancelled), exactly as the original's
     * {@code selectInput(prompt, "load")} did. The paper's sketches load the model there themselves:
     *
     * <pre>
     * void load(File selection) {
     *   if (selection == null) { println("No file was selected"); return; }
     *   loader.loadModel(selection.getAbsolutePath(), mdl);
     * }
     * </pre>
     *
     * <p>A sketch without a public {@code load(File)} method gets Tactus's help instead: the chosen file is loaded
     * into {@code mdl} and {@link #getIsLoaded()} becomes true, and one message (once per loader) says so. The
     * chooser runs asynchronously, as Processing's {@code selectInput}. An error in the sketch's method or in the
     * load is printed and leaves the model as the load left it (a failed load leaves it unchanged).
     *
     * @throws IllegalStateException on a machine without a display, where no chooser can open; call
     *     {@link #loadModel(String, PhysicalModel)} there
     */
    public void loadModelFromFile(PhysicalModel mdl) {
        requireModel("loadModelFromFile", mdl);
        if (app == null || java.awt.GraphicsEnvironment.isHeadless()) {
            throw new IllegalStateException("ModelLoader.loadModelFromFile: "
                    + (app == null ? "no sketch was given to the ModelLoader" : "this machine has no display")
                    + ", so no file chooser can open; call loadModel(fileName, model) instead");
        }
        synchronized (this) {
            pending = mdl;
        }
        app.selectInput("Select the model to load", "modelFileSelected", null, this);
    }

    /**
     * Called by Processing when the file chooser opened by {@link #loadModelFromFile} closes; not meant to be
     * called by sketches. Calls the sketch's {@code load(File)}, or loads the file itself (see
     * {@link #loadModelFromFile}).
     *
     * @param selection the chosen file, or null when the user cancelled
     */
    public void modelFileSelected(File selection) {
        PhysicalModel target;
        synchronized (this) {
            target = pending;
            pending = null;
        }
        deliver(selection, target);
    }

    /** Hands a chosen file to the sketch's {@code load(File)}, or loads it into {@code target} when there is none. */
    void deliver(File selection, PhysicalModel target) {
        java.lang.reflect.Method handler = SketchCallback.find(app, "load");
        if (handler != null) {
            SketchCallback.call(handler, app, selection, "ModelLoader");
            return;
        }
        if (!toldNoHandler) {
            toldNoHandler = true;
            System.err.println(SketchCallback.missing(app, "load", "ModelLoader.loadModelFromFile",
                    "Tactus loads the chosen file into the model given to loadModelFromFile instead"));
        }
        if (selection == null || target == null) {
            return;
        }
        try {
            ModelXml.load(selection, target);
            loaded = true;
        } catch (RuntimeException e) {
            System.err.println("ModelLoader: " + e.getMessage());
        }
    }

    /** {@return true once a model has been loaded (by {@link #loadModel} or through the file chooser)} */
    public boolean getIsLoaded() {
        return loaded;
    }

    /** Sets the loaded flag, for example back to false once the sketch has taken a loaded model into account. */
    public void setIsLoaded(boolean val) {
        loaded = val;
    }

    private File resolve(String op, String name) {
        if (name == null || name.isEmpty()) {
            throw new IllegalArgumentException("ModelLoader." + op + ": the file name must be a non-empty string");
        }
        File f = new File(name);
        if (f.isAbsolute() || app == null) {
            return f;
        }
        return new File(app.sketchPath(name));
    }

    private static void requireModel(String op, PhysicalModel mdl) {
        if (mdl == null) {
            throw new IllegalArgumentException("ModelLoader." + op + ": the model must not be null");
        }
    }
}
