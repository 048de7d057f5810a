package tactus.engine;

/** One homogeneous loop of a step plan: all masses of one kind, or all links of one kind. */
interface Kernel {
    /** Runs the loop once, for one simulation step. */
    void run();
}
