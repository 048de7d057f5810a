package tactus.internal;

import java.io.IOException;
import java.io.InputStream;
import java.util.Properties;

/**
 * The library's version, as the build wrote it into the resource {@code version.properties} beside this class (from
 * the one version in gradle.properties). Not API: {@code tactus.PhysicalModel.VERSION} is the public face.
 */
public final class LibraryVersion {
    /** What {@link #read()} answers when neither the resource nor the jar's manifest names a version. */
    public static final String UNKNOWN = "unknown";

    private LibraryVersion() {
    }

    /**
     * Reads the version: from {@code version.properties} once the build filled it in, else from the jar manifest's
     * {@code Implementation-Version}, else {@link #UNKNOWN}. Never throws.
     *
     * @return the version, such as "0.3.0"
     */
    public static String read() {
        try (InputStream in = LibraryVersion.class.getResourceAsStream("version.properties")) {
            if (in != null) {
                Properties p = new Properties();
                p.load(in);
                String v = p.getProperty("version", "").trim();
                if (!v.isEmpty() && !v.contains("@")) {
                    return v;
                }
            }
        } catch (IOException | IllegalArgumentException e) {
            // an unreadable resource: try the manifest
        }
        Package p = LibraryVersion.class.getPackage();
        String v = p == null ? null : p.getImplementationVersion();
        return v == null || v.isBlank() ? UNKNOWN : v;
    }
}
