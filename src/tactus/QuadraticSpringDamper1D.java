package tactus;

/** A quadratic spring-damper along z only, on z1 - z2 - l0 (mi.lib's nlSpringDamper2). */
public final class QuadraticSpringDamper1D extends QuadraticSpringDamper {
    QuadraticSpringDamper1D(ModuleHandles handles, int id) {
        super(handles, id);
    }
}
