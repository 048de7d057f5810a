package tactus.engine;

/**
 * The kinds of mass-type module. The declaration order is the order in which a compiled
 * {@link StepPlan} lays masses out in its arrays and runs their kernels.
 */
public enum MassKind {
    /** A free 3D mass with air friction and gravity. */
    MASS3D("Mass3D", true),
    /** A free 3D mass that ignores air friction and gravity. */
    MASS3D_SIMPLE("Mass3DSimple", true),
    /** A 3D mass constrained to its initial z plane: only x and y move. */
    MASS2D_PLANE("Mass2DPlane", true),
    /** A mass that moves along z only; x and y stay at their initial values. */
    MASS1D("Mass1D", true),
    /** A 3D mass tied to its rest position by an internal spring and damper. */
    OSC3D("Osc3D", true),
    /** An oscillator that moves along z only. */
    OSC1D("Osc1D", true),
    /** A kinematic avatar driven by a device position through an EWMA filter; accumulates the force it receives. */
    HAPTIC_INPUT3D("HapticInput3D", false),
    /** A kinematic driver that follows a target position through an EWMA filter; reports no force. */
    POS_INPUT3D("PosInput3D", false),
    /**
     * A free mass under velocity control: it moves by a set displacement every step and ignores forces. Only
     * the engine's layout uses this kind; the mass keeps reporting its own kind.
     */
    DRIVEN3D("velocity-driven mass", false),
    /** A fixed point in 3D. */
    GROUND3D("Ground3D", false),
    /** A fixed point for 1D models. */
    GROUND1D("Ground1D", false);

    private final String label;
    private final boolean inertial;

    MassKind(String label, boolean inertial) {
        this.label = label;
        this.inertial = inertial;
    }

    /** @return the module name used in the API and in messages, for example {@code "Mass3D"}. */
    public String label() {
        return label;
    }

    /** @return true when the module integrates forces (it has a mass); false for fixed and driven modules. */
    public boolean isInertial() {
        return inertial;
    }

    /** @return true for the oscillator kinds, which carry their own stiffness and damping. */
    public boolean isOscillator() {
        return this == OSC3D || this == OSC1D;
    }

    /** @return true for the kinds driven from outside through an EWMA filter. */
    public boolean isInput() {
        return this == HAPTIC_INPUT3D || this == POS_INPUT3D;
    }

    /** @return true for the free kinds that can be put under velocity control. */
    public boolean isDrivable() {
        return this == MASS3D || this == MASS3D_SIMPLE || this == MASS2D_PLANE || this == MASS1D;
    }

    /** @return true for fixed points. */
    public boolean isFixed() {
        return this == GROUND3D || this == GROUND1D;
    }
}
