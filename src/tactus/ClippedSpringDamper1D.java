package tactus;

/** A clipped cubic spring-damper along z only, on z1 - z2 - l0 (mi.lib's nlSpringDamperClipped). */
public final class ClippedSpringDamper1D extends ClippedInteraction {
    ClippedSpringDamper1D(ModuleHandles handles, int id) {
        super(handles, id);
    }
}
