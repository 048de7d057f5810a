package tactus;

import tactus.engine.LinkKind;

/**
 * The type of an interaction module, as returned by {@link PhysicalModel#getLinkTypeAt(int)}. The lower-case name
 * and the constants keep drawing code written for the paper's engine ({@code case SpringDamper3D:})
 * source-compatible.
 */
public enum linkModuleType {
    /** A spring. */
    Spring3D,
    /** A damper. */
    Damper3D,
    /** A spring and damper in parallel. */
    SpringDamper3D,
    /** A spring-damper acting along z only. */
    SpringDamper1D,
    /** A spring-damper that acts only while stretched beyond its length. */
    Rope3D,
    /** A spring-damper that acts only while the masses are closer than its threshold. */
    Contact3D,
    /** A one-sided contact with an axis-aligned plane. */
    PlaneContact3D,
    /** A spring-damper that keeps a mass inside a sphere around another. */
    Bubble3D,
    /** An inverse-square attraction. */
    Attractor3D,
    /** A spring-damper with a quadratic term along the line between the masses (mi.lib's nlSpringDamper2). */
    QuadraticSpringDamper3D,
    /** A spring-damper with a quadratic term along z (mi.lib's nlSpringDamper2). */
    QuadraticSpringDamper1D,
    /** A spring-damper with a cubic term along the line between the masses (mi.lib's nlSpringDamper3). */
    CubicSpringDamper3D,
    /** A spring-damper with a cubic term along z (mi.lib's nlSpringDamper3). */
    CubicSpringDamper1D,
    /** A cubic spring-damper bounded by a stiffness, along the line between the masses (nlSpringDamperClipped). */
    ClippedSpringDamper3D,
    /** A cubic spring-damper bounded by a stiffness, along z (mi.lib's nlSpringDamperClipped). */
    ClippedSpringDamper1D,
    /** A plucking interaction along the line between the masses (mi.lib's nlPluck). */
    Pluck3D,
    /** A plucking interaction along z (mi.lib's nlPluck). */
    Pluck1D,
    /** A bowing friction on the relative velocity (mi.lib's nlBow). */
    Bow3D,
    /** A bowing friction along z (mi.lib's nlBow). */
    Bow1D,
    /** A clipped cubic contact on the distance (mi.lib's nlCollisionClipped). */
    ClippedContact3D,
    /** A clipped cubic contact along z (mi.lib's nlCollisionClipped). */
    ClippedContact1D,
    /** No module of a known type (never returned for a live module). */
    UNDEFINED;

    // ---- the kind's descriptor (tactus.engine.LinkKind), for the rooms that may not import the engine

    /** {@return the engine's descriptor of this type, or null for UNDEFINED} */
    private LinkKind kind() {
        return LinkKind.byLabel(name());
    }

    /** {@return true when the type acts along z only, on the signed difference z1 - z2 (a 1-D module)} */
    public boolean isOneDimensional() {
        LinkKind k = kind();
        return k != null && k.isOneDimensional();
    }

    /** {@return true when the type is one of Faust mi.lib's nonlinear interactions} */
    public boolean isNonlinear() {
        LinkKind k = kind();
        return k != null && k.isNonlinear();
    }

    /** {@return the names of the type's parameters beyond stiffness, damping and length (empty for most types)} */
    public String[] extraParameterNames() {
        LinkKind k = kind();
        return k == null ? new String[0] : k.auxNames();
    }

    /** {@return the mi.lib function whose law the type applies (along z in 1-D, along the distance in 3-D), or null} */
    public String miLibFunction() {
        LinkKind k = kind();
        return k == null ? null : k.miLibFunction();
    }

    /**
     * {@return the arguments of {@link #miLibFunction()} before its initial positions, in mi.lib's order, named as
     * this API names them: {@code "K"}, {@code "Z"}, {@code "dist"} or an extra parameter's name}
     */
    public String[] miLibArguments() {
        LinkKind k = kind();
        return k == null ? new String[0] : k.miLibArguments();
    }

    /**
     * {@return the power of the sampling rate that turns extra parameter {@code i} from REAL_UNITS into a per-step
     * value (per step = real / fs^power): 2 for stiffnesses, 1 for velocities, 0 for lengths and numbers}
     */
    public int extraParameterRatePower(int i) {
        return kind().auxRatePower(i);
    }

    /** {@return the default colour of the type in drawings, as 0xAARRGGBB (alpha 0: drawn without a line)} */
    public int defaultColor() {
        LinkKind k = kind();
        return k == null ? 0x007D7D7D : k.color();
    }

    /** {@return true when a listening point can read the type's tension (its elongation while it acts)} */
    public boolean hasReadableTension() {
        LinkKind k = kind();
        return k != null && k.engagement() != LinkKind.Engagement.NONE;
    }

    /** {@return true when the type acts only while its masses are closer than its length (contacts)} */
    public boolean actsOnlyCompressed() {
        LinkKind k = kind();
        return k != null && k.engagement() == LinkKind.Engagement.WHEN_COMPRESSED;
    }

    /** {@return true when the type acts only while its masses are farther apart than its length (ropes, bubbles)} */
    public boolean actsOnlyStretched() {
        LinkKind k = kind();
        return k != null && k.engagement() == LinkKind.Engagement.WHEN_STRETCHED;
    }
}
