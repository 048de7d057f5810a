package tactus;


/** A fixed point for 1D models. */
public final class Ground1D extends Mass {
    Ground1D(ModuleHandles handles, int id, int stamp) {
        super(handles, id, stamp);
    }
}
