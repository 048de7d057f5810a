package tactus;


/** A fixed point in 3D: interactions act on it but it never moves. */
public final class Ground3D extends Mass {
    Ground3D(ModuleHandles handles, int id, int stamp) {
        super(handles, id, stamp);
    }
}
