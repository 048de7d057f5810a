package tactus.engine;

/**
 * One unit of work of a step plan, run once per step in the plan's order: the masses of one kind, the
 * index-array (irregular) links of one kind, one stencil run of a spring-family kind, or one contact group.
 * Kernels that can be cut into index ranges for several threads also implement {@link RangeKernel}.
 */
interface Kernel {
    /** Runs the loop once, for one simulation step. */
    void run();
}
