package tactus;

/** A bow along z only, on the relative velocity (z1 - z1') - (z2 - z2') (mi.lib's nlBow). */
public final class Bow1D extends Bow {
    Bow1D(ModuleHandles handles, int id) {
        super(handles, id);
    }
}
