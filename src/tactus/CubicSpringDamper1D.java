package tactus;

/** A cubic spring-damper along z only, on z1 - z2 - l0 (mi.lib's nlSpringDamper3). */
public final class CubicSpringDamper1D extends CubicSpringDamper {
    CubicSpringDamper1D(ModuleHandles handles, int id) {
        super(handles, id);
    }
}
