package tactus.engine;

/**
 * A kernel whose work splits into stages, each an element-wise loop over an index range that can be cut
 * into chunks and run on several threads: within a stage no two indices touch the same memory, and the
 * stages must run in order. Running every stage over its whole range, in order, is exactly {@link #run()}.
 */
interface RangeKernel extends Kernel {
    /** @return the number of stages. */
    int stages();

    /** @return the first index of a stage's range. */
    int start(int stage);

    /** @return the end (exclusive) of a stage's range. */
    int end(int stage);

    /** Runs a stage over indices [from, to). */
    void run(int stage, int from, int to);
}
