/**
 * Saving and loading models as files.
 *
 * <p>{@link tactus.io.ModelXml} writes a {@link tactus.PhysicalModel} to, and reads it from, the XML
 * format of the paper's engine (miPhysics v1.1 {@code ModelLoader}): a {@code global} section (gravity,
 * friction, gravity direction), a {@code MAT} section with one group per mass type and a {@code Link}
 * section with one group per interaction type. Files written by either engine load in the other.
 * Reading is all or nothing: a file with an error, reported as a {@link tactus.io.ModelFileException}
 * that names the line and the element, leaves the model unchanged. Sketches use the
 * {@link tactus.ModelLoader} shell.
 */
package tactus.io;
