package tactus.engine;

/** The description of one contact group: its members (mass ids, in order) and its contact parameters. */
final class ContactGroupSpec {
    /** Skin distance of the neighbour list, as a fraction of the threshold. */
    static final double SKIN = 0.3;

    int[] members;
    double threshold;
    double stiffness;
    double damping;
    boolean alive = true;

    ContactGroupSpec(int[] members, double threshold, double stiffness, double damping) {
        this.members = members;
        this.threshold = threshold;
        this.stiffness = stiffness;
        this.damping = damping;
    }
}
