package tactus;

/** A clipped cubic spring-damper along the line between two masses, on the elongation d - l0 (mi.lib's nlSpringDamperClipped in 3-D). */
public final class ClippedSpringDamper3D extends ClippedInteraction {
    ClippedSpringDamper3D(ModuleHandles handles, int id) {
        super(handles, id);
    }
}
