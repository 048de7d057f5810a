package tactus;

/** A bow between two masses whose friction acts against their relative velocity vector (mi.lib's nlBow in 3-D). */
public final class Bow3D extends Bow {
    Bow3D(ModuleHandles handles, int id) {
        super(handles, id);
    }
}
