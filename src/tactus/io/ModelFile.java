package tactus.io;

import java.util.ArrayList;
import java.util.List;

/** The content of a model file: the global medium, the masses and the interactions, in model order. */
final class ModelFile {
    double gravity;
    double friction;
    double dirX, dirY, dirZ = 1;
    /** The unit system the file was written in ("ALGO_UNITS" or "REAL_UNITS"), or null when the file does not say. */
    String paramSystem;
    /** The simulation rate the file was written at, or 0 when the file does not say. */
    int simRate;
    /** Lines of the {@code <global>} and {@code <units>} elements, for error messages (-1 when absent). */
    int globalLine = -1;
    int unitsLine = -1;
    final List<MassSpec> masses = new ArrayList<>();
    final List<LinkSpec> links = new ArrayList<>();
}
