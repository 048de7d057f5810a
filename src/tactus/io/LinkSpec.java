package tactus.io;

/** One interaction as read from (or written to) a model file, with where it came from. */
final class LinkSpec {
    String type;
    String name;
    int index = -1;
    String m1;
    String m2;
    double stiffness;
    double damping;
    /** Rest length, threshold, radius or plane offset ("drest"), or the attractor's limit distance. */
    double length;
    int orientation;
    double planePosition;
    double attraction;
    /** The parameters beyond K, Z and the length of a nonlinear kind, in the order of its descriptor. */
    double[] extra = new double[0];
    /** Where it came from: the element's name and 1-based line, for error messages. */
    String element;
    int line = -1;
}
