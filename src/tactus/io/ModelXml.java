package tactus.io;

import java.io.File;
import java.io.IOException;
import java.io.Reader;
import java.io.StringWriter;
import java.io.UncheckedIOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import javax.xml.stream.XMLStreamException;
import tactus.PhysicalModel;

/**
 * Saves and loads a {@link PhysicalModel} in the XML format of the paper's engine (miPhysics v1.1
 * {@code ModelLoader}), so that files move both ways between the two engines.
 *
 * <p>The file stores what the model's getters return, in the model's own unit system: positions,
 * velocities in units per second (attributes {@code initVel.*}, as the paper-era engine writes
 * them; files with the {@code posR.*} attributes of its first loader, and of Tactus before, load too), masses,
 * stiffnesses, dampings and lengths. Like the original it does not store the simulation rate or the
 * unit system in a way the original reads; Tactus adds a {@code <units paramSystem=".." simRate=".."/>}
 * element under {@code <global>}, which the original ignores and which makes a Tactus load refuse a
 * file written in the other unit system. Load a file into a model with the same rate and units as
 * the one that saved it. An oscillator's rest point is saved as its current position; the smoothing
 * of haptic and position inputs is not saved (it loads as the file's {@code smoothing} attribute, or 1).
 *
 * <p>Loading adds the file's modules to the model (after its existing ones), sets gravity, friction
 * and gravity direction, and calls {@link PhysicalModel#init()}. It is all or nothing: any error
 * throws a {@link ModelFileException} naming the line and the element, and leaves the model as it was.
 */
public final class ModelXml {
    private ModelXml() {
    }

    /**
     * Writes a model to a file (UTF-8), with the file's name as the root element when it is a valid XML name.
     *
     * @throws UncheckedIOException if the file cannot be written
     */
    public static void save(PhysicalModel model, File file) {
        StringWriter text = new StringWriter();
        write(model, text, rootNameFor(file.getName()));
        try {
            File parent = file.getAbsoluteFile().getParentFile();
            if (parent != null) {
                Files.createDirectories(parent.toPath());
            }
            Files.write(file.toPath(), text.toString().getBytes(StandardCharsets.UTF_8));
        } catch (IOException e) {
            throw new UncheckedIOException("cannot write the model file " + file.getAbsolutePath() + ": "
                    + reason(e), e);
        }
    }

    /**
     * Reads a model file and adds its content to {@code model}.
     *
     * @throws ModelFileException if the file is malformed or does not fit the model; the model is then unchanged
     * @throws UncheckedIOException if the file cannot be read
     */
    public static void load(File file, PhysicalModel model) {
        String path = file.getAbsolutePath();
        try (Reader in = Files.newBufferedReader(file.toPath(), StandardCharsets.UTF_8)) {
            read(in, path, model);
        } catch (IOException e) {
            throw new UncheckedIOException("cannot read the model file " + path + ": " + reason(e), e);
        }
    }

    /**
     * {@return why a file could not be read or written, in words: "there is no such file", "permission denied", or
     *     the exception's own message}
     */
    static String reason(IOException e) {
        if (e instanceof java.nio.file.NoSuchFileException) {
            return "there is no such file (a relative name is taken from the working directory, "
                    + new File("").getAbsolutePath() + ", or in a sketch from the sketch folder)";
        }
        if (e instanceof java.nio.file.AccessDeniedException) {
            return "permission denied";
        }
        if (e instanceof java.nio.file.FileSystemException && ((java.nio.file.FileSystemException) e).getReason() != null) {
            return ((java.nio.file.FileSystemException) e).getReason();
        }
        return e.getMessage() != null ? e.getMessage() : e.toString();
    }

    /** Writes a model as XML to {@code out}, under a root element named {@code rootName}. */
    public static void write(PhysicalModel model, Writer out, String rootName) {
        if (model == null) {
            throw new IllegalArgumentException("ModelXml.write: the model must not be null");
        }
        try {
            ModelFileWriter.write(ModelCapture.of(model), rootNameFor(rootName), out);
        } catch (XMLStreamException e) {
            throw new UncheckedIOException("cannot write the model as XML: " + e.getMessage(), new IOException(e));
        }
    }

    /**
     * Reads XML from {@code in} and adds its content to {@code model}, all or nothing.
     *
     * @param source the name used in error messages (usually the file name)
     * @throws ModelFileException if the XML is malformed or does not fit the model
     */
    public static void read(Reader in, String source, PhysicalModel model) {
        if (model == null) {
            throw new IllegalArgumentException("ModelXml.read: the model must not be null");
        }
        ModelFile f = new ModelFileParser(source).parse(XmlNode.parse(in, source));
        new ModelApplier(source).apply(f, model);
    }

    /** @return {@code name} when it is a valid XML element name (for example "HelloMass.xml"), else "model". */
    static String rootNameFor(String name) {
        if (name != null && name.matches("[A-Za-z_][A-Za-z0-9._-]*") && !name.toLowerCase().startsWith("xml")) {
            return name;
        }
        return "model";
    }
}
