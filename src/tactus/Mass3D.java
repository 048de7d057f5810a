package tactus;

/** A free 3D mass subject to its interactions, air friction and gravity. */
public final class Mass3D extends InertialMass {
    Mass3D(PhysicalModel model, int id) {
        super(model, id);
    }
}
