package tactus.engine;

/**
 * The kinds of interaction module. The declaration order is the order in which a compiled
 * {@link StepPlan} runs their kernels; within one kind, links run in insertion order.
 */
public enum LinkKind {
    /** Linear spring on the distance between two masses: f = -K (d - l0). */
    SPRING3D("Spring3D", true, false, true),
    /** Radial damper: f = -Z (d(n) - d(n-1)). */
    DAMPER3D("Damper3D", false, true, false),
    /** Spring and damper in parallel. */
    SPRING_DAMPER3D("SpringDamper3D", true, true, true),
    /** Spring and damper acting along z only, on the signed difference z1 - z2. */
    SPRING_DAMPER1D("SpringDamper1D", true, true, true),
    /** Spring-damper that acts only while stretched beyond its rest length. */
    ROPE3D("Rope3D", true, true, true),
    /** Spring-damper that acts only while the masses are closer than a threshold. */
    CONTACT3D("Contact3D", true, true, true),
    /** Spring-damper that acts only while the masses are farther apart than a radius. */
    BUBBLE3D("Bubble3D", true, true, true),
    /** One-sided spring-damper between one mass and an axis-aligned plane. */
    PLANE_CONTACT3D("PlaneContact3D", true, true, true),
    /** Inverse-square attraction beyond a limit distance: f = -A / d^2. */
    ATTRACTOR3D("Attractor3D", false, false, true);

    private final String label;
    private final boolean stiff;
    private final boolean damped;
    private final boolean length;

    LinkKind(String label, boolean stiff, boolean damped, boolean length) {
        this.label = label;
        this.stiff = stiff;
        this.damped = damped;
        this.length = length;
    }

    /** @return the module name used in the API and in messages, for example {@code "SpringDamper3D"}. */
    public String label() {
        return label;
    }

    /** @return true when the kind has a stiffness parameter K. */
    public boolean hasStiffness() {
        return stiff;
    }

    /** @return true when the kind has a damping parameter Z. */
    public boolean hasDamping() {
        return damped;
    }

    /**
     * @return true when the kind has a length parameter: rest length (springs, 1D spring-damper, rope),
     *     threshold (contact), radius (bubble), offset (plane contact) or limit distance (attractor); only the
     *     Damper3D has none
     */
    public boolean hasLength() {
        return length;
    }

    /** @return true when the kind acts on one mass only (the plane contact). */
    public boolean isSingleMass() {
        return this == PLANE_CONTACT3D;
    }

    /** @return true when the force applies only under a distance condition (rope, contact, bubble, plane). */
    public boolean isConditional() {
        return this == ROPE3D || this == CONTACT3D || this == BUBBLE3D || this == PLANE_CONTACT3D;
    }
}
