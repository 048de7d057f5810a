package tactus;


/** A mass that moves along z only; x and y keep their initial values. */
public final class Mass1D extends InertialMass {
    Mass1D(ModuleHandles handles, int id, int stamp) {
        super(handles, id, stamp);
    }
}
