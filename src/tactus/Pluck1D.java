package tactus;

/** A pluck along z only, on z1 - z2 - l0 (mi.lib's nlPluck). */
public final class Pluck1D extends Pluck {
    Pluck1D(ModuleHandles handles, int id) {
        super(handles, id);
    }
}
