package tactus;

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
    /** No module of a known type (never returned for a live module). */
    UNDEFINED
}
