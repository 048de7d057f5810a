package tactus;

/** A cubic spring-damper along the line between two masses, on the elongation d - l0 (mi.lib's nlSpringDamper3 in 3-D). */
public final class CubicSpringDamper3D extends CubicSpringDamper {
    CubicSpringDamper3D(ModuleHandles handles, int id) {
        super(handles, id);
    }
}
