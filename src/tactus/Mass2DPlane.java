package tactus;


/** A mass that moves in the plane z = constant of its initial position. */
public final class Mass2DPlane extends InertialMass {
    Mass2DPlane(ModuleHandles handles, int id, int stamp) {
        super(handles, id, stamp);
    }
}
