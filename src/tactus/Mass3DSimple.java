package tactus;


/** A free 3D mass subject to its interactions only: it ignores air friction and gravity. */
public final class Mass3DSimple extends InertialMass {
    Mass3DSimple(ModuleHandles handles, int id, int stamp) {
        super(handles, id, stamp);
    }
}
