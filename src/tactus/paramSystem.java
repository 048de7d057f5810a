package tactus;

/**
 * The unit system in which a {@link PhysicalModel} takes and returns parameters. The lower-case
 * name keeps sketches written for the original engine source-compatible.
 */
public enum paramSystem {
    /**
     * Algorithmic units: stiffness, damping, friction, gravity and forces are per-step coefficients,
     * used as given. A model behaves differently if its simulation rate changes.
     */
    ALGO_UNITS,
    /**
     * SI units: stiffness in N/m, damping and friction in N·s/m, gravity in m/s^2, forces in N,
     * attraction in N·m^2, masses in kg, lengths in m. They are converted with the simulation rate,
     * so a model describes the same physical system at any rate.
     */
    REAL_UNITS
}
