package tactus;

/** A pluck along the line between two masses, on the elongation d - l0 (mi.lib's nlPluck in 3-D). */
public final class Pluck3D extends Pluck {
    Pluck3D(ModuleHandles handles, int id) {
        super(handles, id);
    }
}
