package tactus.soak;

import java.io.File;
import java.io.FileInputStream;
import java.io.IOException;
import java.io.InputStream;

/** What Minim asks of a sketch for file access ({@code sketchPath}, {@code createInput}), in the temp folder. */
public final class SketchFiles {
    private final File dir = new File(System.getProperty("java.io.tmpdir"));

    /** @return the absolute path of {@code name} in the temp folder (or {@code name} if absolute). */
    public String sketchPath(String name) {
        File f = new File(name);
        return f.isAbsolute() ? name : new File(dir, name).getAbsolutePath();
    }

    /** @return a stream on the named file. */
    public InputStream createInput(String name) throws IOException {
        return new FileInputStream(sketchPath(name));
    }
}
