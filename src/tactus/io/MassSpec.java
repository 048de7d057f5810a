package tactus.io;

/** One mass as read from (or written to) a model file, with where it came from. */
final class MassSpec {
    String type;
    String name;
    int index = -1;
    double x, y, z;
    double vx, vy, vz;
    double mass = 1;
    double stiffness;
    double damping;
    int smoothing = 1;
    /** Where it came from: the element's name and 1-based line, for error messages. */
    String element;
    int line = -1;
}
