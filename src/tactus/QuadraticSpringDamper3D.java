package tactus;

/** A quadratic spring-damper along the line between two masses, on the elongation d - l0 (mi.lib's nlSpringDamper2 in 3-D). */
public final class QuadraticSpringDamper3D extends QuadraticSpringDamper {
    QuadraticSpringDamper3D(ModuleHandles handles, int id) {
        super(handles, id);
    }
}
