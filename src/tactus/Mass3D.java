package tactus;


/** A free 3D mass subject to its interactions, air friction and gravity. */
public final class Mass3D extends InertialMass {
    Mass3D(ModuleHandles handles, int id, int stamp) {
        super(handles, id, stamp);
    }
}
